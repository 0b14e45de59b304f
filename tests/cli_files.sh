#!/usr/bin/env bash
# The `cagd` command's file contract (docs/command.md). Writes (io/output_file.hpp): exit 0 only
# when every byte arrived; a failed write is exit 1 with the old file kept; a bad place is exit 2
# before any work; nothing outside the output changes and nothing is left behind, signals included.
# Reads: lines of at most 1 MiB, subnormals are numbers, table files checked by their checksum and
# their values before use, memory bounded by what was read.
# Usage: tests/cli_files.sh path/to/cagd
set -u
cagd=$(realpath "$1")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
export TMPDIR="$dir/tmp"
mkdir "$TMPDIR"
runs=0 fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
expect() {  # expect CODE DESCRIPTION ACTUAL
    runs=$((runs + 1))
    [ "$3" -eq "$1" ] || fail "$2: exit $3, expected $1 ($(head -c 300 err 2>/dev/null))"
}
no_temporaries() {  # nothing the writer made is left anywhere under the test directory
    local left
    left=$(find "$dir" -name '.*.cagd-*' | head -3)
    runs=$((runs + 1))
    [ -z "$left" ] || fail "$1: temporary files left: $left"
}
printf '0,0\n1,1\n2,0\n3,1\n4,0.5\n5,0\n' > p.csv
python3 -c "
import math, random
random.seed(3); x = y = h = 0.0
print('x,y')
for i in range(20000):
    h += random.uniform(-1, 1); s = random.uniform(0.2, 1.0); x += s * math.cos(h); y += s * math.sin(h)
    print(f'{x!r},{y!r}')" > walk.csv

# ---- failed writes: exit 1, the reason named, the old file kept --------------------------------
"$cagd" interpolate --method cubic-b --in p.csv --out /dev/full 2> err
expect 1 "--out /dev/full" $?
grep -q "'/dev/full'.*No space left" err || fail "--out /dev/full: the message names neither the path nor the reason: $(cat err)"
for cmd in "interpolate --method cubic-b --in p.csv --out -" "analyze --in p.csv --method cubic-b" "energy --theta0 30 --theta1 -45 --deg" \
           "monotone --in p.csv" "interpolate --list-methods"; do
    # shellcheck disable=SC2086
    "$cagd" $cmd > /dev/full 2> err
    expect 1 "$cmd > /dev/full" $?
done
"$cagd" compare --in p.csv --out cmp_full --no-plot > /dev/full 2> err
expect 1 "compare > /dev/full" $?
echo old > kept.csv
(trap '' XFSZ; prlimit --fsize=2000 "$cagd" interpolate --method cubic-b --in walk.csv --out kept.csv 2> err)
expect 1 "a write beyond the file-size limit" $?
runs=$((runs + 1))
[ "$(cat kept.csv)" = old ] || fail "a failed write did not keep the old file: $(head -c 100 kept.csv)"
grep -q "kept.csv" err || fail "the failed write's message does not name the file: $(cat err)"
no_temporaries "failed writes"

# ---- standard output and open descriptors: written through, never replaced ----------------------
echo prev > appended.csv
"$cagd" interpolate --method cubic-b --in p.csv --out /dev/stdout >> appended.csv 2> err
expect 0 "--out /dev/stdout >> file" $?
runs=$((runs + 1))
[ "$(head -1 appended.csv)" = prev ] && [ "$(sed -n 2p appended.csv)" = "t,x,y,dx,dy,ddx,ddy" ] || fail "--out /dev/stdout >> file lost what was there: $(head -2 appended.csv)"
{ echo a; "$cagd" interpolate --method cubic-b --in p.csv --out /dev/stdout; echo b; } > group.csv 2> err
runs=$((runs + 1))
[ "$(head -1 group.csv)" = a ] && [ "$(tail -1 group.csv)" = b ] && [ "$(grep -c . group.csv)" -gt 10 ] || fail "{ echo a; cagd --out /dev/stdout; echo b; } > f: $(head -c 80 group.csv)"
"$cagd" interpolate --method cubic-b --in p.csv --out - >&- 2> err
expect 2 "--out - with standard output closed" $?
"$cagd" interpolate --method cubic-b --in p.csv --out /dev/fd/1 > fd1.csv 2> err
expect 0 "--out /dev/fd/1" $?
cmp -s <(sed 1d appended.csv) fd1.csv || fail "--out /dev/fd/1 differs from --out /dev/stdout"

