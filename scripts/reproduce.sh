#!/usr/bin/env bash
# make reproduce: run every experiment (writing results/<paper>/), render every figure with
# gnuplot, write results/REPORT.md and results/claims.csv. Exit non-zero on any failed check.
set -uo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
status=0
# Figures: scripts/plot/<paper>_<figure>.gp renders what an experiment wrote for its figure.
render_one() {
  local name paper
  name=$(basename "$1" .gp)
  paper=${name%%_fig*}
  echo "$name" >> "$rendered"
  gnuplot -e "datadir='results/$paper'" "$1" || { echo "reproduce: gnuplot failed on $1" >&2; return 1; }
}
# The experiments: the 36-node reference table first (three others read its cache), the timing
# experiment last and alone (no other load distorts its ratios), the rest $JOBS at a time. Each
# experiment's figures (the ones its .meta file names) are rendered by its worker as soon as it has
# finished, while the other workers go on with experiments.
run_one() {
  "$build/experiments/$1" --root "$root" || { echo "reproduce: experiment $1 reported failed checks" >&2; return 1; }
  local paper=${1%%__*} artifact=${1#*__} figure ok=0
  for figure in $(sed -n 's/^figure: \([^|]*\)|.*/\1/p' "results/$paper/$artifact.meta"); do
    [ -f "scripts/plot/${paper}_$figure.gp" ] && { render_one "scripts/plot/${paper}_$figure.gp" || ok=1; }
  done
  return $ok
}
rendered=$(mktemp)
trap 'rm -f "$rendered"' EXIT
export -f run_one render_one
export build root rendered
first=pseudo_energy__minimum_table
last=pseudo_energy__table4_timing
run_one "$first" || status=1
# The longest (3 to 7 s each on the 2-core machine) start first, so that none is left alone at the end.
slow="pseudo_energy__circle_length_area pseudo_energy__fine_grid pseudo_energy__space_pseudo_spline typical_curves__log_aesthetic typical_curves__class_a"
{ for e in $slow; do grep -x -e "$e" "$build/experiments.txt"; done
  grep -v -x -e "$first" -e "$last" -e '' $(for e in $slow; do printf -- '-e %s ' "$e"; done) "$build/experiments.txt"; } |
  xargs -P "${JOBS:-2}" -I{} bash -c 'run_one "$1"' _ {} || status=1
run_one "$last" || status=1
# Beyond the papers: the interpolant benchmark and the peers (results/benchmark/); its figures are
# rendered with the remaining scripts below.
echo "reproduce: the interpolant benchmark (truths, classic data, random sets, peers) into results/benchmark/ ..."
bash scripts/benchmark.sh "$build" || status=1
# Any figure script no experiment named (style.gp and compare_panels.gp are loaded by the figure
# scripts, not figures themselves), $JOBS gnuplot processes at a time.
# (grep -v selects nothing when every figure was rendered: that is not a failure.)
{ ls scripts/plot/*.gp | grep -v -e '/style\.gp$' -e '/compare_panels\.gp$' | grep -v -x -F -f <(sed 's|.*|scripts/plot/&.gp|' "$rendered") || true; } |
  xargs -r -P "${JOBS:-2}" -I{} bash -c 'render_one "$1"' _ {} || status=1
bash scripts/update-docs-methods.sh "$build" || status=1   # docs/methods.md: the registry's table
"$build/cagd_report" "$root" || status=1
{
  echo "git revision: $(git rev-parse HEAD 2>/dev/null || echo unknown)"
  echo "compiler: $(c++ --version | head -1)"
  echo "cmake: $(cmake --version | head -1)"
  echo "gnuplot: $(gnuplot --version)"
  for p in libeigen3-dev libboost-dev libceres-dev libnlopt-cxx-dev libgtest-dev libcli11-dev; do
    echo "$p: $(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo '?')"
  done
} > results/ENVIRONMENT.txt
exit $status
