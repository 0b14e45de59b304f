#!/usr/bin/env bash
# The install-deps layers are enough for their targets (ctest deps.layers):
#  1. The Makefile's CMake flags of `make install` (the python layer), of the library alone
#     (library layer) and of `make reproduce` (reproduce layer) configure a fresh build tree while
#     CMake is forbidden to find any package outside the layer (CMAKE_DISABLE_FIND_PACKAGE_<name>):
#     GoogleTest, Google Benchmark, MPI, and for the layers without Python pybind11 and Python.
#  2. What the build of each tree would compile and link comes from the layer's packages:
#     deps_layer_files.py preprocesses every translation unit (g++ -M) and reads the link lines,
#     and finds each system header and library in dpkg's file lists. A build on this machine could
#     not show this, since every layer's packages are installed here; and the full build costs
#     minutes of CPU per tree.
# The library and the module are the same targets `make test` builds.
# Usage: deps_layers_test.sh SOURCE_DIR
set -euo pipefail
source=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags() { make -s -C "$source" --no-print-directory --eval "print-flags: ; @echo \$($1)" print-flags; }
disable() { for p in "$@"; do printf -- '-DCMAKE_DISABLE_FIND_PACKAGE_%s=ON ' "$p"; done; }
configure() {  # LAYER FLAGS... : configure a fresh tree with them
  local layer=$1; shift
  if cmake -S "$source" -B "$work/$layer" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" > "$work/$layer.log" 2>&1; then
    echo "layer $layer: configures without the other layers' packages"
  else
    cat "$work/$layer.log"; echo "FAIL: layer $layer needs a package outside it"; exit 1
  fi
}
install_flags=$(flags INSTALL_FLAGS)
# shellcheck disable=SC2046  # word splitting of the flag lists is intended
configure python $install_flags $(disable GTest benchmark MPI)
# shellcheck disable=SC2046
configure library ${install_flags/-DCAGD_BUILD_PYTHON=ON/-DCAGD_BUILD_PYTHON=OFF} $(disable GTest benchmark MPI pybind11 Python)
# shellcheck disable=SC2046
configure reproduce $(flags REPRODUCE_ON) $(disable GTest benchmark MPI pybind11 Python)
grep -q "cagd_python" "$work/python/build.ninja" 2>/dev/null || grep -rq "cagd_python" "$work/python/Makefile" 2>/dev/null || { echo "FAIL: the python layer's tree has no module target"; exit 1; }
python3 "$source/tests/deps_layer_files.py" "$work/python" "$source" python:cagd_python,cagd: library:cagd:CMakeFiles/cagd
python3 "$source/tests/deps_layer_files.py" "$work/reproduce" "$source" reproduce:experiments/curvature_profile__fig2_clothoid_spline,cagd:
