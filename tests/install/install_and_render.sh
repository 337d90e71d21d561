#!/usr/bin/env bash
# `cmake --install` into a fresh prefix: only rtvk's files arrive (the executable, its library
# with its header and CMake package, the Python module; no test or third-party file), the man
# page, docs and bash completion are there and true to the CLI, the installed rtvk renders from
# another folder, with the source and build trees hidden where a private mount namespace can hide
# them, the same bytes as the build tree's rtvk, the docs' C++ example builds against the
# installed package and renders, and the installed module imports and renders.
#   install_and_render.sh CMAKE BUILD_DIR SOURCE_DIR
set -euo pipefail
export LC_ALL=C  # the completion candidates are compared sorted
cmake=$1 build=$(realpath "$2") src=$(realpath "$3")
tmp=$(mktemp -d /tmp/rtvk-install-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix work=$tmp/work
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# What CI must have: outside CI a missing tool only narrows the test, in CI it fails it.
missing() { if [[ -n ${CI:-} ]]; then fail "$* (CI=$CI)"; else echo "note: $*"; fi; }
# Output is captured before grep reads it: `cmd | grep -q` under pipefail can fail when grep
# stops reading early and cmd dies of SIGPIPE.

"$cmake" --install "$build" --prefix "$prefix" >"$tmp/install.log"
cat "$tmp/install.log"
# Every file installed is one of rtvk's: GoogleTest, the benchmarks or a library would show here.
grep -E '^-- (Installing|Up-to-date):' "$tmp/install.log" | sed -E 's/^-- [^:]*: //' | while read -r f; do
  case ${f#"$prefix"/} in
    bin/rtvk | share/man/man1/rtvk.1.gz | share/bash-completion/completions/rtvk) ;;
    share/doc/rtvk/README.md | share/doc/rtvk/docs | share/doc/rtvk/docs/*) ;;
    include/rtvk/rtvk.h | lib/librtvk.so* | lib/cmake/rtvk/rtvk*.cmake) ;;
    lib/python3*/dist-packages/rtvk.cpython-*.so | lib/python3*/dist-packages/rtvk.pyi) ;;
    *) fail "installed a file that is not rtvk's: $f" ;;
  esac
done
[[ $(find "$prefix" -type f | wc -l) -ge 10 ]] || fail "too few files installed"

# The binary, without a run path into the build tree.
[[ -x $prefix/bin/rtvk ]] || fail "no bin/rtvk"
dynamic=$(readelf -d "$prefix/bin/rtvk") || fail "readelf -d bin/rtvk"
if grep -Eq 'RPATH|RUNPATH' <<<"$dynamic"; then fail "bin/rtvk has a run path"; fi
[[ $("$prefix/bin/rtvk" --version) == "rtvk "* ]] || fail "rtvk --version"

