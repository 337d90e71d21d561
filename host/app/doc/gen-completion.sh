#!/usr/bin/env bash
# Writes rtvk's bash completion. Its tables (subcommands, flags, which flags take a value, their
# choices, the built-in scenes) are read from the built rtvk's own --help and `rtvk scene list`,
# so they cannot drift from the CLI; the logic that uses them is the fixed text at the end.
#   gen-completion.sh RTVK_EXECUTABLE OUTPUT
set -euo pipefail
rtvk=$1 out=$2

subcommands() { awk '/^Subcommands:$/ { on = 1; next } on && /^  [^ ]/ { print $1 }'; }
# CLI11 pads an option to column 30 and puts its description after it, or, when the option is
# too wide, on the next lines, indented 30 columns. Prints "NAME TAKES_VALUE CHOICES" for each
# name of each option: "  -o,--output TEXT REQUIRED" gives "-o 1" and "--output 1".
options() {
  awk 'function emit(head,    n, words, choices, k, names, i) {
      sub(/ +$/, "", head); n = split(head, words, " ")
      choices = ""; if (match(head, /:\{[^}]*\}/)) choices = substr(head, RSTART + 2, RLENGTH - 3)
      k = split(words[1], names, ",")
      for (i = 1; i <= k; i++) print names[i], (n > 1), choices
    }
    function flush() { if (pending != "") emit(substr(pending, 3, 28)); pending = "" }
    /^  -/ { flush(); pending = $0; next }
    match($0, /^ +/) && RLENGTH == 30 { if (pending != "") emit(substr(pending, 3)); pending = ""; next }
    { flush() }
    END { flush() }'
}

declare -a subs_cases flags_cases valued_cases choices_cases
table() {  # $1: the command path, "" for rtvk itself
  local help names="" name valued choices sub list words
  read -ra words <<<"$1"
  help=$("$rtvk" "${words[@]}" --help)
  while read -r name valued choices; do
    names+=" $name"
    [[ $valued == 1 ]] && valued_cases+=("\"$1 $name\"")
    [[ -n $choices ]] && choices_cases+=("    \"$1 $name\") echo \"${choices//,/ }\" ;;")
  done < <(options <<<"$help")
  flags_cases+=("    \"$1\") echo \"${names# }\" ;;")
  list=$(subcommands <<<"$help" | xargs)
  [[ -n $list ]] && subs_cases+=("    \"$1\") echo \"$list\" ;;")
  for sub in $list; do table "${1:+$1 }$sub"; done
}
table ""
scenes=$("$rtvk" scene list | awk '{ sub(/:N$/, ":", $1); print $1 }' | xargs)

# shellcheck disable=SC2016 # the $1 and $2 quoted here are the generated functions' own
{
  echo "# bash completion for rtvk. Generated from rtvk's --help by gen-completion.sh: do not edit."
  echo "_rtvk_subcommands() {"; echo '  case $1 in'; printf '%s\n' "${subs_cases[@]}"; echo "  esac"; echo "}"
  echo "_rtvk_flags() {"; echo '  case $1 in'; printf '%s\n' "${flags_cases[@]}"; echo "  esac"; echo "}"
  echo "_rtvk_choices() {"; echo '  case "$1 $2" in'; printf '%s\n' "${choices_cases[@]}"; echo "  esac"; echo "}"
  echo "_rtvk_takes_value() {"
  echo '  case "$1 $2" in'; (IFS='|'; echo "    ${valued_cases[*]}) return 0 ;;"); echo "  esac"
  echo "  return 1"; echo "}"
  echo "_rtvk_scenes=\"$scenes\""
  cat <<'LOGIC'

_rtvk_add() { mapfile -t -O "${#COMPREPLY[@]}" COMPREPLY; }  # appends stdin's lines

_rtvk_files() {  # folders, and the files that match one of the globs given (any file if none)
  compopt -o filenames 2>/dev/null
  local glob
  _rtvk_add < <(compgen -d -- "$cur")
  [[ $# == 0 ]] && set -- '*'
  for glob; do _rtvk_add < <(compgen -f -X "!$glob" -- "$cur"); done
}

_rtvk_scene_value() {  # a built-in scene (spheres: wants its N), a .json scene file or a mesh
  _rtvk_add < <(compgen -W "$_rtvk_scenes" -- "$cur")
  [[ ${#COMPREPLY[@]} == 1 && ${COMPREPLY[0]} == *: ]] && compopt -o nospace 2>/dev/null
  _rtvk_files '*.json' '*.obj' '*.gltf' '*.glb'
}

_rtvk() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} path="" i w
  COMPREPLY=()
  # The subcommands typed so far, skipping the values of flags that take one.
  for ((i = 1; i < COMP_CWORD; i++)); do
    w=${COMP_WORDS[i]}
    if _rtvk_takes_value "$path" "$w"; then ((i++)); continue; fi
    [[ " $(_rtvk_subcommands "$path") " == *" $w "* ]] && path=${path:+$path }$w
  done
  if _rtvk_takes_value "$path" "$prev"; then
    case $prev in
      --scene) _rtvk_scene_value ;;
      -o | --output | --diff | --json) _rtvk_files ;;
      *) _rtvk_add < <(compgen -W "$(_rtvk_choices "$path" "$prev")" -- "$cur") ;;
    esac
    return
  fi
  if [[ $cur == -* ]]; then
    _rtvk_add < <(compgen -W "$(_rtvk_flags "$path")" -- "$cur")
  elif [[ -n $(_rtvk_subcommands "$path") ]]; then
    _rtvk_add < <(compgen -W "$(_rtvk_subcommands "$path")" -- "$cur")
  elif [[ $path == "scene dump" ]]; then
    _rtvk_scene_value
  elif [[ $path == compare ]]; then
    _rtvk_files '*.png' '*.ppm'
  elif [[ $path == merge ]]; then
    _rtvk_files '*.exr'
  fi
}
complete -F _rtvk rtvk
LOGIC
} >"$out.tmp"
bash -n "$out.tmp"
mv "$out.tmp" "$out"
