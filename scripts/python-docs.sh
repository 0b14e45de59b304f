#!/usr/bin/env bash
# The Python API reference (docs/python-api, Sphinx autodoc of the module's docstrings) into OUT,
# with every Sphinx warning an error. Usage: scripts/python-docs.sh PYTHON_PACKAGE_PARENT OUT
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
package=$(cd "$1" && pwd) out=$2
command -v sphinx-build >/dev/null || { echo "python-docs: sphinx-build is not installed (scripts/install-deps.sh docs)" >&2; exit 1; }
PYTHONPATH="$package" PYTHONDONTWRITEBYTECODE=1 sphinx-build -q -W --keep-going -b html -d "$out/.doctrees" "$root/docs/python-api" "$out"
echo "python-docs: $out/index.html, no warnings"
