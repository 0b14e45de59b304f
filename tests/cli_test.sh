#!/usr/bin/env bash
# The cagd command: a good run writes a curve through the points; each kind of bad input
# gives exit code 2 and exactly one line on stderr.
set -u
cagd=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fails=0
printf 'x,y\n0,0\n1,1\n2,0\n3,1\n4,0\n' > "$dir/pts.csv"
# A 5 x 5 grid of heights (equally spaced: approximation 1 needs 5 x 5 windows).
for i in 0 1 2 3 4; do for j in 0 1 2 3 4; do echo "$i,$j,$(( (i*i + j) % 3 ))"; done; done > "$dir/grid5.csv"

if ! "$cagd" interpolate --method s-spline --m 2 --in "$dir/pts.csv" --out "$dir/c.csv" --samples 4; then
  echo "FAIL: good interpolate exited non-zero"; fails=$((fails+1))
fi
# t = 2 is the 9th sample (4 per span; the s-spline's parameter is uniform): the curve passes through (2, 0).
if ! awk -F, 'NR==10 { exit !($1==2 && ($2-2)^2 < 1e-20 && $3^2 < 1e-20) }' "$dir/c.csv"; then
  echo "FAIL: curve does not pass through p_2 = (2,0) at u = 2"; sed -n 10p "$dir/c.csv"; fails=$((fails+1))
fi
# The method's own parameter: cubic-b's t is chord length, so the last sample is at the polygon's
# length 4 sqrt 2; --parameter span gives u = 0..4 with the derivatives scaled by the chord.
"$cagd" interpolate --method cubic-b --in "$dir/pts.csv" --out "$dir/cb.csv" --samples 2 || { echo "FAIL: cubic-b"; fails=$((fails+1)); }
"$cagd" interpolate --method cubic-b --parameter span --in "$dir/pts.csv" --out "$dir/cbu.csv" --samples 2 || { echo "FAIL: cubic-b span"; fails=$((fails+1)); }
head -1 "$dir/cb.csv" | grep -q '^t,x,y,dx,dy,ddx,ddy$' && head -1 "$dir/cbu.csv" | grep -q '^u,x,y,dx,dy,ddx,ddy$' || { echo "FAIL: parameter columns"; fails=$((fails+1)); }
awk -F, 'END { exit !(($1 - 4 * sqrt(2))^2 < 1e-24) }' "$dir/cb.csv" || { echo "FAIL: cubic-b's t does not end at the chord length: $(tail -1 "$dir/cb.csv")"; fails=$((fails+1)); }
paste -d, "$dir/cb.csv" "$dir/cbu.csv" | awk -F, 'NR > 1 { if (($2 - $9)^2 > 1e-24 || ($4 * sqrt(2) - $11)^2 > 1e-20) bad = 1 } END { exit bad }' \
  || { echo "FAIL: the span parameter's derivative is not dt/du = chord times the method's"; fails=$((fails+1)); }
"$cagd" analyze "$dir/c.csv" > "$dir/a.txt" 2>/dev/null || { echo "FAIL: analyze"; fails=$((fails+1)); }
grep -q '^polyline_length,' "$dir/a.txt" || { echo "FAIL: analyze prints no length"; fails=$((fails+1)); }
"$cagd" interpolate --help | grep -q -- '--m-vector' || { echo "FAIL: --help lacks --m-vector"; fails=$((fails+1)); }

expect_bad() {   # description, file content, extra args...
  local what=$1 content=$2; shift 2
  printf '%b' "$content" > "$dir/bad.csv"
  "$cagd" "$@" > /dev/null 2> "$dir/err.txt"
  local code=$?
  local lines
  lines=$(wc -l < "$dir/err.txt")
  if [ "$code" -ne 2 ] || [ "$lines" -ne 1 ]; then
    echo "FAIL: $what: exit $code, $lines stderr lines:"; cat "$dir/err.txt"; fails=$((fails+1))
  fi
}
expect_bad "one point"            '0,0\n'              interpolate --m 1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "nan coordinate"       '0,0\n1,nan\n2,0\n'  interpolate --m 1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "repeated points"      '0,0\n1,1\n1,1\n'    interpolate --m 1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "negative m"           '0,0\n1,1\n2,0\n'    interpolate --m -1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "m-vector length"      '0,0\n1,1\n2,0\n'    interpolate --m-vector 1,2,3 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "unreadable line"      '0,0\n1,x\n2,0\n'    interpolate --m 1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "missing file"         ''                   interpolate --m 1 --in "$dir/none.csv" --out "$dir/o.csv"
expect_bad "unknown method"       '0,0\n1,1\n'         interpolate --method foo --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "angle out of range"   ''                   energy --theta0 4 --theta1 0
expect_bad "angle in degrees"     ''                   energy --theta0 200 --theta1 0 --deg
expect_bad "non-finite angle"     ''                   energy --theta0 nan --theta1 0
expect_bad "undefined node"       ''                   energy --theta0 180 --theta1 0 --deg
expect_bad "grid below 2"         ''                   energy-table --grid 1 --out "$dir/t.txt"
expect_bad "unknown placement"    ''                   energy-table --grid 4 --placement uniform --out "$dir/t.txt"

