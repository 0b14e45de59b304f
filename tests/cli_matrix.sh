#!/usr/bin/env bash
# The `cagd` command's input/output contract over a matrix of inputs: every subcommand (every
# interpolation method of the registry) × classes of bad and edge input, bad output targets and
# bad numeric options. For every run it asserts:
#   - the exit code is 0, 1 or 2 (no crash), within 60 s (no hang);
#   - on exit 1 or 2: exactly one line on stderr, nothing on stdout, no output file, no temporary
#     file left beside it;
#   - on exit 0: no nan or inf in any output (the energy table's own inf marks of undefined nodes
#     excepted, see fairness/pseudo_energy_table.hpp) and, for inputs that must read unchanged
#     (CRLF, a byte-order mark, comments), the first point kept;
#   - the expected exit code where the class fixes it (bad input 2, good input 0).
# Usage: tests/cli_matrix.sh path/to/cagd
set -u
cagd=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
runs=0 fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# ---- input files -----------------------------------------------------------------------------
p() { printf '%b' "$2" > "$dir/$1.csv"; }
p good '0,0\n1,1\n2,0\n3,1\n4,0.5\n5,0\n'
p empty ''
p header_only 'x,y\n'
p one_point '0,0\n'
p repeated '0,0\n1,1\n1,1\n2,0\n3,1\n'
p nan '0,0\n1,nan\n2,0\n3,1\n4,0\n'
p inf '0,0\n1,inf\n2,0\n3,1\n4,0\n'
p huge '0,0\n1e308,1e308\n-1e308,1e308\n1e308,-1e308\n-1e308,-1e308\n'
p tiny '0,0\n1e-300,0\n2e-300,1e-300\n3e-300,0\n4e-300,1e-300\n'
p garbage 'hello world\n\001\002 garbage\n'
p typo_first '0,0x\n1,1\n2,0\n3,1\n'
p spaces '0 0\n1 1\n2 0\n3 1\n'
p columns '0,0\n1,1,1\n2,0\n3,1\n'
p crlf '0,0\r\n1,1\r\n2,0\r\n3,1\r\n4,0.5\r\n5,0\r\n'
p bom '\357\273\2770,0\n1,1\n2,0\n3,1\n4,0.5\n5,0\n'
p bom_header '\357\273\277x,y\n0,0\n1,1\n2,0\n3,1\n4,0.5\n5,0\n'
p comments '# a comment\n0,0 # first\n1,1\n\n2,0\n3,1\n4,0.5\n5,0\n'
head -c 2000000 /dev/zero | tr '\0' '7' > "$dir/long_line.csv"
printf '\n1,1\n' >> "$dir/long_line.csv"
# grids of heights (surface tensor, smooth-surface): 5 x 5
for i in 0 1 2 3 4; do for j in 0 1 2 3 4; do echo "$i,$j,$(( (i * i + j) % 3 ))"; done; done > "$dir/grid.csv"
{ head -12 "$dir/grid.csv"; echo "2,2,nan"; tail -12 "$dir/grid.csv"; } > "$dir/grid_nan.csv"
{ head -12 "$dir/grid.csv"; echo "2,2"; tail -12 "$dir/grid.csv"; } > "$dir/grid_columns.csv"
for i in 0 1 2 3 4; do for j in 0 1 2 3 4; do echo "$i,$j,$(( (i + j) % 2 ? 1 : -1 ))e308"; done; done > "$dir/grid_huge.csv"
# space points, control points of a planar B-spline, a curve written by interpolate
p space '0,0,0\n1,0,1\n2,1,0\n3,1,1\n4,0,0\n'
"$cagd" interpolate --in "$dir/good.csv" --out "$dir/curve.csv" --samples 4
p curve_nan 'u,x,y,dx,dy,ddx,ddy\n0,0,0,1,0,0,0\n1,1,nan,1,0,0,0\n2,2,0,1,0,0,0\n'
p curve_noheader '0,0,0,1,0,0,0\n1,1,0,1,0,0,0\n'
p curve_zero_speed 'u,x,y,dx,dy,ddx,ddy\n0,0,0,0,0,0,0\n1,1,0,1,0,0,0\n'
p curve3d 'u,x,y,z\n0,0,0,0\n1,1,0,1\n2,2,1,1\n'
mkdir -p "$dir/adir"

