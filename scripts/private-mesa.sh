#!/usr/bin/env bash
# A second Mesa's lavapipe for the tests, kept out of the system: its packages are fetched by name
# from Debian's archive with apt (a private apt state; the system's sources, lists, hooks and
# packages are not touched) and unpacked into a private folder, never installed. A user's
# graphics stack is not ours to upgrade.
#   private-mesa.sh SUITE     SUITE: bookworm-backports (Mesa 25) or bookworm (Mesa 22.3)
# Into $RTVK_MESA_DIR/SUITE (default ~/.cache/rtvk-test-mesa/SUITE) it writes lavapipe.json, a
# driver manifest with the absolute path of the unpacked libvulkan_lvp.so, and env, the
# variables that point the Vulkan loader at that driver alone (VK_DRIVER_FILES) and the dynamic
# linker at the libraries unpacked beside it (LD_LIBRARY_PATH); it prints the path of env. A
# complete folder is reused; delete it to fetch again. RTVK_DEBIAN_MIRROR overrides the archive
# (default: the mirror the system's apt uses for Debian bookworm, else deb.debian.org).
set -euo pipefail
suite=${1:?usage: private-mesa.sh SUITE (bookworm or bookworm-backports)}
case $suite in
  bookworm | bookworm-backports) ;;
  *) echo "rtvk: private-mesa.sh: SUITE '$suite' is neither bookworm nor bookworm-backports" >&2; exit 2 ;;
esac
base=${RTVK_MESA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/rtvk-test-mesa}
mkdir -p "$base"
base=$(realpath "$base")
out=$base/$suite
die() { echo "rtvk: private-mesa.sh: $*" >&2; exit 1; }

# One fetch at a time per folder; a folder counts as complete only with its env file (written
# last, by rename) and the library its manifest names.
exec 9>"$base/.lock"
flock 9
if [[ -f $out/env && -f $out/lavapipe.json ]]; then
  lib=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' "$out/lavapipe.json")
  if [[ -f $lib ]]; then
    echo "$out/env"
    exit 0
  fi
fi
rm -rf "$out"
mkdir -p "$out"/apt/{lists/partial,archives/partial,etc/apt.conf.d,etc/preferences.d,etc/sources.list.d} "$out/debs"

mirror=${RTVK_DEBIAN_MIRROR:-}
if [[ -z $mirror ]]; then
  mirror=$(apt-get indextargets --format '$(SITE)' 'Created-By: Packages' 'Label: Debian' \
    'Codename: bookworm' 2>/dev/null | head -1 || true)