# energy: one CSV row with header; symmetric inputs give J(θ0, θ1) = J(θ1, θ0).
"$cagd" energy --theta0 30 --theta1 -45 --deg > "$dir/e1.csv" || { echo "FAIL: energy"; fails=$((fails+1)); }
"$cagd" energy --theta0 -45 --theta1 30 --deg > "$dir/e2.csv" || { echo "FAIL: energy swapped"; fails=$((fails+1)); }
head -1 "$dir/e1.csv" | grep -q '^theta0,theta1,J,r0,r1,L,S,type$' || { echo "FAIL: energy header"; fails=$((fails+1)); }
j1=$(awk -F, 'NR==2 {print $3}' "$dir/e1.csv"); j2=$(awk -F, 'NR==2 {print $3}' "$dir/e2.csv")
awk -v a="$j1" -v b="$j2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d < 1e-10 * a) }' || { echo "FAIL: J not symmetric: $j1 vs $j2"; fails=$((fails+1)); }
"$cagd" energy-table --grid 6 --out "$dir/t6.txt" 2> "$dir/progress.txt" || { echo "FAIL: energy-table"; fails=$((fails+1)); }
[ "$(grep -c '^[0-9]' "$dir/t6.txt")" -eq 36 ] || { echo "FAIL: energy-table rows"; fails=$((fails+1)); }
[ ! -s "$dir/progress.txt" ] || { echo "FAIL: energy-table printed progress to a stderr that is not a terminal"; fails=$((fails+1)); }
if command -v script > /dev/null; then   # on a terminal (script gives it one): progress, unless --quiet
  script -qec "$cagd energy-table --grid 6 --out $dir/t7.txt" /dev/null | grep -q 'nodes' || { echo "FAIL: no progress on a terminal"; fails=$((fails+1)); }
  script -qec "$cagd --quiet energy-table --grid 6 --out $dir/t7.txt" /dev/null | grep -q 'nodes' && { echo "FAIL: progress despite --quiet"; fails=$((fails+1)); }
fi
expect_bad "tangent without vec"  '0,0\n1,1\n2,0\n'    interpolate --end tangent --in "$dir/bad.csv" --out "$dir/o.csv"

# pseudo_energy section 4.2 methods: the knot data of Table 3 through every method.
printf 'x,y\n0,0\n2,-0.1\n1,-0.1\n3,0\n' > "$dir/knot.csv"
for m in pseudo-spline cubic-a cubic-b hermite-a hermite-b; do
  "$cagd" interpolate --method "$m" --parameter span --in "$dir/knot.csv" --out "$dir/k.csv" --samples 4 || { echo "FAIL: interpolate $m"; fails=$((fails+1)); }
  # u = 2 (the span index) is the 9th sample: the curve passes through P_2 = (1, -0.1).
  awk -F, 'NR==10 { exit !($1==2 && ($2-1)^2 < 1e-20 && ($3+0.1)^2 < 1e-20) }' "$dir/k.csv" || { echo "FAIL: $m misses P_2"; fails=$((fails+1)); }
done
"$cagd" interpolate --method pseudo-spline --optimize approx --table "$dir/t6.txt" --in "$dir/knot.csv" --out "$dir/k.csv" \
  || { echo "FAIL: pseudo-spline with a table file"; fails=$((fails+1)); }
"$cagd" analyze --in "$dir/knot.csv" --method pseudo-spline > "$dir/an.csv" 2>/dev/null || { echo "FAIL: analyze --in"; fails=$((fails+1)); }
for q in length_integrated area_integrated length_from_tables area_from_tables; do
  grep -q "^$q," "$dir/an.csv" || { echo "FAIL: analyze --in prints no $q"; fails=$((fails+1)); }
done
"$cagd" analyze --in "$dir/knot.csv" --method hermite-a 2>/dev/null | grep -q '^length_from_tables' && { echo "FAIL: tables for hermite-a"; fails=$((fails+1)); }
expect_bad "hairpin (turn of pi)"  '0,0\n2,0\n1,0\n3,1\n' interpolate --method pseudo-spline --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "pseudo-spline 1 point" '0,0\n'               interpolate --method pseudo-spline --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "hermite-b 2 points"    '0,0\n1,1\n'          interpolate --method hermite-b --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "closed with 2 points"  '0,0\n1,1\n'          interpolate --method cubic-b --closed --in "$dir/bad.csv" --out "$dir/o.csv"
# Output formats (docs/export.md): an unknown extension and a planar format for 3-D points are bad
# input, refused before anything is written, with a message naming the extension or the format.
expect_bad "unknown extension"     '0,0\n1,1\n2,0\n'    interpolate --in "$dir/bad.csv" --out "$dir/o.txt"
grep -q "unknown extension '.txt'" "$dir/err.txt" && [ ! -e "$dir/o.txt" ] || { echo "FAIL: unknown extension: message or a file written"; cat "$dir/err.txt"; fails=$((fails+1)); }
expect_bad "svg of 3-D points"     '0,0,0\n1,1,0\n2,0,1\n' interpolate --method cubic-b --in "$dir/bad.csv" --out "$dir/o.svg"
grep -q "svg is planar" "$dir/err.txt" && [ ! -e "$dir/o.svg" ] || { echo "FAIL: svg of 3-D points: message or a file written"; cat "$dir/err.txt"; fails=$((fails+1)); }
expect_bad "unknown --format"      '0,0\n1,1\n2,0\n'    interpolate --in "$dir/bad.csv" --out "$dir/o.csv" --format pdf
expect_bad "compare --export pdf"  '0,0\n1,1\n2,0\n'    compare --in "$dir/bad.csv" --out "$dir/cmp" --export pdf
# --format wins over the extension; --arc-length-samples gives equal chords of the curve's length.
"$cagd" interpolate --method cubic-b --in "$dir/pts.csv" --out "$dir/c.data" --format json || { echo "FAIL: --format json"; fails=$((fails+1)); }
grep -q '"format": "cagd-curve"' "$dir/c.data" || { echo "FAIL: --format json wrote no curve document"; fails=$((fails+1)); }
"$cagd" interpolate --method cubic-b --in "$dir/pts.csv" --out "$dir/al.csv" --arc-length-samples 5 || { echo "FAIL: --arc-length-samples"; fails=$((fails+1)); }
[ "$(wc -l < "$dir/al.csv")" -eq 6 ] || { echo "FAIL: --arc-length-samples 5 wrote $(wc -l < "$dir/al.csv") lines"; fails=$((fails+1)); }
expect_bad "unknown optimisation"  '0,0\n1,1\n2,0\n'    interpolate --method pseudo-spline --optimize fast --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "foreign table file"    '0,0\n1,1\n2,0\n'    interpolate --method pseudo-spline --table "$dir/bad.csv" --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "analyze --in, no method" '0,0\n1,1\n2,0\n'  analyze --in "$dir/bad.csv"