# ---- one run -----------------------------------------------------------------------------------
# run EXPECT OUT ARGS...: EXPECT is 0, 1, 2, "err" (1 or 2) or "any"; OUT is the output file the
# run may write ("" for none). KEEP=first checks that the first data row starts at (0, 0).
run() {
    local expect=$1 out=$2; shift 2
    runs=$((runs + 1))
    [ -n "$out" ] && [ "$out" != - ] && [ -f "$out" ] && rm -f "$out"
    timeout 60 "$cagd" "$@" > "$dir/stdout" 2> "$dir/stderr" < "${STDIN:-/dev/null}"
    local code=$?
    local what="cagd $*"
    if [ "$code" -eq 124 ]; then fail "hang (60 s): $what"; return; fi
    if [ "$code" -gt 2 ]; then fail "exit $code (crash): $what: $(head -c 300 "$dir/stderr")"; return; fi
    case $expect in
        err) [ "$code" -ne 0 ] || fail "expected an error, got exit 0: $what" ;;
        any) ;;
        *) [ "$code" -eq "$expect" ] || fail "expected exit $expect, got $code: $what: $(head -c 300 "$dir/stderr")" ;;
    esac
    if [ "$code" -ne 0 ]; then
        [ "$(wc -l < "$dir/stderr")" -eq 1 ] || fail "exit $code with $(wc -l < "$dir/stderr") stderr lines: $what: $(head -c 300 "$dir/stderr")"
        [ ! -s "$dir/stdout" ] || fail "exit $code but stdout has output: $what"
        [ -z "$out" ] || [ "$out" = - ] || [ ! -e "$out" ] || [ -d "$out" ] || [ -c "$out" ] || fail "exit $code but $out exists: $what"
    else
        for f in "$dir/stdout" ${out:+"$out"}; do
            [ -f "$f" ] || continue
            [ "${NONFINITE_OK:-}" = 1 ] && continue
            if grep -qiE '(^|[,"])[-+]?(nan|inf)' "$f"; then fail "exit 0 with nan/inf in $(basename "$f"): $what"; fi
        done
        if [ "${KEEP:-}" = first ] && [ -n "$out" ] && [ -f "$out" ]; then
            awk -F, 'NR == 2 { exit !($2 == 0 && $3 == 0) }' "$out" || fail "first point lost or altered: $what: $(sed -n 2p "$out")"
        fi
    fi
    if ls -A "$dir" "$dir/adir" 2> /dev/null | grep -q '\.cagd-'; then fail "temporary file left behind: $what"; rm -f "$dir"/.*.cagd-* "$dir"/adir/.*.cagd-*; fi
}

o="$dir/out.csv"
methods=$("$cagd" interpolate --list-methods | awk '/^[a-z0-9]/ { print $1 }')

# ---- interpolate and analyze --in: every method × every input class ----------------------------
for m in $methods; do
    for c in empty header_only garbage typo_first spaces columns nan inf; do
        run 2 "$o" interpolate --method "$m" --in "$dir/$c.csv" --out "$o"
    done
    run 2 "$o" interpolate --method "$m" --in "$dir/long_line.csv" --out "$o"
    run 2 "$o" interpolate --method "$m" --in "$dir/missing.csv" --out "$o"
    run 2 "$o" interpolate --method "$m" --in "$dir/one_point.csv" --out "$o"
    run 2 "$o" interpolate --method "$m" --in "$dir/repeated.csv" --out "$o"
    run err "$o" interpolate --method "$m" --in "$dir/huge.csv" --out "$o"
    run err "$o" interpolate --method "$m" --in "$dir/tiny.csv" --out "$o"
    for c in good crlf bom bom_header comments; do
        KEEP=first run 0 "$o" interpolate --method "$m" --in "$dir/$c.csv" --out "$o" --samples 3
    done
    run 2 "" interpolate --method "$m" --in "$dir/good.csv" --out "$dir/adir"
    run 2 "" interpolate --method "$m" --in "$dir/good.csv" --out /nonexistent-dir/out.csv
    run 0 - interpolate --method "$m" --in "$dir/good.csv" --out - --samples 2
    run 0 /dev/null interpolate --method "$m" --in "$dir/good.csv" --out /dev/null
    run 2 "$o" interpolate --method "$m" --in "$dir/good.csv" --out "$o" --samples 0
    run 2 "$o" interpolate --method "$m" --in "$dir/good.csv" --out "$o" --samples 1000000000
    run 2 "$o" interpolate --method "$m" --in "$dir/good.csv" --out "$o" --samples -5
    run 0 "" analyze --in "$dir/good.csv" --method "$m"
    run err "" analyze --in "$dir/huge.csv" --method "$m"
    run 2 "" analyze --in "$dir/nan.csv" --method "$m"
