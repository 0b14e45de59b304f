#!/usr/bin/env bash
# Writes docs/methods.md's method table (between <!-- methods:begin --> and <!-- methods:end -->)
# from the registry, as `cagd interpolate --list-methods --markdown` prints it, and its table of the
# peers' configurations (between <!-- peers:begin --> and <!-- peers:end -->) from peers/peers.csv,
# as `cagd peers --list-markdown` prints it. Run by make reproduce; the file is replaced only when
# one of them changed, so a run leaves it untouched otherwise. The unit tests
# Methods.MethodsPageIsTheRegistry and PeerCurves.MethodsPageListsTheManifest fail while they differ.
# Usage: scripts/update-docs-methods.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
page="$root/docs/methods.md"
table=$(mktemp)
peers=$(mktemp)
next=$(mktemp "$page.XXXXXX")
trap 'rm -f "$table" "$peers" "$next"' EXIT
"$build/cagd" interpolate --list-methods --markdown > "$table"
"$build/cagd" peers --peers "$root/peers" --list-markdown > "$peers"
awk -v table="$table" -v peers="$peers" '
  /^<!-- methods:begin -->$/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
  /^<!-- peers:begin -->$/   { print; while ((getline line < peers) > 0) print line; skip = 1; next }
  /^<!-- (methods|peers):end -->$/ { skip = 0 }
  !skip { print }
' "$page" > "$next"
cmp -s "$next" "$page" || { chmod --reference="$page" "$next"; mv "$next" "$page"; }