# hosaka eq (20): a space curve through 3-D points passes through them; bad ends are errors.
printf 'x,y,z\n0,0,0\n1,1,0\n2,1,1\n3,0,2\n' > "$dir/space.csv"
"$cagd" interpolate --method hosaka --parameter span --in "$dir/space.csv" --out "$dir/h.csv" --samples 4 || { echo "FAIL: hosaka"; fails=$((fails+1)); }
awk -F, 'NR==10 { exit !($1==2 && ($2-2)^2 < 1e-20 && ($3-1)^2 < 1e-20 && ($4-1)^2 < 1e-20) }' "$dir/h.csv" || { echo "FAIL: hosaka misses P_2"; fails=$((fails+1)); }
"$cagd" interpolate --method hosaka --scale unit --end tangent --start-tangent 1,0,0 --end-tangent 0,0,1 --in "$dir/space.csv" --out "$dir/h.csv" \
  || { echo "FAIL: hosaka tangent ends"; fails=$((fails+1)); }
"$cagd" interpolate --method hosaka --m 2 --parameter span --in "$dir/space.csv" --out "$dir/h2.csv" --samples 4 || { echo "FAIL: hosaka --m 2"; fails=$((fails+1)); }
awk -F, 'NR==10 { exit !($1==2 && ($2-2)^2 < 1e-20 && ($3-1)^2 < 1e-20 && ($4-1)^2 < 1e-20) }' "$dir/h2.csv" || { echo "FAIL: hosaka --m 2 misses P_2"; fails=$((fails+1)); }
expect_bad "hosaka m 0"            '0,0\n1,1\n2,0\n'    interpolate --method hosaka --m 0 --in "$dir/bad.csv" --out "$dir/o.csv"
for m in 1 2; do
  "$cagd" interpolate --method hosaka --m $m --end tangent --start-tangent 1,0,0 --end-tangent 0,0,1 --in "$dir/space.csv" --out "$dir/h3.csv" --samples 4 \
    || { echo "FAIL: hosaka --m $m tangent ends"; fails=$((fails+1)); }
  # the first row's derivative columns (dx, dy, dz) are the given start tangent, in the chord-length t
  awk -F, 'NR==2 { exit !(($5-1)^2 < 1e-20 && $6^2 < 1e-20 && $7^2 < 1e-20) }' "$dir/h3.csv" || { echo "FAIL: hosaka --m $m start tangent"; sed -n 2p "$dir/h3.csv"; fails=$((fails+1)); }
  # and in the span index u they are L_0 = |P_1 − P_0| = sqrt(2) times it
  "$cagd" interpolate --method hosaka --m $m --end tangent --start-tangent 1,0,0 --end-tangent 0,0,1 --parameter span --in "$dir/space.csv" --out "$dir/h4.csv" --samples 4
  awk -F, 'NR==2 { exit !(($5-sqrt(2))^2 < 1e-20 && $6^2 < 1e-20 && $7^2 < 1e-20) }' "$dir/h4.csv" || { echo "FAIL: hosaka --m $m start tangent in u"; sed -n 2p "$dir/h4.csv"; fails=$((fails+1)); }
done
expect_bad "hosaka m 2 tangent dim" '0,0\n1,1\n2,0\n'    interpolate --method hosaka --m 2 --end tangent --start-tangent 1,0,0 --end-tangent 1,0 --in "$dir/bad.csv" --out "$dir/o.csv"
# hosaka section 4: cagd surface (tensor over a grid of heights, Coons from four edges, boundary synthesis).
printf 'x,y,z\n0,0,0\n1,0,1\n2,0,0\n0,1,1\n1,1,2\n2,1,1\n' > "$dir/grid.csv"
"$cagd" surface --kind tensor --in "$dir/grid.csv" --samples 4 --out "$dir/s1.csv" || { echo "FAIL: surface tensor"; fails=$((fails+1)); }
awk -F, 'NR>1 && $1==1 && $2==1 { found=1; if (($3-2)^2 > 1e-20) bad=1 } END { exit !(found && !bad) }' "$dir/s1.csv" || { echo "FAIL: tensor surface misses (1,1,2)"; fails=$((fails+1)); }
printf '0,0,0\n0.5,0.1,0.2\n1,0,0\n' > "$dir/eb.csv"; printf '0,0,0\n-0.1,0.5,0.1\n0,1,0.3\n' > "$dir/el.csv"
printf '0,1,0.3\n0.5,1.1,0.5\n1,1,0.2\n' > "$dir/et.csv"; printf '1,0,0\n1.1,0.5,0.1\n1,1,0.2\n' > "$dir/er.csv"
"$cagd" surface --kind coons --bottom "$dir/eb.csv" --left "$dir/el.csv" --top "$dir/et.csv" --right "$dir/er.csv" --samples 2 --out "$dir/s2.csv" \
  || { echo "FAIL: surface coons"; fails=$((fails+1)); }
awk -F, 'NR>1 && $1==0.5 && $2==0 { found=1; if (($3-0.5)^2 + ($4-0.1)^2 + ($5-0.2)^2 > 1e-20) bad=1 } END { exit !(found && !bad) }' "$dir/s2.csv" \
  || { echo "FAIL: coons surface misses its bottom edge"; fails=$((fails+1)); }
printf 'x,y,z\n0,0,0\n1,0.2,0.1\n2,0,0.3\n' > "$dir/L0.csv"; printf 'x,y,z\n0,1,0.5\n1,1.3,0.4\n2,1.1,0.6\n' > "$dir/L1.csv"
"$cagd" surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/L1.csv" --m 2 --lower-slope 0.5 --samples 4 --out "$dir/s3.csv" \
  || { echo "FAIL: surface boundary"; fails=$((fails+1)); }
awk -F, 'NR>1 && $1==1 && $2==1.3 { found=1; if (($3-0.4)^2 > 1e-20) bad=1 } END { exit !(found && !bad) }' "$dir/s3.csv" \
  || { echo "FAIL: boundary surface misses L1"; fails=$((fails+1)); }
