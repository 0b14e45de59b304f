#!/usr/bin/env bash
# Install the Debian 12 packages a target of cagd-repro needs, in layers; only those not yet
# installed. Idempotent, and quiet when all are present.
#
#   scripts/install-deps.sh [LAYER ...]          (no layer: all of them)
#   scripts/install-deps.sh --list [LAYER ...]   print the layers' packages, one per line
#
#   library    build and install the C++ library and the cagd command (make install without Python)
#   python     + the Python module (make python, make install, pip install --no-build-isolation .)
#   reproduce  + the figures and the peers (make reproduce, make benchmark)
#   peers      the benchmark's peers: GSL, ALGLIB, SISL, libspiro, MetaPost, Asymptote, plotutils, Node.js and npm (the
#              JavaScript peers' packages come from peers/package-lock.json: scripts/benchmark.sh)
#   test       everything below: GoogleTest, the Python tests, MPI, the API docs, the sanitizers and
#              the benchmarks' packages (make test, make sanitize)
#   bench      + Google Benchmark and the peers' Python (make bench)
#   docs       Doxygen and Sphinx (make docs, with the python layer)
#   web        + Emscripten, Chromium, Node.js and npm (make web, make test-web; make test runs the
#              browser tests when Emscripten and Chromium are installed)
#
# As root it says what it installs, then installs it with apt-get. Otherwise it prints the
# apt-get line to run and stops (exit 1): it never installs anything without saying what.
set -euo pipefail

library=(
  cmake g++ make pkg-config
  ninja-build            # the build's generator (compiles a target's files while its libraries build)
  ccache                 # compiled objects reused across build trees and clean clones (scripts/cmake/ccache.cmake)
  libeigen3-dev          # linear algebra, point types
  libboost-dev libboost-math-dev   # Boost.Math quadrature/interpolators, Boost.Multiprecision (headers)
  libceres-dev           # nonlinear least squares, gradient solvers (pseudo_energy reference CG)
  libgoogle-glog-dev     # Ceres's logger; fairness/ silences its CG-restart warnings
  libnlopt-cxx-dev       # bounded/constrained minimisation
  liblapack-dev          # banded LU (dgbtrf) for the curvature-profile Newton steps (numeric/banded_lu.hpp)
  libcli11-dev           # the cagd command's options
  nlohmann-json3-dev     # the JSON curve documents (export/curve_json.cpp)
  libocct-data-exchange-dev   # STEP export through OpenCASCADE (export/step_writer.cpp; LGPL-2.1 with exception)
  libocct-modeling-algorithms-dev  # GeomAPI_Interpolate, the occt-interpolate peer (methods/register_opencascade.cpp)
  libtbb-dev             # OpenCASCADE's CMake targets link libtbb.so, which its -dev packages do not bring
)
python=(
  python3 python3-dev pybind11-dev python3-numpy   # the module `cagd`, built for /usr/bin/python3
  python3-pip python3-setuptools python3-wheel python3-venv   # pip install --no-build-isolation .
  python3-build          # python3 -m build --no-isolation: a wheel
)
reproduce=(
  gnuplot-nox            # figures (pngcairo and svg terminals)
)
peers=(
  libgsl-dev             # the gsl peer (peers/gsl: a program of its own, GPL)
  libalglib-dev          # the alglib peer (peers/alglib: a program of its own, GPL)
  libsisl-dev            # the sisl peer (peers/sisl: a program of its own, AGPL)
  libspiro-dev           # the libspiro peer (peers/libspiro: a program of its own, GPL)
  texlive-binaries texlive-metapost   # the metapost peer: mpost and its plain macros
  asymptote              # the asymptote peer: asy
  plotutils              # the plotutils peer: GNU spline
)
test=(
  libgtest-dev libgmock-dev        # unit tests
  doxygen python3-sphinx # the API references: no undocumented public declaration, no Sphinx warning
  clang libclang-rt-14-dev         # make sanitize: ASan/UBSan and libFuzzer runtimes
  python3-pytest         # the Python module's tests
  python3-nbclient python3-ipykernel python3-matplotlib   # runs examples/curvature_combs.ipynb
  mypy                   # the Python examples pass mypy --strict against the stubs
  libopenmpi-dev openmpi-bin   # the space pseudo-energy table on MPI (make test runs mpirun -np 2)
  python3-ezdxf chromium # the export test reads DXF with ezdxf and renders SVG in headless Chromium
  libspiro-dev           # the spiro method's check against libspiro (a test program only: GPL)
  python3-fonttools fonts-dejavu-core   # the benchmark's glyph outlines regenerate (scripts/glyph_points.py)
)
bench=(
  libbenchmark-dev       # make bench
  python3-scipy          # make bench: scipy's splines as the Python peer; the Python tests of Curve.from_ppoly
)
docs=(
  doxygen                # the C++ API reference
  python3-sphinx         # the Python API reference from the docstrings
)
web=(
  emscripten             # make web: the library compiled to WebAssembly (Debian's 3.1.6)
  chromium               # make test-web: the viewer in headless Chromium (puppeteer-core from web/package-lock.json)
  python3-ezdxf          # make test-web reads the viewer's DXF export back
)
# Node.js and npm (puppeteer-core, the static server) may come from another source than Debian
# (NodeSource's nodejs brings its own npm): Debian's packages only where there is no node or npm.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then web+=(nodejs npm); peers+=(nodejs npm); fi

list_only=0
if [ "${1:-}" = "--list" ]; then list_only=1; shift; fi
layers=("$@")
[ ${#layers[@]} -gt 0 ] || layers=(library python reproduce peers test bench docs web)
packages=()
for layer in "${layers[@]}"; do
  case "$layer" in
    library) packages+=("${library[@]}") ;;
    python) packages+=("${library[@]}" "${python[@]}") ;;
    reproduce) packages+=("${library[@]}" "${reproduce[@]}" "${peers[@]}") ;;
    peers) packages+=("${library[@]}" "${peers[@]}") ;;
    test) packages+=("${library[@]}" "${python[@]}" "${reproduce[@]}" "${peers[@]}" "${test[@]}" "${bench[@]}") ;;  # make test's build has the benchmarks too
    bench) packages+=("${library[@]}" "${python[@]}" "${bench[@]}") ;;
    docs) packages+=("${docs[@]}") ;;
    web) packages+=("${library[@]}" "${web[@]}") ;;  # the native command makes the tests' golden files
    *) echo "install-deps: unknown layer '$layer'; allowed: library python reproduce peers test bench docs web" >&2; exit 2 ;;
  esac
done

if [ $list_only -eq 1 ]; then printf '%s\n' "${packages[@]}" | sort -u; exit 0; fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    case " ${missing[*]} " in *" $p "*) ;; *) missing+=("$p") ;; esac
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps (${layers[*]}): missing Debian packages: ${missing[*]}" >&2
if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: no apt-get on this machine; install these packages by hand:" >&2
  echo "  apt-get install -y ${missing[*]}" >&2
  exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: not root; run as root (or with sudo):" >&2
  echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
echo "install-deps: installing them with apt-get" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
