#!/usr/bin/env bash
# The space pseudo-energy table on MPI (ctest space_table.mpi): 2 ranks, 1 rank with 3 threads and
# 3 ranks on a small grid write the same bytes; a bad argument exits 2 with one line (run as a
# singleton, without mpiexec, whose own report would add lines).
# Usage: space_table_mpi_test.sh PROGRAM MPIEXEC
set -uo pipefail
prog=$1 mpiexec=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run() { "$mpiexec" --oversubscribe -np "$1" "$prog" --n-theta 6 --n-phi 8 --threads "$2" --out "$3" > "$dir/log" 2>&1 || { echo "FAIL: -np $1 --threads $2"; cat "$dir/log"; exit 1; }; }
run 2 1 "$dir/np2.txt"
run 1 3 "$dir/np1.txt"
run 3 1 "$dir/np3.txt"
cmp "$dir/np2.txt" "$dir/np1.txt" || { echo "FAIL: 2 ranks and 1 rank x 3 threads differ"; exit 1; }
cmp "$dir/np3.txt" "$dir/np1.txt" || { echo "FAIL: 3 ranks differ"; exit 1; }
[ "$(wc -l < "$dir/np2.txt")" -eq $((6 * 6 * 8 + 3)) ] || { echo "FAIL: row count (header, column names, one row per node, checksum)"; exit 1; }
"$prog" --n-theta 1 --n-phi 8 --out "$dir/bad.txt" > "$dir/out" 2> "$dir/err"; code=$?
[ "$code" -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && [ ! -e "$dir/bad.txt" ] || { echo "FAIL: bad grid must exit 2 with one line (exit $code)"; cat "$dir/err"; exit 1; }
# The output is the command's (io/output_file.hpp): - is standard output, a directory is refused
# before the work with nothing left behind, a full device is exit 1.
"$prog" --n-theta 6 --n-phi 8 --out - > "$dir/stdout.txt" 2> "$dir/err" || { echo "FAIL: --out -"; cat "$dir/err"; exit 1; }
cmp "$dir/stdout.txt" "$dir/np1.txt" || { echo "FAIL: --out - differs from the file"; exit 1; }
[ ! -e ./- ] || { echo "FAIL: --out - wrote a file named -"; exit 1; }
mkdir "$dir/folder"
"$prog" --n-theta 6 --n-phi 8 --out "$dir/folder" > "$dir/out" 2> "$dir/err"; code=$?
[ "$code" -eq 2 ] && [ -z "$(ls -A "$dir/folder")" ] && [ -z "$(ls "$dir" | grep -e '\.tmp' -e '\.cagd-')" ] || { echo "FAIL: --out a directory must exit 2 leaving nothing (exit $code)"; ls -A "$dir"; exit 1; }
"$prog" --n-theta 6 --n-phi 8 --out /dev/full > "$dir/out" 2> "$dir/err"; code=$?
[ "$code" -eq 1 ] && grep -q 'No space left' "$dir/err" || { echo "FAIL: --out /dev/full must exit 1 naming the reason (exit $code)"; cat "$dir/err"; exit 1; }
echo "space table on MPI: 1, 2 and 3 ranks byte-identical; -, a directory and a full device handled"