expect_bad "surface crossing"       'x,y,z\n0,1,0.5\n1,-0.3,0.4\n2,1.1,0.6\n' surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "surface x ranges"       'x,y,z\n0,1,0.5\n1,1.3,0.4\n2.5,1.1,0.6\n' surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "surface x not rising"   'x,y,z\n0,1,0.5\n2,1.3,0.4\n1,1.1,0.6\n' surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "surface m 3"            ''                   surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/L1.csv" --m 3 --out "$dir/o.csv"
expect_bad "surface not a grid"     'x,y,z\n0,0,0\n1,0,1\n0,1,1\n' surface --kind tensor --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "coons open corners"     '0,1,0.9\n0.5,1.1,0.5\n1,1,0.2\n' surface --kind coons --bottom "$dir/eb.csv" --left "$dir/el.csv" --top "$dir/bad.csv" --right "$dir/er.csv" --out "$dir/o.csv"
expect_bad "coons missing edge"     ''                   surface --kind coons --bottom "$dir/eb.csv" --out "$dir/o.csv"
# Surfaces leave in csv, json and step only; the boundary surface (not polynomial) in csv only.
expect_bad "surface as svg"         ''                   surface --kind tensor --in "$dir/grid.csv" --out "$dir/o.svg"
expect_bad "surface as dxf format"  ''                   surface --kind tensor --in "$dir/grid.csv" --format dxf --out "$dir/o"
expect_bad "boundary surface json"  ''                   surface --kind boundary --lower "$dir/L0.csv" --upper "$dir/L1.csv" --out "$dir/o.json"
expect_bad "typical surface svg"    ''                   typical-surface --n 5 --alpha-u -1 --alpha-v -1 --angle-deg 10 --out "$dir/o.svg"
expect_bad "typical surface step 30" ''                  typical-surface --n 30 --alpha-u -1 --alpha-v -1 --angle-deg 10 --out "$dir/o.step"
[ ! -e "$dir/o.svg" ] && [ ! -e "$dir/o.json" ] && [ ! -e "$dir/o.step" ] || { echo "FAIL: a refused surface export left a file"; fails=$((fails+1)); }
"$cagd" surface --kind tensor --in "$dir/grid.csv" --out "$dir/s1.json" && grep -q '"format": "cagd-surface"' "$dir/s1.json" \
  || { echo "FAIL: surface tensor as json"; fails=$((fails+1)); }
expect_bad "hosaka bessel end"     '0,0\n1,1\n2,0\n'    interpolate --method hosaka --end bessel --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "hosaka zero chord"     '0,0\n1,1\n1,1\n'    interpolate --method hosaka --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "hosaka tangent dim"    '0,0\n1,1\n2,0\n'    interpolate --method hosaka --end tangent --start-tangent 1,0,0 --end-tangent 0,1,0 --in "$dir/bad.csv" --out "$dir/o.csv"

# hosaka sections 6-7: cagd smooth (elastic line) and cagd smooth-surface.
printf 'x,y\n0,1\n1,0.6\n2,0.1\n3,0.5\n4,0.9\n' > "$dir/noisy.csv"
"$cagd" smooth --lambda 0 --in "$dir/noisy.csv" --samples 2 --out "$dir/sm0.csv" || { echo "FAIL: smooth lambda 0"; fails=$((fails+1)); }
# lambda = 0 interpolates: the sample at x = 2 (row 6) is 0.1.
awk -F, 'NR==6 { exit !($1==2 && ($2-0.1)^2 < 1e-24) }' "$dir/sm0.csv" || { echo "FAIL: smooth lambda 0 misses (2, 0.1)"; sed -n 6p "$dir/sm0.csv"; fails=$((fails+1)); }
"$cagd" smooth --lambda 1 --in "$dir/noisy.csv" --samples 2 --out "$dir/sm1.csv" || { echo "FAIL: smooth lambda 1"; fails=$((fails+1)); }
awk -F, 'NR==6 { exit !($2 > 0.2) }' "$dir/sm1.csv" || { echo "FAIL: smooth lambda 1 does not lift the dip at x = 2"; fails=$((fails+1)); }
printf '1\n1\n0\n1\n1\n' > "$dir/lam.csv"
"$cagd" smooth --lambda-file "$dir/lam.csv" --in "$dir/noisy.csv" --samples 2 --out "$dir/sm2.csv" || { echo "FAIL: smooth lambda-file"; fails=$((fails+1)); }
awk -F, 'NR==6 { exit !(($2-0.1)^2 < 1e-24) }' "$dir/sm2.csv" || { echo "FAIL: lambda_2 = 0 must hold the point"; fails=$((fails+1)); }
"$cagd" smooth --lambda 0.1 --form parametric --in "$dir/pts.csv" --out "$dir/sm3.csv" || { echo "FAIL: smooth parametric"; fails=$((fails+1)); }
for m in net plate plate-boundary approx1 approx2; do
  "$cagd" smooth-surface --method $m --lambda 0.001 --in "$dir/grid5.csv" --out "$dir/ss_$m.csv" 2>/dev/null || { echo "FAIL: smooth-surface $m"; fails=$((fails+1)); }
done
expect_bad "smooth negative lambda"   'x,y\n0,0\n1,1\n2,0\n' smooth --lambda -0.1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth unsorted x"        'x,y\n0,0\n2,1\n1,0\n' smooth --lambda 0.1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth repeated x"        'x,y\n0,0\n1,1\n1,0\n' smooth --lambda 0.1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth nan"               'x,y\n0,0\n1,nan\n2,0\n' smooth --lambda 0.1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth both lambdas"      'x,y\n0,0\n1,1\n2,0\n' smooth --lambda 0.1 --lambda-file "$dir/lam.csv" --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth lambda count"      'x,y\n0,0\n1,1\n2,0\n' smooth --lambda-file "$dir/lam.csv" --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth-surface ragged"    'x,y,z\n0,0,0\n1,0,1\n0,1,1\n' smooth-surface --method net --lambda 0.1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "smooth-surface negative"  ''                   smooth-surface --method net --lambda -1 --in "$dir/grid5.csv" --out "$dir/o.csv"
expect_bad "smooth-surface plate 0"   ''                   smooth-surface --method plate --lambda 0 --in "$dir/grid5.csv" --out "$dir/o.csv"
expect_bad "smooth-surface nan"       'x,y,z\n0,0,0\n1,0,nan\n0,1,1\n1,1,1\n' smooth-surface --method net --lambda 0.1 --in "$dir/bad.csv" --out "$dir/o.csv"