fi
mirror=${mirror:-http://deb.debian.org/debian}
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
cat >"$out/apt/etc/sources.list" <<EOF
deb [signed-by=$keyring] $mirror bookworm main
deb [signed-by=$keyring] $mirror bookworm-backports main
EOF
# apt reads APT_CONFIG before anything else: the system's apt.conf.d is copied (its proxy and
# the like still apply) and followed by a file that clears the hooks an update would run
# (appstream's cache refresh, PackageKit's...), which are the system's business, not ours.
cp -r /etc/apt/apt.conf.d/. "$out/apt/etc/apt.conf.d/" 2>/dev/null || true
cat >"$out/apt/etc/apt.conf.d/zz-rtvk-private" <<'EOF'
#clear APT::Update::Pre-Invoke;
#clear APT::Update::Post-Invoke;
#clear APT::Update::Post-Invoke-Success;
#clear DPkg::Pre-Invoke;
#clear DPkg::Post-Invoke;
#clear DPkg::Pre-Install-Pkgs;
EOF
cat >"$out/apt/apt.conf" <<EOF
Dir::Etc::Parts "$out/apt/etc/apt.conf.d";
Dir::Etc::SourceList "$out/apt/etc/sources.list";
Dir::Etc::SourceParts "$out/apt/etc/sources.list.d";
Dir::Etc::Preferences "$out/apt/etc/preferences";
Dir::Etc::PreferencesParts "$out/apt/etc/preferences.d";
Dir::State::Lists "$out/apt/lists";
Dir::Cache "$out/apt";
Dir::Cache::Archives "$out/apt/archives";
Dir::State::status "/var/lib/dpkg/status";
Debug::NoLocking "true";
APT::Sandbox::User "$(id -un)";
EOF
export APT_CONFIG=$out/apt/apt.conf
echo "rtvk: fetching mesa-vulkan-drivers from $suite ($mirror) into $out" >&2
apt-get -q update >"$out/apt/update.log" 2>&1 || { cat "$out/apt/update.log" >&2; die "apt-get update failed (above)"; }

# The driver, and those of its dependencies that the system has too old (for Mesa 25 on
# bookworm: libdrm), as apt would install them; nothing else. apt reads the system's package
# status only to know what it already has.
depends=$(apt-cache depends "mesa-vulkan-drivers/$suite" 2>&1) || { echo "$depends" >&2; die "apt-cache depends failed (above)"; }
depends=$(sed -n 's/^ *Depends: \([^ <]*\).*/\1/p' <<<"$depends" | sort -u)
plan=$(apt-get -s install --no-install-recommends "mesa-vulkan-drivers/$suite" 2>&1) ||
  { echo "$plan" >&2; die "apt cannot resolve mesa-vulkan-drivers/$suite (above)"; }
packages=("mesa-vulkan-drivers/$suite")
while read -r name version; do
  [[ $name == mesa-vulkan-drivers ]] && continue
  if grep -qx "$name" <<<"$depends"; then packages+=("$name=$version"); fi
done < <(sed -n 's/^Inst \([^ ]*\) \(\[[^]]*\] \)\?(\([^ ]*\) .*/\1 \3/p' <<<"$plan")
(cd "$out/debs" && apt-get -q download "${packages[@]}" >"$out/apt/download.log" 2>&1) ||
  { cat "$out/apt/download.log" >&2; die "apt-get download failed (above)"; }
for deb in "$out"/debs/*.deb; do dpkg-deb -x "$deb" "$out/root"; done

lib=$(find "$out/root" -name libvulkan_lvp.so -print -quit)
[[ -n $lib ]] || die "mesa-vulkan-drivers from $suite holds no libvulkan_lvp.so"
libdir=$(dirname "$lib")
missing=$(LD_LIBRARY_PATH=$libdir ldd "$lib" | grep 'not found' || true)
[[ -z $missing ]] || die "the unpacked lavapipe lacks libraries: $missing"
# The api_version of the package's own lavapipe manifest, whatever it is called (the one that
# names libvulkan_lvp.so).
api=
for m in "$out"/root/usr/share/vulkan/icd.d/*.json; do
  grep -q 'libvulkan_lvp\.so' "$m" || continue
  api=$(sed -n 's/.*"api_version": *"\([^"]*\)".*/\1/p' "$m")
done
[[ -n $api ]] || die "mesa-vulkan-drivers from $suite has no manifest naming libvulkan_lvp.so"
# The library path is absolute: the manifest is read through VK_DRIVER_FILES, from this folder.
cat >"$out/lavapipe.json" <<EOF
{
  "file_format_version": "1.0.0",
  "ICD": { "library_path": "$lib", "api_version": "$api" }
}
EOF
version=$(dpkg-deb -f "$out"/debs/mesa-vulkan-drivers_*.deb Version)
# NODEVICE_SELECT: the system's Mesa device-selection layer (an implicit layer of its own Mesa)
# is not part of what this driver is tested with.
{
  printf 'VK_DRIVER_FILES=%q\n' "$out/lavapipe.json"
  printf 'VK_ICD_FILENAMES=%q\n' "$out/lavapipe.json"
  printf 'LD_LIBRARY_PATH=%q\n' "$libdir"
  printf 'NODEVICE_SELECT=1\n'
  printf 'RTVK_PRIVATE_MESA_VERSION=%q\n' "$version"
} >"$out/env.tmp"
mv "$out/env.tmp" "$out/env"
echo "rtvk: lavapipe of mesa-vulkan-drivers $version (${packages[*]}) in $out" >&2
echo "$out/env"