# The docs, as in the source tree.
[[ -f $prefix/share/doc/rtvk/README.md ]] || fail "no README.md in the docs"
for f in "$src"/docs/*.md "$src"/docs/images/* "$src"/docs/farm/*; do
  cmp "$f" "$prefix/share/doc/rtvk/docs/${f#"$src"/docs/}" || fail "docs: ${f#"$src"/} missing or different"
done

# The man page: gzipped roff that man reads, with a section for each subcommand.
man=$prefix/share/man/man1/rtvk.1.gz
[[ -f $man ]] || fail "no man page"
gzip -t "$man" || fail "the man page is not gzip"
zcat "$man" >"$tmp/man.roff"
grep -q '^\.TH RTVK "1"' "$tmp/man.roff" || fail "the man page has no .TH line"
for cmd in render compare devices scene bench merge view; do
  grep -qx ".SS \"rtvk $cmd\"" "$tmp/man.roff" || fail "the man page has no section for rtvk $cmd"
done
# Every built-in scene rtvk has, named in the description (in roff: bold, dashes escaped).
"$build/rtvk" scene list >"$tmp/scenes.txt"
while read -r scene _; do
  want=${scene%%:*}
  grep -qF "\\fB${want//-/\\-}" "$tmp/man.roff" || fail "the man page does not name the scene $scene"
done <"$tmp/scenes.txt"
if ! command -v man >/dev/null; then
  missing "no man (Debian: man-db), so the page is not rendered"
else
  MANWIDTH=80 man -l "$man" >"$tmp/man.txt" 2>"$tmp/man.err" || fail "man -l: $(cat "$tmp/man.err")"
  grep -q -- '--gpu-timeout' "$tmp/man.txt" || fail "man -l shows no --gpu-timeout"
  grep -q '^EXIT STATUS' "$tmp/man.txt" || fail "man -l shows no EXIT STATUS"
  # What the README says: with the prefix's bin/ on PATH, `man rtvk` finds the page (man-db
  # looks beside each bin/ of PATH), and without it does not.
  found=$(env -u MANPATH PATH="$prefix/bin:/usr/bin:/bin" man -w rtvk 2>&1) || true
  [[ $found == "$man" ]] || fail "with $prefix/bin on PATH, man -w rtvk gives '$found', not $man"
fi

# The bash completion, driven as bash would: every flag it offers is in that command's --help.
completion=$prefix/share/bash-completion/completions/rtvk
[[ -f $completion ]] || fail "no bash completion"
rtvk=$prefix/bin/rtvk
complete_words() {  # the words typed, the last one being completed; prints the candidates
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _rtvk
           printf "%s\n" "${COMPREPLY[@]}" | sort' _ "$completion" "$@"
}
expect() {  # expect WANT WORDS...: the candidates for WORDS, one line, sorted
  local got
  got=$(cd "$work" && complete_words "${@:2}" | xargs)
  [[ $got == "$1" ]] || fail "completing '${*:2}': got '$got', want '$1'"
}
for cmd in render compare devices scene bench merge view; do
  flags=$(complete_words rtvk "$cmd" -)
  [[ -n $flags ]] || fail "no flags completed for rtvk $cmd"
  help=$("$rtvk" "$cmd" --help)
  for flag in $flags; do
    grep -Eq -- "(^|[ ,])$flag([ ,=]|$)" <<<"$help" || fail "completion offers $flag, not in rtvk $cmd --help"
  done
done
# The flags the completion's fixed logic names, with the command whose help must have them.
for pair in render:--scene render:--output render:-o bench:--json compare:--diff merge:--output; do
  help=$("$rtvk" "${pair%%:*}" --help)
  grep -Eq -- "(^|[ ,])${pair#*:}[ ,]" <<<"$help" || fail "rtvk ${pair%%:*} has no ${pair#*:}"
done
touch "$work/a.json" "$work/b.png" "$work/c.exr" "$work/d.ppm"
expect "bench compare devices merge render scene view" rtvk ""
expect "--samples --sampling --scene --scene-root --seed --shutter --spp" rtvk render --s
expect "--spp" rtvk render --scene seed --sp
expect "auto both cpu gpu" rtvk render --backend ""
expect "seed showcase simple-light spheres:" rtvk render --scene s
expect "a.json book-final bouncing-spheres checkered-spheres cornell-box cornell-smoke materials next-week-final perlin-spheres quads rest-of-life-final seed showcase simple-light spheres:" rtvk bench --scene ""
expect "b.png d.ppm" rtvk compare ""
expect "c.exr" rtvk merge -q ""
expect "dump" rtvk scene d
expect "--json" rtvk bench --js
rm "$work"/*

# The installed rtvk renders from another folder, the same bytes as the build tree's rtvk: with
# the CPU, and through lavapipe with the GPU shaders embedded in the binary. lavapipe is found by
# its driver ID (the "lavapipe" device selector), whatever its manifest is called and wherever
# the loader found it; both rtvks then render on it through RTVK_DEVICE.
backends=(cpu)
if "$build/rtvk" devices --device lavapipe >"$tmp/devices.txt" 2>&1; then
  backends+=(gpu)
  export RTVK_DEVICE=lavapipe
else
  missing "no lavapipe, so no GPU render: $(cat "$tmp/devices.txt")"
fi
# Runs rtvk render in $work with the source and build trees hidden under empty mounts where a
# private mount namespace can be had (root, or user namespaces), else just from $work.
# The probe mounts for real: some sandboxes allow the namespace but not the mount.
hide=()
mkdir "$tmp/probe"
# shellcheck disable=SC2016 # expanded by the inner bash
probe='mount -t tmpfs none "$1"'
if unshare --mount bash -c "$probe" _ "$tmp/probe" 2>/dev/null; then
  hide=(unshare --mount)
elif unshare --mount --map-root-user bash -c "$probe" _ "$tmp/probe" 2>/dev/null; then
  hide=(unshare --mount --map-root-user)
else
  echo "note: no mount namespace here; rendering from another folder without hiding the trees"
fi
render_installed() {
  if [[ ${#hide[@]} == 0 ]]; then (cd "$work" && "$rtvk" render "$@"); return; fi
  # shellcheck disable=SC2016 # expanded by the inner bash
  "${hide[@]}" bash -c 'src=$1 build=$2 work=$3; shift 3
    mount -t tmpfs none "$src" && { [[ $build == "$src"/* ]] || mount -t tmpfs none "$build"; } &&
    [[ ! -e $src/CMakeLists.txt && ! -e $build/rtvk ]] && cd "$work" && exec "$@"' \
    _ "$src" "$build" "$work" "$rtvk" render "$@"
}
for backend in "${backends[@]}"; do
  (cd "$work" && "$build/rtvk" render --scene seed --backend "$backend" -q -o "$tmp/reference.png")
  [[ -s $tmp/reference.png ]] || fail "the build tree's rtvk wrote no image ($backend)"
  render_installed --scene seed --backend "$backend" -o seed.png \
    || fail "the installed rtvk did not render with --backend $backend"
  cmp "$work/seed.png" "$tmp/reference.png" || fail "the installed rtvk's $backend image differs"
  rm "$work/seed.png" "$tmp/reference.png"
done
# The docs' C++ example against the installed package: find_package(rtvk CONFIG), rtvk::rtvk.
"$cmake" -S "$src/docs/examples/cpp" -B "$tmp/example" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  >"$tmp/example.log" 2>&1 || { cat "$tmp/example.log"; fail "configuring the C++ example"; }
"$cmake" --build "$tmp/example" >>"$tmp/example.log" 2>&1 \
  || { cat "$tmp/example.log"; fail "building the C++ example against the package"; }
LD_LIBRARY_PATH=$prefix/lib "$tmp/example/render_views" cornell-box cpu >"$tmp/example.out" \
  || fail "the C++ example did not render: $(cat "$tmp/example.out")"
cat "$tmp/example.out"
grep -q '^view 2: 64x48, mean 0\.[0-9]*, objects at [1-9]' "$tmp/example.out" \
  || fail "the C++ example printed no third view with objects"
# The installed Python module, from the prefix's own path.
pydir=$(echo "$prefix"/lib/python3*/dist-packages)
[[ -f $pydir/rtvk.pyi ]] || fail "no rtvk.pyi beside the module"
shape=$(cd "$work" && PYTHONPATH=$pydir /usr/bin/python3 -c \
  "import rtvk; print(rtvk.Renderer(rtvk.Scene('seed')).render(rtvk.Camera.from_scene('seed')).shape)") \
  || fail "the installed module does not render"
[[ $shape == "(225, 400, 3)" ]] || fail "the installed module's image is $shape"
echo "PASS: installed into $prefix; ${backends[*]} renders from $work equal the build tree's" \
  "${hide[*]:+(source and build trees hidden)}"