# typical_curves: cagd lac and cagd monotone.
"$cagd" lac --alpha -0.5 --length 1 --degree 99 --lcg --out "$dir/lac.csv" > "$dir/lac.txt" || { echo "FAIL: lac"; fails=$((fails+1)); }
awk -F, '$1=="lcg_slope" { exit !($2 > -0.51 && $2 < -0.49) }' "$dir/lac.txt" || { echo "FAIL: lac LCG slope not near alpha"; cat "$dir/lac.txt"; fails=$((fails+1)); }
[ "$(grep -c '^control,' "$dir/lac.csv")" -eq 100 ] || { echo "FAIL: lac must write 100 control points"; fails=$((fails+1)); }
"$cagd" lac --alpha 1.5 --degree 20 --construction rotation --out "$dir/lac2.csv" || { echo "FAIL: lac rotation"; fails=$((fails+1)); }
# A unit-edge polygon with decreasing turns 30, 10, 5, 2 degrees: uniform knots, every segment monotone.
printf '0,0
1,0
1.8660254,0.5
2.5088130,1.2660444
3.0825706,2.0852596
3.6117634,2.9333054
' > "$dir/mono.csv"
"$cagd" monotone --knots uniform --in "$dir/mono.csv" > "$dir/mono.txt" || { echo "FAIL: monotone"; fails=$((fails+1)); }
grep -q '^whole_curve,' "$dir/mono.txt" || { echo "FAIL: monotone prints no whole-curve verdict"; fails=$((fails+1)); }
[ "$(grep -c '^[0-9]' "$dir/mono.txt")" -eq 3 ] || { echo "FAIL: monotone must report 3 uniform segments"; cat "$dir/mono.txt"; fails=$((fails+1)); }
expect_bad "lac degree 0"         ''  lac --alpha -0.5 --degree 0 --out "$dir/o.csv"
expect_bad "lac alpha 0.5 scale1" ''  lac --alpha 0.5 --degree 9 --out "$dir/o.csv"
expect_bad "lac alpha 1 rotation" ''  lac --alpha 1 --degree 9 --construction rotation --out "$dir/o.csv"
expect_bad "lac alpha nan"        ''  lac --alpha nan --degree 9 --out "$dir/o.csv"
expect_bad "lac negative length"  ''  lac --alpha -0.5 --length -1 --degree 9 --out "$dir/o.csv"
expect_bad "monotone zero edge"   '0,0\n1,0\n1,0\n2,1\n3,3\n' monotone --in "$dir/bad.csv"
expect_bad "monotone nan"         '0,0\n1,0\nnan,1\n2,1\n3,3\n' monotone --in "$dir/bad.csv"
expect_bad "monotone 3-D"         '0,0,0\n1,0,0\n2,1,0\n3,3,1\n' monotone --in "$dir/bad.csv"
expect_bad "monotone too few"     '0,0\n1,0\n2,1\n' monotone --in "$dir/bad.csv"

# typical_curves section 4–5: cagd lac3d and cagd typical-surface.
"$cagd" lac3d --alpha 1.5 --beta 1.2 --degree 99 --slopes --out "$dir/l3.csv" > "$dir/l3.txt" || { echo "FAIL: lac3d"; fails=$((fails+1)); }
awk -F, '$1=="lcg_slope" { exit !($2 > 1.44 && $2 < 1.5) }' "$dir/l3.txt" || { echo "FAIL: lac3d LCG slope not near alpha"; cat "$dir/l3.txt"; fails=$((fails+1)); }
awk -F, '$1=="ltg_slope" { exit !($2 > 1.05 && $2 < 1.2) }' "$dir/l3.txt" || { echo "FAIL: lac3d LTG slope not near beta"; cat "$dir/l3.txt"; fails=$((fails+1)); }
[ "$(grep -c '^control,' "$dir/l3.csv")" -eq 100 ] || { echo "FAIL: lac3d must write 100 control points"; fails=$((fails+1)); }
awk -F, '$1=="curve" && !($7 > 0) { bad=1 } END { exit bad }' "$dir/l3.csv" || { echo "FAIL: lac3d torsion must stay positive"; fails=$((fails+1)); }
"$cagd" typical-surface --n 25 --alpha-u -0.5 --alpha-v -0.6 --angle-deg 0.01 --grid 11 --out "$dir/ts.csv" --net-out "$dir/tsnet.csv" || { echo "FAIL: typical-surface"; fails=$((fails+1)); }
[ "$(tail -n +2 "$dir/ts.csv" | wc -l)" -eq 121 ] || { echo "FAIL: typical-surface must write 11x11 grid rows"; fails=$((fails+1)); }
[ "$(tail -n +2 "$dir/tsnet.csv" | wc -l)" -eq 625 ] || { echo "FAIL: typical-surface must write 25x25 control points"; fails=$((fails+1)); }
awk -F, 'NR > 1 && !($7 < 0) { bad=1 } END { exit bad }' "$dir/ts.csv" || { echo "FAIL: typical-surface mean curvature must be negative (normal S_u x S_v, dome bending to -z)"; fails=$((fails+1)); }
expect_bad "lac3d degree 2"          ''  lac3d --alpha 1.5 --beta 1.2 --degree 2 --out "$dir/o.csv"
expect_bad "lac3d beta 1"            ''  lac3d --alpha 1.5 --beta 1 --degree 9 --out "$dir/o.csv"
expect_bad "lac3d alpha 0.5 start 0" ''  lac3d --alpha 0.5 --beta 1.2 --start 0 --degree 9 --out "$dir/o.csv"
expect_bad "lac3d alpha nan"         ''  lac3d --alpha nan --beta 1.2 --degree 9 --out "$dir/o.csv"
expect_bad "lac3d negative start"    ''  lac3d --alpha 1.5 --beta 1.2 --start -1 --degree 9 --out "$dir/o.csv"
expect_bad "lac3d zero length"       ''  lac3d --alpha 1.5 --beta 1.2 --length 0 --degree 9 --out "$dir/o.csv"
expect_bad "surface n 2"             ''  typical-surface --n 2 --alpha-u -0.5 --alpha-v -0.6 --angle-deg 0 --out "$dir/o.csv"
expect_bad "surface alpha 0.5"       ''  typical-surface --n 5 --alpha-u 0.5 --alpha-v -0.6 --angle-deg 0 --out "$dir/o.csv"
expect_bad "surface angle inf"       ''  typical-surface --n 5 --alpha-u -0.5 --alpha-v -0.6 --angle-deg inf --out "$dir/o.csv"
expect_bad "surface zero edges"      ''  typical-surface --n 5 --alpha-u -0.5 --alpha-v -0.6 --angle-deg 0 --length 0 --out "$dir/o.csv"

