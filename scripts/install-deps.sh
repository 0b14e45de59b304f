#!/usr/bin/env bash
# Install the Debian 12 packages that cagd-repro needs to build, test, reproduce
# and plot; only those not yet installed. Idempotent and quiet when all are present.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  ninja-build            # the build's generator (make test compiles with both cores busy)
  libeigen3-dev          # linear algebra, point types
  libboost-dev libboost-math-dev   # Boost.Math quadrature/interpolators, Boost.Multiprecision (headers)
  libceres-dev           # nonlinear least squares, gradient solvers (pseudo_energy reference CG)
  libgoogle-glog-dev     # Ceres's logger; fairness/ silences its CG-restart warnings
  libnlopt-cxx-dev       # bounded/constrained minimisation
  libgtest-dev libgmock-dev        # unit tests
  libbenchmark-dev       # make bench
  libcli11-dev           # command line of the cagd tool
  gnuplot-nox            # figures (pngcairo and svg terminals)
  doxygen                # make docs and make test: the API reference, no undocumented public declaration
  clang libclang-rt-14-dev         # make sanitize: ASan/UBSan and libFuzzer runtimes
  python3                # make test: the claim-id and folder-dependency checks (standard library only)
  python3-dev pybind11-dev python3-numpy   # the Python module `cagd` (python/), built for /usr/bin/python3
  python3-pytest         # make test: the Python module's tests
  python3-nbclient python3-ipykernel python3-matplotlib   # make test: runs examples/curvature_combs.ipynb
  libopenmpi-dev openmpi-bin   # the space pseudo-energy table on MPI (optional in CMake; make test runs mpirun -np 2)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: missing Debian packages: ${missing[*]}" >&2
if ! command -v apt-get >/dev/null 2>&1; then
  echo "install-deps: no apt-get on this machine; install these packages by hand:" >&2
  echo "  apt-get install -y ${missing[*]}" >&2
  exit 1
fi
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo_cmd=(sudo -n)
  else
    echo "install-deps: not root and no password-less sudo; run as root:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
