#!/usr/bin/env bash
# The interpolant benchmark into results/benchmark/ (make benchmark; make reproduce runs it too):
# the methods on data with a truth, the classic data and seeded random sets (cagd benchmark; the
# random sets' run times in results/timing/, not compared), then the peers (cagd peers: other
# libraries' interpolants run by their adapters under peers/, and the identity table). A peer that
# is not installed is skipped and named. Figures are rendered by the caller. Usage: scripts/benchmark.sh BUILD
set -uo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
status=0
mkdir -p results/timing
started=$SECONDS
"$build/cagd" benchmark --out results/benchmark --classic reference/benchmark/classic_data.csv --timing-out results/timing/benchmark_random_sets.csv --quiet ||
  { echo "benchmark: cagd benchmark failed" >&2; status=1; }
# The JavaScript peers' packages, as peers/package-lock.json pins them (installed once per lockfile).
if command -v npm > /dev/null 2>&1; then
  (cd peers && (cmp -s package-lock.json node_modules/.cagd-lock 2>/dev/null ||
    (npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.cagd-lock))) ||
    echo "benchmark: npm ci in peers/ failed: the JavaScript peers are skipped" >&2
fi
"$build/cagd" peers --peers peers --identities reference/benchmark/peer_identities.csv --classic reference/benchmark/classic_data.csv --out results/benchmark --programs "$build/peers" ||
  { echo "benchmark: cagd peers failed" >&2; status=1; }
echo "benchmark: took $((SECONDS - started)) s"
exit $status