done
[ -c /dev/null ] || fail "/dev/null is no longer a device"
for bad in "--m -1" "--m 1e9" "--m 0.5" "--m nan" "--m 100000" "--end clamped" "--scale huge" "--optimize fast" "--degree 9" "--knots {0" "--spans line" "--table $dir/good.csv"; do
    for m in s-spline hosaka curvature-profile pseudo-spline; do
        # shellcheck disable=SC2086
        run 2 "$o" interpolate --method "$m" $bad --in "$dir/good.csv" --out "$o"
    done
done
run 0 "$o" interpolate --method s-spline --m 10 --in "$dir/good.csv" --out "$o"
run 0 "$o" interpolate --method hosaka --in "$dir/space.csv" --out "$o"
STDIN="$dir/good.csv" run 0 "$o" interpolate --method cubic-b --in - --out "$o"

# ---- analyze CURVE.csv -------------------------------------------------------------------------
run 0 "" analyze "$dir/curve.csv"
run 0 "" analyze "$dir/curve3d.csv"
STDIN="$dir/curve.csv" run 0 "" analyze -
for c in curve_nan curve_noheader curve_zero_speed empty header_only garbage long_line missing; do run 2 "" analyze "$dir/$c.csv"; done
run 2 "" analyze "$dir/adir"

# ---- compare -----------------------------------------------------------------------------------
for c in empty header_only garbage typo_first spaces columns nan inf one_point repeated long_line missing; do
    run 2 "" compare --in "$dir/$c.csv" --out "$dir/cmp_$c" --no-plot
    [ ! -e "$dir/cmp_$c" ] || fail "compare on $c left $dir/cmp_$c"
done
run 0 "" compare --in "$dir/good.csv" --out "$dir/cmp_good" --no-plot --methods cubic-b,hosaka,s-spline-m2
run 0 "" compare --in "$dir/space.csv" --out "$dir/cmp_space" --no-plot --methods cubic-b,hosaka,pseudo-spline-approx,curvature-profile
for c in huge tiny; do run any "" compare --in "$dir/$c.csv" --out "$dir/cmp_$c" --no-plot --methods cubic-b,hermite-a; done
echo x > "$o"
run 2 "" compare --in "$dir/good.csv" --out "$o" --no-plot   # a file where a directory is expected
run 2 "" compare --in "$dir/good.csv" --out "$dir/cmp_x" --methods cubic-z --no-plot

# ---- surfaces and smoothing ----------------------------------------------------------------------
for c in grid grid_nan grid_columns grid_huge empty garbage good missing long_line; do
    case $c in grid) e=0 ;; grid_huge) e=err ;; *) e=2 ;; esac
    run $e "$o" surface --kind tensor --in "$dir/$c.csv" --samples 4 --out "$o"
    for sm in net plate plate-boundary approx1 approx2; do
        run $e "$o" smooth-surface --method "$sm" --lambda 0.1 --in "$dir/$c.csv" --out "$o"
    done
done
for bad in "--samples 0" "--samples 100000" "--samples -1"; do
    # shellcheck disable=SC2086
    run 2 "$o" surface --kind tensor --in "$dir/grid.csv" $bad --out "$o"
done
for bad in "--lambda -1" "--lambda nan" "--lambda 1e400" "--energy 54" "--poisson 0.6" "--m 0" "--samples 100000"; do
    # shellcheck disable=SC2086
    run 2 "$o" smooth-surface --method plate-boundary $bad --in "$dir/grid.csv" --out "$o"
done
run 2 "$o" surface --kind coons --bottom "$dir/good.csv" --out "$o"
run 2 "$o" surface --kind boundary --lower "$dir/nan.csv" --upper "$dir/good.csv" --out "$o"
for c in good crlf bom comments nan inf huge tiny empty garbage columns repeated; do
    case $c in good | crlf | bom | comments) e=0 ;; huge | tiny) e=any ;; *) e=2 ;; esac
    run $e "$o" smooth --lambda 0.1 --in "$dir/$c.csv" --out "$o"
    run $e "$o" smooth --lambda 0.1 --form parametric --in "$dir/$c.csv" --out "$o"
done
for bad in "--lambda -1" "--lambda nan" "--lambda inf" "--samples 0" "--samples 100000000"; do
    # shellcheck disable=SC2086
    run 2 "$o" smooth $bad --in "$dir/good.csv" --out "$o"
done
run 2 "$o" smooth --lambda-file "$dir/nan.csv" --in "$dir/good.csv" --out "$o"
run 2 "$o" smooth --lambda 1 --lambda-file "$dir/good.csv" --in "$dir/good.csv" --out "$o"

