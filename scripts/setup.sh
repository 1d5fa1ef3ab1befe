#!/usr/bin/env bash
# Set-up shared by the README's two commands: installs the Debian packages the project needs
# (only those missing, so a second run installs nothing), then configures and builds into build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ make pkg-config                 # toolchain
  clang                                     # tests: an outside consumer built with Clang too
  libvulkan-dev mesa-vulkan-drivers         # Vulkan loader and lavapipe
  vulkan-validationlayers glslang-tools     # validation in tests; GLSL -> SPIR-V at build time
  libtinyobjloader-dev nlohmann-json3-dev   # OBJ meshes and scene files
  libglm-dev                                # scene matrices (model, normal, camera) in double
  libstb-dev libcli11-dev libgtest-dev      # PNG output, command line, tests
  zlib1g-dev                                # the report's pixel data
  chromium libxml2-utils bsdutils           # tests: the report in a browser, JUnit (xmllint), a terminal (script)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j"$(nproc)"
