#!/usr/bin/env bash
# A second Mesa's lavapipe for the tests, kept out of the system: its packages are fetched by name
# from Debian's archive with apt (a private apt state; the system's sources, lists and packages
# are not touched) and unpacked into a private folder, never installed. A user's graphics stack
# is not ours to upgrade.
#   private-mesa.sh DIR SUITE     SUITE: bookworm-backports (Mesa 25) or bookworm (Mesa 22.3)
# Writes DIR/SUITE/lavapipe.json, a driver manifest with the absolute path of the unpacked
# libvulkan_lvp.so, and DIR/SUITE/env, the variables that point the Vulkan loader at it alone
# (VK_DRIVER_FILES) and the dynamic linker at the libraries unpacked beside it (LD_LIBRARY_PATH),
# and prints the path of the env file. An unpacked folder is reused; delete it to fetch again.
# RTVK_DEBIAN_MIRROR overrides the archive (default: the system's own mirror, as apt lists it).
set -euo pipefail
dir=${1:?usage: private-mesa.sh DIR SUITE} suite=${2:?usage: private-mesa.sh DIR SUITE}
mkdir -p "$dir"
out=$(realpath "$dir")/$suite
if [[ -f $out/env && -f $out/lavapipe.json ]]; then
  echo "$out/env"
  exit 0
fi
rm -rf "$out"
mkdir -p "$out"/apt/{lists/partial,archives/partial,etc/preferences.d,etc/sources.list.d} "$out/debs"

# The mirror the system's apt already uses for bookworm, else Debian's own.
mirror=${RTVK_DEBIAN_MIRROR:-}
if [[ -z $mirror ]]; then
  mirror=$(apt-get indextargets --format '$(URI)' 'Created-By: Packages' 2>/dev/null |
    sed -n 's#/dists/bookworm[^/]*/main/.*##p' | head -1)
fi
mirror=${mirror:-http://deb.debian.org/debian}
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
cat >"$out/apt/etc/sources.list" <<EOF
deb [signed-by=$keyring] $mirror bookworm main
deb [signed-by=$keyring] $mirror bookworm-backports main
EOF
# Everything apt keeps goes under $out/apt; it reads the system's installed packages only to
# know which dependencies they already satisfy.
apt_private=(-o "Dir::Etc::SourceList=$out/apt/etc/sources.list"
  -o "Dir::Etc::SourceParts=$out/apt/etc/sources.list.d"
  -o "Dir::Etc::PreferencesParts=$out/apt/etc/preferences.d"
  -o "Dir::Etc::Preferences=$out/apt/etc/preferences"
  -o "Dir::State::Lists=$out/apt/lists" -o "Dir::Cache=$out/apt"
  -o "Dir::Cache::Archives=$out/apt/archives" -o "Dir::State::status=/var/lib/dpkg/status"
  -o "Debug::NoLocking=true" -o "APT::Sandbox::User=$(id -un)")
echo "rtvk: fetching mesa-vulkan-drivers from $suite ($mirror) into $out" >&2
apt-get "${apt_private[@]}" -q update >"$out/apt/update.log" 2>&1 ||
  { cat "$out/apt/update.log" >&2; echo "rtvk: apt-get update failed (above)" >&2; exit 1; }

# The driver, and those of its dependencies that the system has too old (for Mesa 25 on
# bookworm: libdrm), as apt would install them; nothing else.
depends=$(apt-cache "${apt_private[@]}" depends "mesa-vulkan-drivers/$suite" 2>/dev/null |
  sed -n 's/^ *Depends: \([^ <]*\).*/\1/p' | sort -u)
plan=$(apt-get "${apt_private[@]}" -s install --no-install-recommends "mesa-vulkan-drivers/$suite" 2>&1) ||
  { echo "$plan" >&2; echo "rtvk: apt cannot resolve mesa-vulkan-drivers/$suite (above)" >&2; exit 1; }
packages=("mesa-vulkan-drivers/$suite")
while read -r name version; do
  [[ $name == mesa-vulkan-drivers ]] && continue
  if grep -qx "$name" <<<"$depends"; then packages+=("$name=$version"); fi
done < <(sed -n 's/^Inst \([^ ]*\) \(\[[^]]*\] \)\?(\([^ ]*\) .*/\1 \3/p' <<<"$plan")
(cd "$out/debs" && apt-get "${apt_private[@]}" -q download "${packages[@]}" >"$out/apt/download.log" 2>&1) ||
  { cat "$out/apt/download.log" >&2; echo "rtvk: apt-get download failed (above)" >&2; exit 1; }
for deb in "$out"/debs/*.deb; do dpkg-deb -x "$deb" "$out/root"; done

lib=$(find "$out/root" -name libvulkan_lvp.so -print -quit)
[[ -n $lib ]] || { echo "rtvk: mesa-vulkan-drivers from $suite holds no libvulkan_lvp.so" >&2; exit 1; }
libdir=$(dirname "$lib")
# The library path is absolute: the manifest is found by VK_DRIVER_FILES, not in a system folder.
# The api_version of the package's own lavapipe manifest (whatever it is called: the one that
# names libvulkan_lvp.so).
shipped=$(grep -l 'libvulkan_lvp\.so' "$out"/root/usr/share/vulkan/icd.d/*.json | head -1)
api=$(sed -n 's/.*"api_version": *"\([^"]*\)".*/\1/p' "$shipped")
cat >"$out/lavapipe.json" <<EOF
{
  "file_format_version": "1.0.0",
  "ICD": { "library_path": "$lib", "api_version": "${api:-1.3.0}" }
}
EOF
missing=$(LD_LIBRARY_PATH=$libdir ldd "$lib" | grep 'not found' || true)
[[ -z $missing ]] || { echo "rtvk: the unpacked lavapipe lacks libraries: $missing" >&2; exit 1; }
version=$(dpkg-deb -f "$out"/debs/mesa-vulkan-drivers_*.deb Version)
# NODEVICE_SELECT: the system's Mesa device-selection layer (an implicit layer of its own Mesa)
# is not part of what this driver is tested with.
cat >"$out/env" <<EOF
VK_DRIVER_FILES=$out/lavapipe.json
VK_ICD_FILENAMES=$out/lavapipe.json
LD_LIBRARY_PATH=$libdir
NODEVICE_SELECT=1
RTVK_PRIVATE_MESA_VERSION=$version
EOF
echo "rtvk: lavapipe of mesa-vulkan-drivers $version (${packages[*]}) in $out" >&2
echo "$out/env"
