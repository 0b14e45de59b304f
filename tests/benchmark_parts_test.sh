#!/usr/bin/env bash
# The interpolant benchmark split (ctest benchmark.parts): `cagd benchmark --part K/N` runs merged
# by `--merge`, and cagd_benchmark_mpi on 1, 2 and 3 ranks, write the same directory, byte for byte,
# as one whole `cagd benchmark` run with the same options. Bad splits exit 2 with one line and leave
# nothing. MPI is skipped (and said) when cagd_benchmark_mpi was not built.
# Usage: benchmark_parts_test.sh CAGD SOURCE_DIR [MPI_PROGRAM MPIEXEC]
set -uo pipefail
cagd=$1 src=$2 mpi=${3:-} mpiexec=${4:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
plan=(--sizes 6,12,24 --families circle,helix,clothoid --methods cubic-b,spiro,pseudo-spline,boost-pchip --random-sets 20 --random-sizes 8,32
      --classic "$src/reference/benchmark/classic_data.csv")
# The run times inside the --out directory, which does not exist yet (as docs/benchmark.md shows it).
"$cagd" benchmark --out "$dir/whole" "${plan[@]}" --timing-out "$dir/whole/random_sets_seconds.csv" 2> "$dir/err" || { cat "$dir/err"; fail "the whole run"; }
[ -s "$dir/whole/random_sets_seconds.csv" ] || fail "--timing-out inside --out was not written"
mv "$dir/whole/random_sets_seconds.csv" "$dir/whole_seconds.csv"
[ "$(ls "$dir/whole" | wc -l)" -ge 8 ] || fail "the whole run wrote $(ls "$dir/whole" | wc -l) files"
for k in 1 2 3; do "$cagd" benchmark --out "$dir/part$k" "${plan[@]}" --part "$k/3" --threads 1 2> "$dir/err" || { cat "$dir/err"; fail "--part $k/3"; }; done
"$cagd" benchmark --out "$dir/merged" "${plan[@]}" --merge "$dir/part2" "$dir/part3" "$dir/part1" --timing-out "$dir/merged_seconds.csv" 2> "$dir/err" ||
  { cat "$dir/err"; fail "--merge"; }
diff -r "$dir/whole" "$dir/merged" > "$dir/diff" || { head "$dir/diff"; fail "3 parts merged differ from the whole run"; }
[ "$(wc -l < "$dir/merged_seconds.csv")" -eq "$(wc -l < "$dir/whole_seconds.csv")" ] || fail "the merged run times have other rows"
# SIGTERM at moments spread over a --merge (about 25 ms): nothing is left behind, since every
# temporary is registered before it exists (io/temporary_file.hpp).
for delay in 0 0.002 0.004 0.006 0.008 0.01 0.012 0.014 0.016 0.018 0.02 0.025 0.03 0.04 0.06; do
  "$cagd" benchmark --out "$dir/killed" "${plan[@]}" --merge "$dir/part2" "$dir/part3" "$dir/part1" > /dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -TERM "$pid" 2> /dev/null
  wait "$pid"
  left=$(find "$dir" -name '.*.cagd-*' | head -3)
  [ -z "$left" ] || fail "SIGTERM after $delay s of --merge left $left"
  rm -rf "$dir/killed"
done
# A missing part, a part of other options: exit 2, one line naming it, no directory.
expect_refusal() {  # expect_refusal TEXT ARGS...: exit 2, one line containing TEXT, nothing at $dir/bad
    local text=$1; shift
    "$cagd" benchmark --out "$dir/bad" "$@" > "$dir/out" 2> "$dir/err"; local code=$?
    [ "$code" -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -qF -- "$text" "$dir/err" && [ ! -e "$dir/bad" ] ||
      { cat "$dir/err"; fail "$* must exit 2 with one line naming '$text' (exit $code)"; }
}
expect_refusal "part 3 of 3 is missing" "${plan[@]}" --merge "$dir/part1" "$dir/part2"
expect_refusal "another plan" --sizes 6,12 --families circle,helix,clothoid --methods cubic-b,spiro,pseudo-spline,boost-pchip --random-sets 20 --random-sizes 8,32 \
  --classic "$src/reference/benchmark/classic_data.csv" --merge "$dir/part1" "$dir/part2" "$dir/part3"
head -c 100 "$dir/part2" > "$dir/cut"
expect_refusal "cut: no checksum line" "${plan[@]}" --merge "$dir/part1" "$dir/cut" "$dir/part3"
if [ -z "$mpi" ]; then echo "benchmark parts: 3 parts merged byte-identical; MPI not built, its runs skipped"; exit 0; fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
for np in 1 2 3; do
  "$mpiexec" --oversubscribe -np "$np" "$mpi" --out "$dir/mpi$np" "${plan[@]}" --threads 1 > "$dir/log" 2>&1 || { cat "$dir/log"; fail "cagd_benchmark_mpi on $np ranks"; }
  diff -r "$dir/whole" "$dir/mpi$np" > "$dir/diff" || { head "$dir/diff"; fail "$np ranks differ from the whole run"; }
done
"$mpi" --out "$dir/bad" --sizes 2 > "$dir/out" 2> "$dir/err"; code=$?
[ "$code" -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && [ ! -e "$dir/bad" ] || { cat "$dir/err"; fail "cagd_benchmark_mpi --sizes 2 must exit 2 with one line (exit $code)"; }
echo "benchmark parts: 3 parts merged and 1, 2, 3 MPI ranks byte-identical to the whole run; bad merges refused"
