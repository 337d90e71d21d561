#!/usr/bin/env bash
# Writes rtvk's man page, gzipped as Debian ships them: help2man on `rtvk --help`, plus a
# COMMANDS section made from each subcommand's own --help (help2man reads only the top level)
# and the hand-written sections of rtvk.h2m.
#   gen-man.sh RTVK_EXECUTABLE RTVK_H2M OUTPUT.1.gz
set -euo pipefail
rtvk=$1 h2m=$2 out=$3
# help2man dates the page; the last commit's date (when there is one) makes builds reproducible.
if [[ -z ${SOURCE_DATE_EPOCH:-} ]] && date=$(git -C "$(dirname "$h2m")" log -1 --format=%ct 2>/dev/null); then
  export SOURCE_DATE_EPOCH=$date
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The subcommands a CLI11 help text lists, one a line.
subcommands() { awk '/^Subcommands:$/ { on = 1; next } on && /^  [^ ]/ { print $1 }'; }

# One subcommand's help as roff: its description, usage, then each group of options as .TP
# entries. CLI11 pads an option to column 30 and puts its description after it, or, when the
# option is too wide, on the next lines, indented 30 columns.
roff_help() {
  awk -v cmd="$1" '
    function esc(s) { gsub(/\\/, "\\e", s); gsub(/-/, "\\-", s); return s }
    function para(s) { if (s ~ /^[.\x27]/) s = "\\&" s; return s }
    function option(head, desc,    name, rest) {
      sub(/ +$/, "", head); name = head; rest = ""
      if (match(head, / /)) { name = substr(head, 1, RSTART - 1); rest = substr(head, RSTART) }
      print ".TP"; print "\\fB" esc(name) "\\fR" esc(rest)
      if (desc != "") print para(esc(desc))
    }
    function flush() {
      if (pending != "") option(substr(pending, 3, 28), substr(pending, 31))
      pending = ""
    }
    NR == 1 { print ".SS \"rtvk " cmd "\""; print para(esc($0)); next }
    /^Usage: / { flush(); sub(/^Usage: /, ""); print ".PP"; print "Usage: \\fB" esc($0) "\\fR"; next }
    /^[^ ].*:$/ { flush(); print ".PP"; print "\\fI" esc($0) "\\fR"; next }
    /^  [^ ]/ { flush(); pending = $0; next }
    match($0, /^ +/) && RLENGTH == 30 {  # mawk knows no /^ {30}/
      if (pending != "") option(substr(pending, 3), "")
      pending = ""; sub(/^ +/, ""); print para(esc($0)); next
    }
    END { flush() }'
}

document() {  # $1: the command path, such as "render" or "scene dump"
  local help sub words
  read -ra words <<<"$1"
  help=$("$rtvk" "${words[@]}" --help)
  roff_help "$1" <<<"$help"
  for sub in $(subcommands <<<"$help"); do document "$1 $sub"; done
}

# The built-in scenes in roff, from `rtvk scene list` (a name a line; a parameter, as in
# "spheres:N (N from 1 to 4000000)", is upper case after a colon): "\fBseed\fR, ... and
# \fBspheres:\fR\fIN\fR (N from 1 to 4000000)", put where rtvk.h2m says @SCENES@.
scenes=$("$rtvk" scene list | awk '
  function esc(s) { gsub(/\\/, "\\e", s); gsub(/-/, "\\-", s); return s }
  {
    name = $1; rest = substr($0, length($1) + 1); param = ""
    if (match(name, /:[A-Z]+$/)) { param = substr(name, RSTART + 1); name = substr(name, 1, RSTART) }
    item[++n] = "\\fB" esc(name) "\\fR" (param != "" ? "\\fI" param "\\fR" : "") esc(rest)
  }
  END {
    for (i = 1; i <= n; i++) printf "%s%s", item[i], (i == n ? "\n" : i == n - 1 ? " and " : ", ")
  }')
[[ -n $scenes ]] || { echo "gen-man.sh: rtvk scene list printed nothing" >&2; exit 1; }
h2m_text=$(<"$h2m")
printf '%s\n' "${h2m_text//@SCENES@/"$scenes"}" >"$work/rtvk.h2m"

top=$("$rtvk" --help)
{
  echo "[COMMANDS]"
  for cmd in $(subcommands <<<"$top"); do document "$cmd"; done
} >"$work/commands.h2m"
help2man --no-info --section=1 --name="ray tracer with a CPU reference and a Vulkan compute port" \
  --include="$work/commands.h2m" --include="$work/rtvk.h2m" --output="$work/rtvk.1" "$rtvk"
gzip -9n <"$work/rtvk.1" >"$out.tmp"
mv "$out.tmp" "$out"
