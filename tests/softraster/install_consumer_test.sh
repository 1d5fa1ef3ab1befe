#!/usr/bin/env bash
# softraster as an installed package, seen from outside: installs the build tree into a scratch
# prefix, checks what was installed, then one of
#   gcc | clang  configures consumer/ with that compiler and its default flags (-O2, nothing about
#                floating point: only what the softraster target carries), runs the triangle
#                check and the exactness check against the project's reference frames; gcc
#                then does it again at -O0 (no inlining: the scalar path, which must match too)
#   control      the GCC build with the target's -ffp-contract=off removed and -ffp-contract=fast
#                (a package without the fix): on a CPU with FMA its frames must differ, or the
#                exactness check could not see contraction
#   pkg-config   compiles consumer/main.cpp with only `pkg-config --cflags --libs softraster`
#   examples     configures examples/ against the package (with GLM) and runs both examples
# Usage: install_consumer_test.sh BUILD_DIR SOURCE_DIR MODE
set -euo pipefail
build_dir=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
mode=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build_dir" --prefix "$prefix" >/dev/null

# What was installed: headers (with the generated version header), the CMake package, the
# pkg-config file, the documentation and the examples; the include folder listed once.
for f in include/softraster/pipeline.hpp include/softraster/version.hpp include/softraster/glm.hpp \
         lib/cmake/softraster/softrasterConfig.cmake lib/cmake/softraster/softrasterConfigVersion.cmake \
         lib/pkgconfig/softraster.pc share/doc/softraster/README.md share/doc/softraster/library.md \
         share/doc/softraster/examples/CMakeLists.txt; do
  test -f "$prefix/$f" || { echo "not installed: $f"; exit 1; }
done
includes=$(grep 'INTERFACE_INCLUDE_DIRECTORIES' "$prefix/lib/cmake/softraster/softrasterTargets.cmake")
[ "$(grep -o '/include' <<<"$includes" | wc -l)" -eq 1 ] || { echo "include folder listed more than once: $includes"; exit 1; }

reference=$work/reference.frames
case $mode in gcc | clang | control) "$build_dir/bin/softraster_exactness_reference" "$reference" ;; esac

consumer() {  # consumer(COMPILER, CONTROL, OPT, TARGET...): configure consumer/ in $work/build, build the targets
  cmake -S "$source_dir/tests/softraster/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_CXX_COMPILER="$1" -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS="$3" -DCONSUMER_WITHOUT_CONTRACT_OFF="$2" \
    -DSOFTRASTER_SHADERS_DIR="$source_dir/shaders" >/dev/null
  cmake --build "$work/build" --target "${@:4}" >/dev/null
}

case $mode in
  gcc | clang)
    if [ "$mode" = gcc ]; then consumer g++ OFF -O2 consumer exactness; else consumer clang++ OFF -O2 consumer exactness; fi
    "$work/build/consumer"
    "$work/build/exactness" "$reference"
    if [ "$mode" = gcc ]; then
      consumer g++ OFF "" exactness
      echo "at -O0:"
      "$work/build/exactness" "$reference"
    fi
    ;;
  control)
    if ! grep -qw fma /proc/cpuinfo; then
      echo "control: this CPU has no FMA, so contraction cannot change the fused path's bits; nothing to check"
      exit 0
    fi
    consumer g++ ON -O2 exactness
    if "$work/build/exactness" "$reference"; then
      echo "control: frames built with -ffp-contract=fast match; the exactness check cannot see contraction"
      exit 1
    fi
    echo "control: contraction noticed"
    ;;
  pkg-config)
    export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
    [ "$(pkg-config --modversion softraster)" = "$(sed -n 's/^#define SOFTRASTER_VERSION_STRING "\(.*\)"/\1/p' "$prefix/include/softraster/version.hpp")" ]
    flags=$(pkg-config --cflags softraster)
    grep -q -- -ffp-contract=off <<<"$flags" || { echo "softraster.pc: no -ffp-contract=off in '$flags'"; exit 1; }
    # shellcheck disable=SC2046  # pkg-config's output is a list of flags
    g++ -std=c++20 -O2 -Wall -Wextra -o "$work/consumer" "$source_dir/tests/softraster/consumer/main.cpp" \
      $(pkg-config --cflags --libs softraster)
    "$work/consumer"
    ;;
  examples)
    cmake -S "$prefix/share/doc/softraster/examples" -B "$work/examples" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
    cmake --build "$work/examples" >/dev/null
    "$work/examples/lit_obj" "$source_dir/scenes/meshes/torus.obj" "$work/lit.png"
    "$work/examples/msaa_wireframe" "$work/msaa.png"
    for png in lit.png msaa.png; do
      [ "$(head -c 8 "$work/$png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || { echo "$png is not a PNG"; exit 1; }
    done
    echo "examples ran: lit.png $(stat -c %s "$work/lit.png") bytes, msaa.png $(stat -c %s "$work/msaa.png") bytes"
    ;;
  *)
    echo "unknown mode $mode"
    exit 2
    ;;
esac