# curvature_profile: cagd interpolate --method curvature-profile (Fig. 3's points, lines and arcs).
printf 'x,y\n9,1\n4,1\n1,3\n1,6\n2,7\n7,7\n10,3.5\n14,3.5\n14,6\n15,7\n17,4.2\n20,3\n22,3\n' > "$dir/f3.csv"
f3_spans=line,free,line,arc,line,free,arc,line,arc,free,free,line
"$cagd" interpolate --method curvature-profile --in "$dir/f3.csv" --spans "$f3_spans" --out "$dir/cp.csv" --report "$dir/cp.txt" || { echo "FAIL: curvature-profile"; fails=$((fails+1)); }
grep -q '^knot_difference_list,"{0, 5.0000, 0, 4.0181, 0, 3.0000, 0, 1.5708, 0, 5.0000, 0, 5.1227, 0, 6.2832,' "$dir/cp.txt" || { echo "FAIL: curvature-profile list"; cat "$dir/cp.txt"; fails=$((fails+1)); }
tail -1 "$dir/cp.csv" | awk -F, '{ exit !(($2-22)^2 + ($3-3)^2 < 1e-18) }' || { echo "FAIL: curvature-profile curve does not end at (22,3)"; tail -1 "$dir/cp.csv"; fails=$((fails+1)); }
# 150 points on y = sin x: a square system of 300 unknowns takes the sparse LU path.
awk 'BEGIN { print "x,y"; for (i = 0; i < 150; ++i) printf "%.17g,%.17g\n", 0.5 * i, sin(0.5 * i) }' > "$dir/sine.csv"
"$cagd" interpolate --method curvature-profile --in "$dir/sine.csv" --out "$dir/sine_c.csv" --report "$dir/sine.txt" || { echo "FAIL: curvature-profile on 150 points"; fails=$((fails+1)); }
grep -q '^rank,full (sparse LU)' "$dir/sine.txt" && grep -q '^unknowns,300$' "$dir/sine.txt" || { echo "FAIL: 150 points should take sparse LU steps"; grep equations "$dir/sine.txt"; fails=$((fails+1)); }
tail -1 "$dir/sine_c.csv" | awk -F, -v y="$(awk 'BEGIN { printf "%.17g", sin(74.5) }')" '{ exit !(($2-74.5)^2 + ($3-y)^2 < 1e-18) }' || { echo "FAIL: sparse-path curve does not end at the last point"; tail -1 "$dir/sine_c.csv"; fails=$((fails+1)); }
printf 'x,y\n0,0\n1,0\n2,1\n3,1\n' > "$dir/arc.csv"
"$cagd" interpolate --method curvature-profile --in "$dir/arc.csv" --spans line,arc,line --out "$dir/o.csv" > /dev/null 2> "$dir/err.txt"
code=$?
{ [ "$code" -eq 1 ] && [ "$(wc -l < "$dir/err.txt")" -eq 1 ] && grep -q inconsistent "$dir/err.txt"; } || { echo "FAIL: impossible arc must exit 1 with one line: exit $code"; cat "$dir/err.txt"; fails=$((fails+1)); }
expect_bad "cp one point"          '0,0\n'                  interpolate --method curvature-profile --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp coincident points"  '0,0\n1,1\n1,1\n2,0\n'   interpolate --method curvature-profile --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp span count"         '0,0\n1,1\n2,0\n'        interpolate --method curvature-profile --spans line,free,arc --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp unknown shape"      '0,0\n1,1\n2,0\n'        interpolate --method curvature-profile --spans line,circle --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp malformed list"     '0,0\n1,1\n2,0\n'        interpolate --method curvature-profile --knots "{0, A, {B, 0}" --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp list vs points"     '0,0\n1,1\n2,0\n'        interpolate --method curvature-profile --knots "{0, A, 0}" --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "cp degree, no list"    '0,0\n1,1\n2,0\n'        interpolate --method curvature-profile --degree 3 --in "$dir/bad.csv" --out "$dir/o.csv"

# cagd compare: one table row per method, the figure data, and bad input.
printf 'x,y\n0,0\n1,1\n2,0\n3,1\n4,0\n5,1\n' > "$dir/zig.csv"
if "$cagd" compare --in "$dir/zig.csv" --out "$dir/cmp" --no-plot > "$dir/cmp.md" 2> /dev/null; then
  rows=$(($(wc -l < "$dir/cmp/measures.csv") - 1))
  # one row per configuration of the registry: the backticked names of the table's last column
  configs=$("$cagd" interpolate --list-methods --markdown | awk -F'|' '/^\| `/ { n += gsub(/`/, "", $(NF-1)) / 2 } END { print n }')
  [ "$rows" -eq "$configs" ] || { echo "FAIL: compare wrote $rows method rows, the registry has $configs configurations"; fails=$((fails+1)); }
  grep -q '^| curvature-profile | ok |' "$dir/cmp.md" || { echo "FAIL: compare table lacks curvature-profile"; fails=$((fails+1)); }
  for f in methods points curves curvature combs; do [ -s "$dir/cmp/$f.csv" ] || { echo "FAIL: compare wrote no $f.csv"; fails=$((fails+1)); }; done