# ---- pseudo-energy, aesthetic curves and surfaces --------------------------------------------------
run 0 "" energy --theta0 30 --theta1 -45 --deg
for bad in "--theta0 4 --theta1 0" "--theta0 nan --theta1 0" "--theta0 inf --theta1 0" "--theta0 1e308 --theta1 0" "--theta0 180 --theta1 0 --deg" "--theta0 0 --theta1 0"; do
    # shellcheck disable=SC2086
    run err "" energy $bad
done
NONFINITE_OK=1 run 0 "$o" energy-table --grid 4 --out "$o"
NONFINITE_OK=1 run 0 - energy-table --grid 3 --out -
for bad in "--grid 1" "--grid 0" "--grid -3" "--grid 1000000" "--grid 4 --threads 0" "--grid 4 --placement uniform" "--grid 4 --method slow"; do
    # shellcheck disable=SC2086
    run 2 "$o" energy-table $bad --out "$o"
done
run 2 "" energy-table --grid 4 --out "$dir/adir"
run 0 "$o" lac --alpha -0.5 --degree 20 --out "$o"
run 0 "$o" lac --alpha -0.5 --degree 99 --lcg --out "$o"
for bad in "--degree 2147483647" "--degree 0" "--degree -1" "--degree 100000 --samples 1000000" "--degree 2 --lcg" "--degree 10 --alpha nan" "--degree 10 --alpha 0.5" "--degree 10 --length 0" "--degree 10 --length -1" "--degree 10 --samples 1" "--degree 10 --lcg --fit-from 0.9 --fit-to 0.1"; do
    # shellcheck disable=SC2086
    run 2 "$o" lac --alpha -0.5 $bad --out "$o"
done
run 0 "$o" lac3d --alpha 1.5 --beta 1.2 --degree 24 --out "$o"
for bad in "--degree 2147483647" "--degree 2" "--degree 100000 --samples 1000000" "--degree 24 --alpha 1" "--degree 24 --beta nan" "--degree 24 --length 0" "--degree 24 --start -1" "--degree 24 --composition other"; do
    # shellcheck disable=SC2086
    run 2 "$o" lac3d --alpha 1.5 --beta 1.2 $bad --out "$o"
done
run 0 "$o" typical-surface --n 8 --alpha-u -0.5 --alpha-v -0.6 --angle-deg 1 --grid 11 --out "$o"
for bad in "--n 100000" "--n 2" "--n 0" "--grid 100000" "--grid 1" "--n 400 --grid 3000" "--angle-deg nan" "--alpha-u 0.5" "--length 0"; do
    # shellcheck disable=SC2086
    run 2 "$o" typical-surface --n 8 --alpha-u -0.5 --alpha-v -0.6 --angle-deg 1 $bad --out "$o"
done
run 0 "" benchmark --out "$dir/bench_good" --sizes 6,12 --families circle,helix --methods cubic-b,spiro --random-sets 20 --timing-out "$dir/bench_seconds.csv"
[ -s "$dir/bench_good/random_sets.csv" ] && [ -s "$dir/bench_seconds.csv" ] || fail "benchmark wrote no random_sets.csv or no --timing-out file"
for bad in "--sizes 2" "--sizes 6,x" "--sizes 100001" "--sizes 6,6" "--sizes 12,6" "--families square" "--methods cubic-z" "--threads -1" "--random-sets -1" "--random-sizes 8,2" \
    "--scatter-max-points -1" "--part 0/2" "--part 3/2" "--part 1/5000" "--part x" "--part 1/2 --timing-out $dir/bench_t.csv" "--merge $dir/no_such_part" \
    "--merge $dir/good.csv" "--part 1/2 --merge $dir/good.csv"; do
    # shellcheck disable=SC2086
    run 2 "" benchmark --out "$dir/bench_bad" $bad
    [ ! -e "$dir/bench_bad" ] || fail "benchmark $bad left $dir/bench_bad"
done
: > "$dir/bench_file"
run 2 "" benchmark --out "$dir/bench_file" --sizes 6 --families circle --methods cubic-b   # a file where a directory is expected
# peers: the real peers (those installed here; the others are skipped) on the real claims, and
# every bad input refused before a peer runs, leaving no --out.
src=$(cd "$(dirname "$0")/.." && pwd)
run 0 "" peers --peers "$src/peers" --list-markdown
run 0 "" peers --peers "$src/peers" --identities "$src/reference/benchmark/peer_identities.csv" --classic "$src/reference/benchmark/classic_data.csv" --out "$dir/peers_good" --truth-sizes 6,12
[ -s "$dir/peers_good/peers.md" ] && [ -s "$dir/peers_good/peer_identities.csv" ] && [ -s "$dir/peers_good/peer_truth_runs.csv" ] ||
    fail "peers wrote no peers.md, peer_identities.csv or peer_truth_runs.csv"
