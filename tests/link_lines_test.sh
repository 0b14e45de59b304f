#!/usr/bin/env bash
# The library, the command, the Python module and the OpenCASCADE plugin are MIT and stay so: none
# of them links a GPL or AGPL library (ctest licence.link_lines). The peers GSL, ALGLIB, SISL and
# libspiro are programs of their own (peers/, docs/peers.md) or a test program
# (cagd_spiro_libspiro_test); this reads what the MIT binaries load (ldd) and what the static
# library asks its users to link (its pkg-config file).
# Usage: link_lines_test.sh BUILD_DIR BINARY_OR_FOLDER...   (a folder: its shared objects; absent ones
# are not built in this tree and are passed over)
set -euo pipefail
build=$1
shift
forbidden='libgsl|libgslcblas|libalglib|libsisl|libspiro'
status=0
binaries=()
for given in "$@"; do
  if [ -d "$given" ]; then binaries+=("$given"/*.so); elif [ -e "$given" ]; then binaries+=("$given"); fi
done
[ ${#binaries[@]} -gt 0 ] || { echo "FAIL: no binary to check"; exit 1; }
for binary in "${binaries[@]}"; do
  [ -e "$binary" ] || continue
  if hits=$(ldd "$binary" | grep -E "$forbidden"); then
    echo "FAIL: $binary loads a GPL or AGPL library: $hits"
    status=1
  else
    echo "ok: $(basename "$binary") loads no GPL or AGPL library ($(ldd "$binary" | wc -l) libraries)"
  fi
done
for file in "$build/cagd.pc"; do
  [ -e "$file" ] || continue
  if grep -E -q "gsl|alglib|sisl|spiro" "$file"; then
    echo "FAIL: $file asks for a GPL or AGPL library: $(grep -E -o "[^ ;\"]*(gsl|alglib|sisl|spiro)[^ ;\"]*" "$file" | head -3)"
    status=1
  else
    echo "ok: $(basename "$file") names no GPL or AGPL library"
  fi
done
# The check itself must be able to fail: the test program that does link libspiro is found.
if [ -e "$build/tests/cagd_spiro_libspiro_test" ] && ! ldd "$build/tests/cagd_spiro_libspiro_test" | grep -q -E "$forbidden"; then
  echo "FAIL: cagd_spiro_libspiro_test links libspiro, but ldd does not show it: this check sees nothing"
  status=1
fi
exit $status
