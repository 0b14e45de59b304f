#!/usr/bin/env bash
# make docs: the Doxygen API reference of the public headers (docs/Doxyfile) into OUT/html.
# Fails, listing them, on any warning: an undocumented public declaration or a malformed comment.
# Usage: scripts/docs.sh [OUT]   (default build/docs)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/docs}"
command -v doxygen >/dev/null || { echo "docs: doxygen is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
mkdir -p "$out"
log="$out/warnings.log"
cd "$root"
echo "docs: Doxygen over the public headers into $out ..."
{ cat docs/Doxyfile; echo "OUTPUT_DIRECTORY = $out"; echo "WARN_LOGFILE = $log"; } | doxygen - >/dev/null
if [ -s "$log" ]; then
  cat "$log" >&2
  echo "docs: $(grep -c 'warning:' "$log") warning(s) in the public headers' documentation" >&2
  exit 1
fi
echo "docs: $out/html/index.html, no warnings"
