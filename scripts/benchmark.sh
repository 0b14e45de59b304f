#!/usr/bin/env bash
# The interpolant benchmark into results/benchmark/. Usage: scripts/benchmark.sh BUILD [WHAT]
#   benchmark (the default; make reproduce): the methods on data with a truth, the classic data and
#             seeded random sets (cagd benchmark; the random sets' run times in results/timing/, not
#             compared), then the peers (cagd peers: other libraries' interpolants run by their
#             adapters under peers/, and the identity table);
#   scorecard (make scorecard): Levien's properties for every method and peer on 10^4 random
#             polygons (cagd scorecard; about half an hour on two cores, so make reproduce leaves it out);
#   all       (make benchmark): both.
# A peer that is not installed is skipped and named. Figures are rendered by the caller.
set -uo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
status=0
mkdir -p results/timing
started=$SECONDS
what=${2:-benchmark}
case $what in benchmark | scorecard | all) ;; *) echo "benchmark: WHAT is benchmark, scorecard or all, not $what" >&2; exit 2 ;; esac
if [ "$what" != scorecard ]; then
  "$build/cagd" benchmark --out results/benchmark --classic reference/benchmark/classic_data.csv --timing-out results/timing/benchmark_random_sets.csv --quiet ||
    { echo "benchmark: cagd benchmark failed" >&2; status=1; }
fi
# The JavaScript peers' packages, as peers/package-lock.json pins them (installed once per lockfile).
if command -v npm > /dev/null 2>&1; then
  (cd peers && (cmp -s package-lock.json node_modules/.cagd-lock 2>/dev/null ||
    (npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.cagd-lock))) ||
    echo "benchmark: npm ci in peers/ failed: the JavaScript peers are skipped" >&2
fi
if [ "$what" != scorecard ]; then
  "$build/cagd" peers --peers peers --identities reference/benchmark/peer_identities.csv --classic reference/benchmark/classic_data.csv --out results/benchmark --programs "$build/peers" ||
    { echo "benchmark: cagd peers failed" >&2; status=1; }
fi
if [ "$what" != benchmark ]; then
  "$build/cagd" scorecard --out results/benchmark --peers peers --programs "$build/peers" --classic reference/benchmark/classic_data.csv ||
    { echo "benchmark: cagd scorecard failed" >&2; status=1; }
fi
echo "benchmark: took $((SECONDS - started)) s"
exit $status
