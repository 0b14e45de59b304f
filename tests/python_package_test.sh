#!/usr/bin/env bash
# The Python package as a Python user gets it (ctest python.package):
#  1. pip: `pip install --no-build-isolation .` (pyproject.toml, setup.py) into a virtual
#     environment that sees Debian's numpy, then import from outside the tree, __version__,
#     the registry, and `pip show` metadata; `python3 -m build --no-isolation --wheel` (Debian
#     python3-build) makes a wheel holding the stubs.
#  2. cmake --install: the package lands where the interpreter looks under the prefix
#     (scripts/python-install-dir.py) and imports from there; with the default PREFIX=/usr/local
#     that directory is on the system python3's sys.path.
# The module is not compiled again: setup.py builds the target in BUILD_DIR (CAGD_BUILD_DIR), a
# no-op when it is up to date. Usage: python_package_test.sh PYTHON BUILD_DIR SOURCE_DIR
set -euo pipefail
python=$1 build=$(cd "$2" && pwd) source=$(cd "$3" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A copy of what the package build reads, so that pip writes nothing into the source tree.
mkdir -p "$work/src"
cp -r "$source/pyproject.toml" "$source/setup.py" "$source/README.md" "$source/CMakeLists.txt" "$source/python" "$work/src/"
"$python" -m venv --system-site-packages "$work/venv"
CAGD_BUILD_DIR="$build" "$work/venv/bin/pip" install --quiet --no-build-isolation --no-index "$work/src" > "$work/pip.log" 2>&1 || { cat "$work/pip.log"; fail "pip install"; }
cd "$work"
out=$("$work/venv/bin/python" -c "import cagd; print(cagd.__version__, [m['name'] for m in cagd.methods()][:3], cagd.__file__)")
echo "pip install: $out"
case "$out" in "0."*"['pseudo-spline', 'cubic-a', 'cubic-b']"*"$work/venv/"*) ;; *) fail "the installed package: $out" ;; esac
show=$("$work/venv/bin/pip" show cagd)
for field in "Name: cagd" "Version: $("$python" -c "import re,sys; print(re.search(r'project\(\s*cagd_repro\s+VERSION\s+([0-9.]+)', open(sys.argv[1]).read()).group(1))" "$source/CMakeLists.txt")" \
             "License: MIT" "Summary: Interpolating curves" "Requires: numpy"; do
  grep -q "^$field" <<< "$show" || fail "pip show lacks '$field': $show"
done
"$work/venv/bin/python" -c "import cagd, os; d = os.path.dirname(cagd.__file__); assert all(os.path.exists(os.path.join(d, f)) for f in ('py.typed', '_cagd.pyi')), os.listdir(d)"
# The OpenCASCADE plugin (core/detail/opencascade_plugin.hpp) comes with the package, and the
# module loads it from there (not from the build tree) on the first use.
if [ -f "$build/libcagd_occt.so" ]; then
  "$work/venv/bin/python" -c "
import cagd, os, numpy as np
d = os.path.dirname(cagd.__file__)
plugin = os.path.join(d, 'libcagd_occt.so')
assert os.path.exists(plugin), os.listdir(d)
assert plugin not in open('/proc/self/maps').read(), 'loaded before use'
c = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), 'occt-interpolate')
assert plugin in open('/proc/self/maps').read(), 'the plugin beside the module was not the one loaded'
" || fail "the OpenCASCADE plugin of the installed package"
  echo "pip install: the OpenCASCADE plugin loads from the package"
fi
CAGD_BUILD_DIR="$build" "$python" -m build --no-isolation --wheel --outdir "$work/dist" "$work/src" > "$work/wheel.log" 2>&1 || { cat "$work/wheel.log"; fail "python3 -m build --no-isolation --wheel"; }
wheel=$(ls "$work"/dist/cagd-*.whl)
listing=$("$python" -m zipfile -l "$wheel")
grep -q "cagd/_cagd.pyi" <<< "$listing" && grep -q "cagd/py.typed" <<< "$listing" || fail "the wheel lacks the stubs: $listing"
echo "wheel: $(basename "$wheel")"

# cmake --install into a temporary prefix: the package goes where the interpreter looks.
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
rel=$("$python" "$source/scripts/python-install-dir.py" /usr/local)
[ -f "$work/prefix/$rel/cagd/__init__.py" ] && ls "$work/prefix/$rel/cagd"/_cagd*.so > /dev/null || fail "cmake --install put no package in $rel"
if [ -f "$build/libcagd_occt.so" ]; then
  ls "$work/prefix"/lib*/cagd/libcagd_occt.so "$work/prefix/$rel/cagd/libcagd_occt.so" > /dev/null || fail "cmake --install put no OpenCASCADE plugin in lib/cagd and the package"
fi
out=$(PYTHONPATH="$work/prefix/$rel" "$python" -c "import cagd; print(cagd.__version__, cagd.__file__)")
echo "cmake --install: $out"
case "$out" in *"$work/prefix/$rel/cagd/"*) ;; *) fail "imported from elsewhere: $out" ;; esac
"$python" -c "import sys; d = '/usr/local/$rel'; assert d in sys.path, (d, sys.path)" || fail "/usr/local/$rel is not on $python's path"
echo "python package: ok"
