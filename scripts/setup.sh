#!/usr/bin/env bash
# Set-up shared by the README's two commands: installs the Debian packages the job needs (only
# those missing, so a second run installs nothing), then configures and builds into build/.
#   setup.sh main   the main job: the packages crosscheck needs, and only the crosscheck target
#   setup.sh tests  the test job (the default): everything, the tests' tools and every target
# Installing needs root or sudo; without either, and when apt-get fails, it says so and stops.
# The fuzz and sanitizer jobs install their own extra packages (scripts/fuzz.sh, sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
job=${1:-tests}
case $job in main|tests) ;; *) echo "setup: unknown job '$job' (main or tests)" >&2; exit 2 ;; esac

packages=(
  cmake g++ make pkg-config                 # toolchain
  libvulkan-dev mesa-vulkan-drivers         # Vulkan loader and lavapipe
  vulkan-validationlayers glslang-tools     # validation layer (vkref asks for it); GLSL -> SPIR-V at build time
  libtinyobjloader-dev nlohmann-json3-dev   # OBJ meshes and scene files
  libglm-dev                                # scene matrices (model, normal, camera) in double
  libstb-dev libcli11-dev                   # PNG output, command line
  zlib1g-dev                                # the report's PNGs and pixel data
  libsdl2-dev                               # crosscheck view's window
)
if [ "$job" = tests ]; then
  packages+=(
    libgtest-dev                            # the unit and cross-check tests
    libbenchmark-dev                        # softraster_benchmarks (benchmarks/), built to keep it compiling
    clang                                   # an outside consumer built with Clang too
    chromium libxml2-utils bsdutils         # the report in a browser, JUnit (xmllint), a terminal (script)
    python3 python3-yaml                    # the bench JSON check, the README's CI recipe run; scenes/tools/
    xvfb xauth                              # crosscheck view's window under a virtual X server (xvfb-run)
  )
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
      echo "setup: these packages are missing and installing them needs root or sudo (neither is available): ${missing[*]}" >&2
      exit 1
    fi
    sudo=(sudo)
  fi
  echo "setup: installing ${missing[*]}"
  log=$(mktemp)
  if ! { "${sudo[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq "${missing[@]}"; } >"$log" 2>&1; then
    cat "$log" >&2
    echo "setup: apt-get failed (its output is above); missing: ${missing[*]}" >&2
    rm -f "$log"
    exit 1
  fi
  rm -f "$log"
fi

if [ "$job" = main ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=OFF >/dev/null
  cmake --build build -j"$(nproc)" --target crosscheck
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON >/dev/null
  cmake --build build -j"$(nproc)"
fi
