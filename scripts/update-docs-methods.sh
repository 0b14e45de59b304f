#!/usr/bin/env bash
# Writes docs/methods.md's method table (between <!-- methods:begin --> and <!-- methods:end -->)
# from the registry, as `cagd interpolate --list-methods --markdown` prints it. Run by make
# reproduce; the file is replaced only when the registry changed, so a run leaves it untouched
# otherwise. The unit test Methods.MethodsPageIsTheRegistry fails while the two differ.
# Usage: scripts/update-docs-methods.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
page="$root/docs/methods.md"
table=$(mktemp)
next=$(mktemp "$page.XXXXXX")
trap 'rm -f "$table" "$next"' EXIT
"$build/cagd" interpolate --list-methods --markdown > "$table"
awk -v table="$table" '
  /^<!-- methods:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /^<!-- methods:end -->$/   { skip = 0 }
  !skip { print }
' "$page" > "$next"
cmp -s "$next" "$page" || { chmod --reference="$page" "$next"; mv "$next" "$page"; }
