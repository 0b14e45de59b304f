#!/usr/bin/env bash
# make sanitize: the ASan + UBSan build of the modules behind `cagd compare` (tests/sanitize),
# their tests, and the libFuzzer targets for a bounded time. Any sanitizer report, test failure
# or fuzzer crash fails the run. Usage: scripts/sanitize.sh BUILD_DIR
#   CAGD_PROPERTY_SETS  random point sets per method in the property test (default here 400, about
#                       16 s instrumented; make test runs the full 10^4)
#   CAGD_FUZZ_SECONDS   seconds per fuzz target (default 30; the two run at once, one core each)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-sanitize}"
# A new tree uses Ninja when it is installed (as the main build); one configured before keeps its generator.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja > /dev/null 2>&1; then generator=(-G Ninja); fi
CXX=clang++ cmake -S "$root/tests/sanitize" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE= >/dev/null
cmake --build "$build" -j"${JOBS:-2}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The 10^6- and 6·10^4-point tests are left to make test: instrumented, the curvature-profile
# Newton on them takes minutes, through the code the small cases already cover.
CAGD_PROPERTY_SETS="${CAGD_PROPERTY_SETS:-400}" "$build/cagd_sanitized_tests" --gtest_filter='-*MillionPoints*:*LongOpenSpline*' --gtest_brief=1

seconds="${CAGD_FUZZ_SECONDS:-30}"
# The two targets fuzz at the same time, one core each (libFuzzer runs one process per target):
# each gets its full ${seconds} s, the run takes ${seconds} s instead of twice that.
fuzz() {
  local target=$1 scratch="$build/corpus-$1" log="$build/fuzz-$1.log" status=0
  # New inputs go to a scratch directory; the committed seed corpus is only read.
  mkdir -p "$scratch"
  rm -f "$build"/failure-"$target"-*
  "$build/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
      -artifact_prefix="$build/failure-$target-" "$scratch" "$root/tests/fuzz/corpus/$target" > "$log" 2>&1 || status=$?
  echo "$status" > "$build/fuzz-$target.status"
}
targets="readers interpolate"
echo "sanitize: fuzzing $targets for ${seconds} s each, at once"
for target in $targets; do fuzz "$target" & done
wait
for target in $targets; do
  log="$build/fuzz-$target.log"
  status=$(cat "$build/fuzz-$target.status")
  echo "sanitize: fuzz_$target"
  grep -E "^stat::(number_of_executed_units|new_units_added)" "$log" || true
  if [ "$status" -ne 0 ]; then
    tail -n 60 "$log" >&2
    echo "sanitize: fuzz_$target failed (exit $status); input: $(ls "$build"/failure-"$target"-* 2>/dev/null || echo none)" >&2
    exit 1
  fi
done
echo "sanitize: tests and fuzzing clean."
