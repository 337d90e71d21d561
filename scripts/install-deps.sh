#!/usr/bin/env bash
# Installs, from Debian bookworm's archive, every package rtvk needs to build, render and test.
# Does nothing (and needs no network) when all of them are already installed.
#   install-deps.sh          build, render and package (help2man: the man page; dpkg-dev and file:
#                            cpack -G DEB)
#   install-deps.sh --test   also what only the tests use: Slurm, for the farm job files' test,
#                            man-db, to read the installed man page, Xvfb, an X server
#                            without a screen for rtvk view's window, xdotool, to drive it, and
#                            twm, a window manager to minimize it, python3-opencv, the
#                            calibrated cameras' oracle (cv2.projectPoints), and python3-pytest,
#                            which runs the Python module's tests
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libglm-dev libcli11-dev libstb-dev nlohmann-json3-dev libtbb-dev libglfw3-dev libx11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libvulkan-dev libvulkan-volk-dev glslang-tools spirv-tools libspirv-cross-c-shared-dev
  mesa-vulkan-drivers vulkan-validationlayers
  clang libclang-rt-14-dev
  libopenexr-dev libtinyobjloader-dev libtinygltf-dev libembree-dev
  libdraco-dev libmeshoptimizer-dev
  pybind11-dev python3-dev python3-numpy
  help2man dpkg-dev file
)
if [ "${1:-}" = "--test" ]; then
  packages+=(slurm-wlm man-db xvfb xdotool twm python3-opencv python3-pytest)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "rtvk: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "rtvk: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