# A method's report never goes onto standard output beside data.
"$cagd" interpolate --method curvature-profile --in p.csv --out cp.csv --quiet > cp_stdout.txt 2> cp_stderr.txt
expect 0 "curvature-profile --quiet" $?
runs=$((runs + 1))
[ ! -s cp_stdout.txt ] && [ ! -s cp_stderr.txt ] || fail "curvature-profile --quiet printed its report: $(head -c 100 cp_stdout.txt cp_stderr.txt)"
"$cagd" interpolate --method curvature-profile --in p.csv --out cp.csv --report cp_report.csv > cp_stdout.txt 2> cp_stderr.txt
expect 0 "curvature-profile --report" $?
runs=$((runs + 1))
[ ! -s cp_stdout.txt ] && grep -q '^knot_difference_list,' cp_report.csv || fail "curvature-profile --report: the report is not in its file"

# ---- links and devices --------------------------------------------------------------------------
ln -s loop_b loop_a
ln -s loop_a loop_b
"$cagd" interpolate --method cubic-b --in p.csv --out loop_a 2> err
expect 2 "a loop of symbolic links" $?
runs=$((runs + 1))
[ -L loop_a ] && [ -L loop_b ] || fail "a link loop given as --out was replaced"
echo target > real.csv
ln -s real.csv link.csv
"$cagd" interpolate --method cubic-b --in p.csv --out link.csv 2> err
expect 0 "--out a symbolic link" $?
runs=$((runs + 1))
[ -L link.csv ] && [ "$(head -1 real.csv)" = "t,x,y,dx,dy,ddx,ddy" ] || fail "a symbolic link was not kept, or its target not replaced"
if [ "$(id -u)" -eq 0 ] && mknod full_device c 1 7 2> /dev/null && mknod null_device c 1 3 2> /dev/null; then
    "$cagd" energy-table --grid 8 --out full_device 2> err
    expect 1 "energy-table onto a full character device" $?
    "$cagd" interpolate --method cubic-b --in p.csv --out null_device 2> err
    expect 0 "--out a null character device" $?
    runs=$((runs + 1))
    [ -c full_device ] && [ -c null_device ] || fail "a device node was replaced by a regular file"
fi
mkfifo fifo
timeout 30 cat fifo > from_fifo.csv &
"$cagd" interpolate --method cubic-b --in p.csv --out fifo 2> err
expect 0 "--out a FIFO" $?
wait
runs=$((runs + 1))
[ -p fifo ] && [ "$(head -1 from_fifo.csv)" = "t,x,y,dx,dy,ddx,ddy" ] || fail "a FIFO was not written through"

# ---- bad places: exit 2 before any work ----------------------------------------------------------
start=$SECONDS
"$cagd" compare --in walk.csv --out /proc/no_such_place --no-plot 2> err
expect 2 "compare --out a place that cannot be written" $?
runs=$((runs + 1))
[ $((SECONDS - start)) -le 2 ] || fail "compare found a bad --out only after the work ($((SECONDS - start)) s)"
"$cagd" compare --in p.csv --out p.csv --no-plot 2> err
expect 2 "compare --out an existing file" $?
"$cagd" interpolate --method cubic-b --in p.csv --out no_such_dir/c.csv 2> err
expect 2 "--out in a missing directory" $?

# ---- compare: one output, whole or not at all ----------------------------------------------------
mkdir planted
echo secret > outside.txt
ln -s ../outside.txt planted/measures.csv
"$cagd" compare --in p.csv --out planted --no-plot > /dev/null 2> err
expect 0 "compare into a folder with a planted link" $?
runs=$((runs + 1))
[ "$(cat outside.txt)" = secret ] && [ ! -L planted/measures.csv ] || fail "compare followed a link planted in its folder"
# Two runs into one folder: every file of the folder comes from one of them.
"$cagd" compare --in p.csv --out both --no-plot --methods cubic-a,cubic-b > /dev/null 2>&1 &
"$cagd" compare --in p.csv --out both --no-plot --methods hermite-a,hermite-b,s-spline-m2 > /dev/null 2>&1 &
wait
runs=$((runs + 1))
[ "$(tail -n +2 both/measures.csv | cut -d, -f1 | sort)" = "$(tail -n +2 both/methods.csv | cut -d, -f2 | sort)" ] || fail "two concurrent compare runs mixed their files"
no_temporaries "compare"

# ---- signals: the temporary files go, the status is the signal's ---------------------------------
# Kills spread over the whole run of compare (about 3.5 s here): its staging folder, its files and
# their temporaries are registered before they exist (io/temporary_file.hpp).
for delay in 0.05 0.2 0.5 0.9 1.4 2 2.6 3.2; do
    "$cagd" compare --in walk.csv --out killed > /dev/null 2>&1 &
    pid=$!
    sleep "$delay"
    kill -TERM "$pid" 2> /dev/null
    wait "$pid"
    code=$?
    runs=$((runs + 1))
    [ "$code" -eq 143 ] || [ "$code" -eq 0 ] || fail "SIGTERM after $delay s of compare: exit $code"
    [ "$code" -eq 0 ] || [ ! -e killed ] || fail "compare killed after $delay s left its folder"
    rm -rf killed
    no_temporaries "SIGTERM after $delay s of compare"