else
  echo "FAIL: compare exited non-zero"; fails=$((fails+1))
fi
"$cagd" compare --in "$dir/zig.csv" --closed --methods boost-pchip,cubic-b --out "$dir/cmp2" --no-plot > "$dir/cmp2.md" 2> /dev/null
grep -q '^| boost-pchip | not applicable |' "$dir/cmp2.md" || { echo "FAIL: compare --closed must list boost-pchip as not applicable"; fails=$((fails+1)); }
# Space points: the space columns (max_abs_torsion, no area), τ in the curvature file.
printf 'x,y,z\n1,0,0\n0,1,0.4\n-1,0,0.8\n0,-1,1.2\n1,0,1.6\n0,1,2\n' > "$dir/helix.csv"
if "$cagd" compare --in "$dir/helix.csv" --methods pseudo-spline-approx,hosaka-c2-chord,curvature-profile --out "$dir/cmp3d" --no-plot > "$dir/cmp3d.md" 2> /dev/null; then
  head -1 "$dir/cmp3d/measures.csv" | grep -q 'max_abs_torsion' || { echo "FAIL: compare on 3-D points lacks max_abs_torsion"; fails=$((fails+1)); }
  head -1 "$dir/cmp3d/curvature.csv" | grep -q '^index,s,kappa,tau' || { echo "FAIL: compare on 3-D points writes no torsion profile"; fails=$((fails+1)); }
  grep -q '^| pseudo-spline-approx | ok |' "$dir/cmp3d.md" || { echo "FAIL: compare on 3-D points lacks the space pseudo-spline"; fails=$((fails+1)); }
  grep -q '^| curvature-profile | not applicable |' "$dir/cmp3d.md" || { echo "FAIL: compare on 3-D points must list curvature-profile as not applicable"; fails=$((fails+1)); }
else
  echo "FAIL: compare on 3-D points exited non-zero"; fails=$((fails+1))
fi
expect_bad "compare 4-D points"    '0,0,0,0\n1,1,1,1\n2,0,0,0\n3,1,1,1\n'  compare --in "$dir/bad.csv" --out "$dir/cmp3" --no-plot
expect_bad "compare unknown method" '0,0\n1,1\n2,0\n3,1\n'        compare --in "$dir/bad.csv" --methods cubic-z --out "$dir/cmp3" --no-plot

# Every registered method is reachable from interpolate, analyze --in and compare by name (the
# list comes from the registry: a new method is walked here without editing this file).
methods=$("$cagd" interpolate --list-methods | awk '/^[a-z0-9]/ { print $1 }')
[ "$(echo "$methods" | wc -l)" -ge 12 ] || { echo "FAIL: --list-methods lists $(echo "$methods" | wc -l) methods"; fails=$((fails+1)); }
for m in $methods; do
  "$cagd" interpolate --method "$m" --in "$dir/zig.csv" --out "$dir/each.csv" --samples 2 > /dev/null 2> "$dir/err.txt" \
    || { echo "FAIL: interpolate --method $m: $(cat "$dir/err.txt")"; fails=$((fails+1)); }
  # 2 samples per piece and the end: 11 rows for a piece per span (6 points), 7 for eigen-spline's
  # 3 pieces (its knots are averages of the parameters, not the points).
  [ "$(($(wc -l < "$dir/each.csv") - 1))" -ge 7 ] || { echo "FAIL: interpolate --method $m wrote $(wc -l < "$dir/each.csv") lines"; fails=$((fails+1)); }
  "$cagd" analyze --in "$dir/zig.csv" --method "$m" 2> /dev/null | grep -q '^length_integrated,' \
    || { echo "FAIL: analyze --in --method $m prints no length"; fails=$((fails+1)); }
  "$cagd" compare --in "$dir/zig.csv" --methods "$m" --out "$dir/cmp_each" --no-plot 2> /dev/null | grep -q "^| $m" \
    || { echo "FAIL: compare --methods $m has no row"; fails=$((fails+1)); }
done
expect_bad "option of another method" '0,0\n1,1\n2,0\n'  interpolate --method s-spline --scale unit --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "hosaka m-vector"          '0,0\n1,1\n2,0\n'  interpolate --method hosaka --m-vector 1,1 --in "$dir/bad.csv" --out "$dir/o.csv"
expect_bad "m and m-vector"           '0,0\n1,1\n2,0\n'  interpolate --m 1 --m-vector 1,1 --in "$dir/bad.csv" --out "$dir/o.csv"
"$cagd" --version | grep -q '^cagd [0-9]' || { echo "FAIL: --version"; fails=$((fails+1)); }
"$cagd" energy-table --help | grep -q 'periodic' || { echo "FAIL: energy-table --help shows no default placement"; fails=$((fails+1)); }

# Writers: a symbolic link (even dangling) keeps pointing at the replaced file; a replaced file
# keeps its mode, a new one gets 0666 less the umask; /dev/stdout on a pipe is written, not replaced.
ln -s target.csv "$dir/link.csv"
"$cagd" interpolate --in "$dir/pts.csv" --out "$dir/link.csv" --samples 1 || { echo "FAIL: output through a dangling link"; fails=$((fails+1)); }
{ [ -L "$dir/link.csv" ] && [ -s "$dir/target.csv" ]; } || { echo "FAIL: the link was replaced or its target not written"; fails=$((fails+1)); }
echo old > "$dir/mode.csv"; chmod 640 "$dir/mode.csv"
"$cagd" interpolate --in "$dir/pts.csv" --out "$dir/mode.csv" --samples 1
[ "$(stat -c %a "$dir/mode.csv")" = 640 ] || { echo "FAIL: mode of a replaced file: $(stat -c %a "$dir/mode.csv")"; fails=$((fails+1)); }
(umask 022; "$cagd" interpolate --in "$dir/pts.csv" --out "$dir/new_mode.csv" --samples 1)
[ "$(stat -c %a "$dir/new_mode.csv")" = 644 ] || { echo "FAIL: mode of a new file: $(stat -c %a "$dir/new_mode.csv")"; fails=$((fails+1)); }
"$cagd" interpolate --in "$dir/pts.csv" --out /dev/stdout --samples 1 | grep -q '^t,x,y' || { echo "FAIL: --out /dev/stdout on a pipe"; fails=$((fails+1)); }
[ -L /dev/stdout ] || [ -c /dev/stdout ] || { echo "FAIL: /dev/stdout is no longer a link or device"; fails=$((fails+1)); }

