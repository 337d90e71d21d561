#!/usr/bin/env bash
# `cpack -G DEB` on the build tree (into a temporary folder): the package's control fields name
# what rtvk needs at run time, dlopened Vulkan loader included, and it holds only rtvk's files.
#   deb_package.sh CPACK BUILD_DIR
set -euo pipefail
cpack=$1 build=$(realpath "$2")
tmp=$(mktemp -d /tmp/rtvk-deb-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$cpack" --config "$build/CPackConfig.cmake" -G DEB -B "$tmp" >"$tmp/cpack.log" 2>&1 \
  || { cat "$tmp/cpack.log"; fail "cpack -G DEB"; }
debs=("$tmp"/rtvk_*.deb)
[[ ${#debs[@]} == 1 && -f ${debs[0]} ]] || fail "cpack made no rtvk_*.deb: $(ls "$tmp")"
deb=${debs[0]}
dpkg-deb -I "$deb"
field() { dpkg-deb -f "$deb" "$1"; }
# A field's entries, one a line, without version constraints: "libc6 (>= 2.34)" -> "libc6".
entries() { field "$1" | tr ',' '\n' | sed -E 's/\(.*\)//; s/^ +//; s/ +$//'; }

[[ $(field Package) == rtvk ]] || fail "Package is not rtvk"
[[ $(field Section) == graphics ]] || fail "Section is not graphics"
grep -qx libvulkan1 <<<"$(entries Depends)" || fail "Depends lacks libvulkan1"
# dpkg-shlibdeps ran: the libraries rtvk links (libc, libstdc++, OpenEXR, the mesh loaders) are
# in Depends.
for lib in libc6 'libstdc\+\+6' 'libopenexr.*' 'libtinyobjloader.*' 'libtinygltf.*' 'libmeshoptimizer.*'; do
  grep -Eqx "$lib" <<<"$(entries Depends)" || fail "Depends lacks $lib (dpkg-shlibdeps did not run?)"
done
grep -qx mesa-vulkan-drivers <<<"$(entries Recommends)" || fail "Recommends lacks mesa-vulkan-drivers"
grep -qx bash-completion <<<"$(entries Recommends)" || fail "Recommends lacks bash-completion (the completion is inert without it)"
grep -qx vulkan-validationlayers <<<"$(entries Suggests)" || fail "Suggests lacks vulkan-validationlayers"

dpkg-deb -c "$deb" | awk '{ print $6 }' >"$tmp/files"
for f in ./usr/bin/rtvk ./usr/share/man/man1/rtvk.1.gz ./usr/share/bash-completion/completions/rtvk \
  ./usr/share/doc/rtvk/README.md; do
  grep -qx "$f" "$tmp/files" || fail "the package lacks $f"
done
for f in ./usr/include/rtvk/rtvk.h ./usr/lib/python3/dist-packages/rtvk.pyi; do
  grep -qx "$f" "$tmp/files" || fail "the package lacks $f"
done
grep -Eq '^\./usr/lib/python3/dist-packages/rtvk\.cpython-.*\.so$' "$tmp/files" \
  || fail "the package lacks the Python module"
! grep -Ev '^\./usr/(bin/rtvk|share/(man/man1/rtvk\.1\.gz|bash-completion/completions/rtvk|doc/rtvk/.*)|include/rtvk/rtvk\.h|lib/(librtvk\.so.*|cmake/rtvk/rtvk.*\.cmake|python3/dist-packages/rtvk(\.pyi|\.cpython-.*\.so)))$' \
  "$tmp/files" | grep -v '/$' | grep . || fail "the package holds files that are not rtvk's (above)"
echo "PASS: $(basename "$deb"): Depends: $(field Depends)"