done
"$cagd" interpolate --method cubic-b --in walk.csv --out - 2> /dev/null | head -c 100 > /dev/null
expect 141 "a reader that stops (SIGPIPE)" "${PIPESTATUS[0]}"
no_temporaries "signals"

# ---- reads that check values ------------------------------------------------------------------------
timeout 20 "$cagd" interpolate --method cubic-b --in /dev/zero --out z.csv 2> err
expect 2 "--in /dev/zero (a stream without line breaks)" $?
grep -q 'longer than' err || fail "--in /dev/zero: $(cat err)"
printf '0,0\n1,1e-310\n2,0\n3,1\n' > subnormal.csv
"$cagd" interpolate --method cubic-b --in subnormal.csv --out s.csv 2> err
expect 0 "a subnormal coordinate is a number" $?
printf '0,0\n1,\0331\n' > escape.csv
"$cagd" interpolate --method cubic-b --in escape.csv --out e.csv 2> err
expect 2 "an ESC byte in a field" $?
runs=$((runs + 1))
! grep -q $'\033' err && grep -q '\\x1b' err || fail "an ESC byte is echoed raw: $(cat -v err)"
"$cagd" energy-table --grid 12 --out t12.txt 2> err
expect 0 "energy-table --grid 12" $?
"$cagd" interpolate --method pseudo-spline --table t12.txt --in p.csv --out ps.csv 2> err
expect 0 "--table a table it wrote" $?
sed '5s/\(^[0-9]*,[0-9]*,[^,]*,[^,]*,\)[0-9]/\19/' t12.txt > t12_flipped.txt
cmp -s t12.txt t12_flipped.txt && fail "the test did not flip a digit"
"$cagd" interpolate --method pseudo-spline --table t12_flipped.txt --in p.csv --out ps.csv 2> err
expect 2 "--table with one flipped digit" $?
grep -q "checksum does not match" err || fail "a flipped digit is not named as a checksum mismatch: $(cat err)"
printf '# cagd pseudo_energy table format 7 grid 6000 placement periodic method fast\nx\n' > huge_header.txt
prlimit --as=536870912 "$cagd" interpolate --method pseudo-spline --table huge_header.txt --in p.csv --out ps.csv 2> err
expect 2 "a table whose header declares a huge grid, under 512 MB of address space" $?
# Table readers are bounded before they read whole: a stream without line breaks at its first line,
# a valid header followed by endless rows at the last line its grid allows.
printf '0,0,0\n1,1,0.5\n2,0,1\n3,1,0\n' > space.csv
for option in --table --space-table; do
    in=p.csv
    [ "$option" = --space-table ] && in=space.csv
    timeout 20 prlimit --as=536870912 "$cagd" interpolate --method pseudo-spline "$option" /dev/zero --in "$in" --out ps.csv 2> err
    expect 2 "$option /dev/zero" $?
    grep -q "a line longer than 4096 bytes" err || fail "$option /dev/zero: $(cat err)"
done
mkfifo endless.txt
( (head -1 t12.txt; yes "1,2") > endless.txt 2> /dev/null &)
timeout 20 prlimit --as=536870912 "$cagd" interpolate --method pseudo-spline --table endless.txt --in p.csv --out ps.csv 2> err
expect 2 "--table: a header, then endless rows" $?
grep -q "more than the 147 lines a table of the grid its header declares holds" err || fail "endless rows: $(cat err)"
rm -f endless.txt
no_temporaries "reads"

# ---- curve documents (export/curve_json.hpp): bounded before they are read, every fault exit 2 ----
"$cagd" interpolate --method cubic-b --in walk.csv --out walk.json 2> err
expect 0 "a curve document of 20000 points" $?
prlimit --as=536870912 "$cagd" analyze --in walk.json > walk_measures.csv 2> err
expect 0 "analyze of its own document under 512 MB" $?
mkdir dir.json
"$cagd" analyze --in dir.json 2> err
expect 2 "a directory as the document" $?
grep -q "dir.json: is a directory" err || fail "a directory document: $(cat err)"
sed '0,/"points": \[/{n;s/\[[^,]*,/[1e400,/}' walk.json > overflow.json
"$cagd" analyze --in overflow.json 2> err
expect 2 "1e400 in a document" $?
grep -q "overflow.json: not JSON (in points\[0\]\[0\]): number overflow parsing '1e400'" err ||
    fail "1e400: $(cat err)"