# The user's table cache: the first pseudo-spline run builds the planar table into
# $XDG_CACHE_HOME/cagd with one line on stderr, the second loads it silently; --no-cache and
# CAGD_NO_CACHE=1 write nothing.
printf 'x,y\n0,0\n1,1\n2,0\n3,1\n' > "$dir/ps.csv"
for run in first second; do
  XDG_CACHE_HOME="$dir/xdg" CAGD_NO_CACHE= "$cagd" analyze --in "$dir/ps.csv" --method pseudo-spline > /dev/null 2> "$dir/cache.$run"
done
[ "$(grep -c "building the 36 x 36 pseudo-energy table" "$dir/cache.first")" = 1 ] || { echo "FAIL: no build note on a cold cache"; cat "$dir/cache.first"; fails=$((fails+1)); }
! grep -q "building" "$dir/cache.second" || { echo "FAIL: a warm cache was built again"; fails=$((fails+1)); }
ls "$dir"/xdg/cagd/pseudo-energy-table-36-periodic-fast.txt > /dev/null || { echo "FAIL: no cached table"; fails=$((fails+1)); }
XDG_CACHE_HOME="$dir/xdg2" "$cagd" --no-cache analyze --in "$dir/ps.csv" --method pseudo-spline > /dev/null 2> "$dir/cache.off"
XDG_CACHE_HOME="$dir/xdg3" CAGD_NO_CACHE=1 "$cagd" analyze --in "$dir/ps.csv" --method pseudo-spline > /dev/null 2>> "$dir/cache.off"
{ [ ! -e "$dir/xdg2" ] && [ ! -e "$dir/xdg3" ] && ! grep -q building "$dir/cache.off"; } || { echo "FAIL: the cache was written while off"; fails=$((fails+1)); }
cmp -s <(XDG_CACHE_HOME="$dir/xdg" "$cagd" analyze --in "$dir/ps.csv" --method pseudo-spline 2>/dev/null) \
       <("$cagd" --no-cache analyze --in "$dir/ps.csv" --method pseudo-spline 2>/dev/null) || { echo "FAIL: the cached table gives other measures"; fails=$((fails+1)); }

# Messages in the user's terms: a point is named by its ordinal and its line of the file, and no
# C++ qualified name reaches the user.
printf 'x,y\n# a comment\n0,0\n1,1\n1,1\n2,0\n' > "$dir/dup.csv"
"$cagd" interpolate --method cubic-b --in "$dir/dup.csv" --out "$dir/o.csv" 2> "$dir/err.txt"
grep -q 'point 2 (line 4) and point 3 (line 5) coincide' "$dir/err.txt" || { echo "FAIL: coincident points not named by their lines:"; cat "$dir/err.txt"; fails=$((fails+1)); }
! grep -q '::' "$dir/err.txt" || { echo "FAIL: a C++ qualified name reached the user:"; cat "$dir/err.txt"; fails=$((fails+1)); }
# --closed with the first point repeated at the end (a CAD export's closed polyline): the repeat is
# the closing point, dropped with one line that says so; the curve is that of the points without it.
printf '0,0\n1,0\n1,1\n0,1\n0,0\n' > "$dir/closing.csv"
printf '0,0\n1,0\n1,1\n0,1\n' > "$dir/square.csv"
"$cagd" interpolate --method cubic-b --closed --in "$dir/closing.csv" --out "$dir/closing_curve.csv" 2> "$dir/err.txt" || { echo "FAIL: --closed with a repeated closing point"; cat "$dir/err.txt"; fails=$((fails+1)); }
[ "$(wc -l < "$dir/err.txt")" -eq 1 ] && grep -q 'closing.csv:5: the last point repeats the first' "$dir/err.txt" || { echo "FAIL: the dropped closing point is not said in one line:"; cat "$dir/err.txt"; fails=$((fails+1)); }
"$cagd" interpolate --method cubic-b --closed --in "$dir/square.csv" --out "$dir/square_curve.csv" 2> /dev/null
cmp -s "$dir/closing_curve.csv" "$dir/square_curve.csv" || { echo "FAIL: the curve with the closing point dropped differs from the curve of the points without it"; fails=$((fails+1)); }
# Open, a repeated first point is a closed polyline's last point, and stays bad input for no method.
"$cagd" analyze --in "$dir/closing.csv" --method cubic-b > "$dir/a.txt" 2> /dev/null || { echo "FAIL: analyze of an open polyline that returns to its start"; fails=$((fails+1)); }
# compare on two points: gnuplot's warnings (empty ranges) never reach stderr.
if command -v gnuplot > /dev/null; then
  printf '0,0\n1,1\n' > "$dir/two.csv"
  "$cagd" compare --in "$dir/two.csv" --methods cubic-b,hermite-a --out "$dir/cmp2" > /dev/null 2> "$dir/err.txt" || { echo "FAIL: compare on two points"; cat "$dir/err.txt"; fails=$((fails+1)); }
  ! grep -qi 'warning' "$dir/err.txt" || { echo "FAIL: gnuplot's chatter reached stderr:"; cat "$dir/err.txt"; fails=$((fails+1)); }
fi
# analyze names where the curvature extremes are as the file names its parameter column.
"$cagd" analyze "$dir/c.csv" 2> /dev/null | grep -q '^curvature_max_at_t,' || { echo "FAIL: analyze does not name the extremes' parameter t as the file does"; fails=$((fails+1)); }
if [ "$fails" -eq 0 ]; then echo "cli: all checks passed"; fi
exit $((fails > 0))
