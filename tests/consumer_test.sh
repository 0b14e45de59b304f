#!/usr/bin/env bash
# The install as an outside project sees it (ctest install.consumer): cmake --install into a
# temporary prefix; build examples/consumer against it with find_package(cagd), and its main.cpp
# again with pkg-config's flags alone; both must print what the same source built in this tree
# prints (the library's own value); every installed header compiles alone and every docs/cpp.md
# example builds against the install (installed_headers_test.py). Usage: consumer_test.sh BUILD_DIR SOURCE_DIR IN_TREE_EXE
set -euo pipefail
build=$1 source=$2 in_tree=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
for f in include/cagd/core/errors.hpp include/cagd/fairness/pseudo_spline.hpp lib/cmake/cagd/cagdConfig.cmake \
         lib/cmake/cagd/cagdConfigVersion.cmake lib/cmake/cagd/cagdTargets.cmake lib/pkgconfig/cagd.pc; do
  [ -f "$work/prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
[ ! -e "$work/prefix/include/cagd/repro" ] && [ ! -e "$work/prefix/include/cagd/cli" ] || { echo "FAIL: harness or command headers installed"; exit 1; }
expected=$("$in_tree")
echo "in tree:     $expected"

cmake -S "$source/examples/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" || { cat "$work/build.log"; exit 1; }
got=$("$work/consumer/consumer")
echo "find_package: $got"
[ "$got" = "$expected" ] || { echo "FAIL: the installed library prints something else"; exit 1; }

flags=$(PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig" pkg-config --cflags --libs cagd)
${CXX:-c++} -O2 "$source/examples/consumer/main.cpp" $flags -o "$work/consumer_pc"
got=$("$work/consumer_pc")
echo "pkg-config:   $got"
[ "$got" = "$expected" ] || { echo "FAIL: the pkg-config build prints something else"; exit 1; }

# Every installed header compiles alone, and every C++ example of docs/cpp.md builds against the install.
/usr/bin/python3 "$source/tests/installed_headers_test.py" "$work/prefix" "$source"