python3 -c "
import json
d = json.load(open('walk.json'))
d['pieces'][7][0][1] += 1.0
json.dump(d, open('jump.json', 'w'))"
"$cagd" analyze --in jump.json 2> err
expect 2 "pieces that do not join" $?
grep -q "jump.json: pieces\[7\] starts at" err || fail "a jump: $(cat err)"
ln -s /dev/zero zero.json
timeout 20 "$cagd" analyze --in zero.json 2> err
expect 2 "/dev/zero as a document" $?
mkfifo blank.json
(yes "" > blank.json 2> /dev/null &)
start=$(date +%s)
timeout 60 prlimit --as=536870912 "$cagd" analyze --in blank.json 2> err
expect 2 "a FIFO of endless white space under 512 MB" $?
runs=$((runs + 1))
[ $(($(date +%s) - start)) -le 5 ] || fail "endless white space was refused only after $(($(date +%s) - start)) s"
grep -q "white space longer than 1048576 bytes" err || fail "endless white space: $(cat err)"
rm -f walk.json overflow.json jump.json
no_temporaries "documents"

# Sizes: every size option at its limit runs inside 512 MB of address space; beyond it, exit 2 at once.
prlimit --as=536870912 "$cagd" typical-surface --n 1000 --grid 100 --alpha-u -1.5 --alpha-v -1.5 --angle-deg 10 --out ts.csv 2> err
expect 0 "typical-surface at its net limit (n 1000) under 512 MB" $?
prlimit --as=536870912 "$cagd" typical-surface --n 3 --grid 700 --alpha-u -1.5 --alpha-v -1.5 --angle-deg 10 --out ts.csv 2> err
expect 0 "typical-surface with a 700 x 700 grid under 512 MB (held a row block at a time)" $?
prlimit --as=536870912 "$cagd" typical-surface --n 1001 --grid 10 --alpha-u -1.5 --alpha-v -1.5 --angle-deg 10 --out ts.csv 2> err
expect 2 "typical-surface --n beyond its limit" $?
prlimit --as=536870912 "$cagd" lac3d --alpha 1.5 --beta 1.2 --degree 100000 --samples 200 --out lac3d.csv 2> err
expect 0 "lac3d at its degree limit under 512 MB" $?
prlimit --as=536870912 "$cagd" interpolate --method cubic-b --in /dev/zero --out zero.csv 2> err
expect 2 "a stream without line breaks under 512 MB" $?
grep -q "longer than" err || fail "the line limit is not named: $(cat err)"
start=$(date +%s)
prlimit --as=536870912 "$cagd" typical-surface --n 1000 --alpha-u -1.5 --alpha-v -1.5 --angle-deg 10 --out ts.json 2> err
expect 0 "typical-surface --n 1000 as JSON (its own net, no conversion) under 512 MB" $?
runs=$((runs + 1))
[ $(($(date +%s) - start)) -le 10 ] || fail "typical-surface --n 1000 --out ts.json took $(($(date +%s) - start)) s"
"$cagd" typical-surface --n 27 --alpha-u -1.5 --alpha-v -1.5 --angle-deg 10 --out ts.step 2> err
code=$?
if grep -q "without it" err; then runs=$((runs + 1)); else
    expect 2 "typical-surface --n 27 to STEP, refused before the work" $code
    grep -q "step takes degree <= 25 (--n <= 26)" err || fail "--n 27 to STEP: $(cat err)"
fi
python3 -c "
for name, row in (('b', '{s!r},0,0'), ('l', '0,{s!r},0'), ('t', '{s!r},1,0'), ('r', '1,{s!r},0')):
    open('edge_' + name + '.csv', 'w').write(''.join(row.format(s=i / 999) + '\n' for i in range(1000)))"
start=$(date +%s)
"$cagd" surface --kind coons --bottom edge_b.csv --left edge_l.csv --top edge_t.csv --right edge_r.csv --out co.json 2> err
expect 2 "a Coons surface of 1000-point edges to JSON: more patches than the limit" $?
runs=$((runs + 1))
[ $(($(date +%s) - start)) -le 1 ] || fail "the Coons size refusal took $(($(date +%s) - start)) s"
grep -q "would hold 15968016 control points, more than 10000000" err || fail "Coons size: $(cat err)"
rm -f ts.csv ts.json ts.step lac3d.csv edge_?.csv
no_temporaries "sizes"

echo "cli files: $runs checks, $fails failed"
echo "$((runs - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