run 2 "" peers --peers "$src/peers" --identities "$src/reference/benchmark/peer_identities.csv" --classic "$src/reference/benchmark/classic_data.csv" --out "$dir/peers_bad" --truth-sizes 12,6
printf 'left,right,closed,ends,expected,reason\nnobody:x,cagd:cubic-b,0,0,identical,r\n' > "$dir/claims_unknown.csv"
printf 'left,right,closed,ends,expected,reason\nd3-shape:natural,cagd:cubic-a,0,x,identical,r\n' > "$dir/claims_ends.csv"
claims=$src/reference/benchmark/peer_identities.csv classic=$src/reference/benchmark/classic_data.csv
for bad in "$dir/adir $claims $classic" "$src/peers $dir/good.csv $classic" "$src/peers $dir/claims_unknown.csv $classic" \
    "$src/peers $dir/claims_ends.csv $classic" "$src/peers $dir/no_such_file $classic" "$src/peers $claims $dir/good.csv"; do
    read -r peers identities data <<< "$bad"
    run 2 "" peers --peers "$peers" --identities "$identities" --classic "$data" --out "$dir/peers_bad"
    [ ! -e "$dir/peers_bad" ] || fail "peers $bad left $dir/peers_bad"
done
run 2 "" peers --peers "$src/peers" --identities "$src/reference/benchmark/peer_identities.csv"
# scorecard: a few methods and a peer (skipped where it is not installed) on a few polygons, and
# bad input refused before any work, leaving no --out.
run 0 "" scorecard --out "$dir/score_good" --polygons 20 --only cubic-b,s-spline-m1,d3-shape:natural --peers "$src/peers" --classic "$classic"
for f in scorecard.md scorecard.csv scorecard_classic.csv scorecard_locality.dat; do
    [ -s "$dir/score_good/$f" ] || fail "scorecard wrote no $f"
done
grep -q '^| s-spline-m1 |' "$dir/score_good/scorecard.md" || fail "scorecard.md has no row for s-spline-m1"
for bad in "--polygons 0" "--polygons 1000001" "--only nosuch" "--threads -1" "--peers $dir/adir" "--classic $dir/no_such_file"; do
    # shellcheck disable=SC2086
    run 2 "" scorecard --out "$dir/score_bad" --only cubic-b $bad
    [ ! -e "$dir/score_bad" ] || fail "scorecard $bad left $dir/score_bad"
done
run 2 "" scorecard --polygons 5
# compare with peers: a method and a peer (its row and --export file where the peer is installed
# here), and a peer's name refused without --peers or where the manifest lacks it.
run 0 "" compare --in "$dir/good.csv" --out "$dir/cmp_peers" --no-plot --methods cubic-b,d3-shape:natural --peers "$src/peers" --export json
grep -q '^cubic-b,ok,' "$dir/cmp_peers/measures.csv" || fail "compare --peers has no cubic-b row"
if "$src/peers/run" d3-shape --version > /dev/null 2>&1; then
    grep -q '^d3-shape:natural,ok,' "$dir/cmp_peers/measures.csv" || fail "compare --peers has no d3-shape:natural row"
    grep -q '"name":"d3-shape:natural"' "$dir/cmp_peers/curve_d3-shape_natural.json" ||
        fail "compare --peers --export json wrote no d3-shape:natural curve"
fi
for bad in "--methods d3-shape:natural" "--methods nobody:x --peers $src/peers" "--peers $dir/adir"; do
    # shellcheck disable=SC2086
    run 2 "" compare --in "$dir/good.csv" --out "$dir/cmp_peers_bad" --no-plot $bad
    [ ! -e "$dir/cmp_peers_bad" ] || fail "compare $bad left $dir/cmp_peers_bad"
done
run 0 "" monotone --in "$dir/good.csv"
for c in empty garbage nan inf columns space one_point missing; do run 2 "" monotone --in "$dir/$c.csv"; done
run 2 "" monotone --in "$dir/good.csv" --knots other

# ---- usage --------------------------------------------------------------------------------------
run 2 "" nosuchcommand
run 2 ""
run 0 "" --version
run 2 "" interpolate --in "$dir/good.csv"

echo "cli matrix: $runs runs, $fails failed"
[ "$fails" -eq 0 ]
