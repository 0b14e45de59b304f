#!/usr/bin/env bash
# Rewrites README.md's method table (between <!-- methods:begin --> and <!-- methods:end -->) from
# the registry, as `cagd interpolate --list-methods --markdown` prints it. Run by make reproduce;
# tests/test_methods.cpp (ReadmeTableIsTheRegistry) fails while the two differ.
# Usage: scripts/update-readme-methods.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
table=$(mktemp)
trap 'rm -f "$table"' EXIT
"$build/cagd" interpolate --list-methods --markdown > "$table"
awk -v table="$table" '
  /^<!-- methods:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /^<!-- methods:end -->$/   { skip = 0 }
  !skip { print }
' "$root/README.md" > "$root/README.md.tmp"
mv "$root/README.md.tmp" "$root/README.md"
