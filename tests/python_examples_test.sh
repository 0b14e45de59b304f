#!/usr/bin/env bash
# The Python examples (ctest python.types): each runs from an empty temporary directory and leaves
# it empty, and all pass `mypy --strict` against the package's stubs (python/cagd/_cagd.pyi,
# py.typed). Usage: python_examples_test.sh PYTHON PACKAGE_PARENT_DIR EXAMPLES_DIR
set -euo pipefail
python=$1 package=$(cd "$2" && pwd) examples=$(cd "$3" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for f in "$examples"/*.py; do
  PYTHONPATH="$package" PYTHONDONTWRITEBYTECODE=1 "$python" "$f" > "$work.out" || { cat "$work.out"; echo "FAIL: $f"; exit 1; }
  [ -z "$(ls -A "$work")" ] || { echo "FAIL: $f wrote into its working directory: $(ls -A "$work")"; exit 1; }
  echo "ran $(basename "$f")"
done
rm -f "$work.out"
command -v mypy > /dev/null || { echo "FAIL: mypy is not installed (scripts/install-deps.sh test)"; exit 1; }
MYPYPATH="$package" mypy --strict --cache-dir "$work/.mypy_cache" "$examples"/*.py
