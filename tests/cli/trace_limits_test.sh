#!/usr/bin/env bash
# The bound on a trace's size (issue 19): a trace is estimated from the scene
# before anything is traced and refused above the limit (exit 2, the
# estimate named, --max-trace-size to go past it) by trace (text, json, --spp,
# --compare), lesson and render --traces; diff reads a trace up to that
# limit. And the smaller items: diff refuses a group index past 2^31 - 1 and
# an unknown real type, names no pixel (-1, -1) for a key given twice, says
# when two traces come from different scenes or panes; a lesson file without
# a name lists as its file's name; a failed lesson --dump leaves no folder.
# usage: trace_limits_test.sh PROMYK WORKDIR
promyk=$1 dir=$2
scenes=$(cd "$(dirname "$0")/scenes" && pwd)
. "$(dirname "$0")/lib.sh"

# many_scene (lib.sh): pixel (4, 4) of an 8 x 8 pane tests every sphere on
# the way to every light.
# The message's lines joined (main wraps errors at 80 columns).
joined() { tr '\n' ' ' <err.txt | tr -s ' '; }

# 1. A million shadow tests (the issue's 583 MB of JSON): refused at once,
# before tracing, by every command that would build the trace.
many_scene 1000 1000 >big.json
refused() {  # refused NAME ARGS...: exit 2 in under 2 s of processor time, the estimate and the way past it
    local name=$1
    shift
    local start end
    start=$(date +%s%N)
    "$promyk" "$@" >out.txt 2>err.txt
    local code=$?
    end=$(date +%s%N)
    local ms=$(((end - start) / 1000000))
    if [ $code != 2 ]; then bad "$name: exit $code, expected 2"; cat err.txt; return; fi
    [ $ms -lt 2000 ] || bad "$name: took $ms ms to refuse"
    joined | grep -qE "would take about [0-9.]+ (MB|GB|TB)" || bad "$name: no estimate: $(joined)"
    joined | grep -q -- "--max-trace-size [0-9]" || bad "$name: no --max-trace-size: $(joined)"
    joined | grep -q "1000 spheres, 0 planes, 1000 lights with shadows" || bad "$name: not what it is made of: $(joined)"
    [ ! -s out.txt ] || bad "$name: wrote standard output"
    ok
}
refused "trace text" trace --scene big.json --pixel 4,4
refused "trace json" trace --scene big.json --pixel 4,4 --format json
refused "trace --spp 4" trace --scene big.json --pixel 4,4 --spp 4
refused "trace --compare" trace --scene big.json --pixel 4,4 --compare float,double
refused "lesson" lesson shadows --scene big.json --pixel 4,4
refused "render --traces" render --scene big.json --w 8 -o x.png --traces t.jsonl --trace-pixel 4,4
refused "render --traces -" render --scene big.json --w 8 -o x.png --traces - --trace-pixel 4,4
[ ! -e x.png ] && [ ! -e t.jsonl ] && ok || bad "render left files behind"

# The Polish message: the same numbers, a decimal comma, the option.
"$promyk" --lang pl trace --scene big.json --pixel 4,4 >out.txt 2>err.txt
[ $? = 2 ] && joined | grep -q "ślad zająłby około [0-9,]* [MG]B" && joined | grep -q -- "--max-trace-size" && ok ||
    bad "Polish refusal: $(joined)"
# Within 80 columns.
wide=0
while IFS= read -r line; do [ ${#line} -le 80 ] || wide=1; done <err.txt  # characters, in C.UTF-8
[ $wide = 0 ] && ok || bad "Polish refusal wider than 80 columns"

# 2. A smaller scene (150 x 150) under a small limit: refused; the size the
# message suggests lets it run, and the trace is then below the estimate.
many_scene 150 150 >mid.json
"$promyk" trace --scene mid.json --pixel 4,4 --format json --max-trace-size 1MB >out.txt 2>err.txt
[ $? = 2 ] && ok || bad "1MB limit: not refused: $(joined)"
enough=$(joined | grep -oE -- "--max-trace-size [0-9]+" | head -1 | cut -d' ' -f2)
estimate=$(joined | grep -oE "about [0-9.]+ MB" | head -1 | grep -oE "[0-9.]+")
"$promyk" trace --scene mid.json --pixel 4,4 --format json --max-trace-size "$enough" >out.txt 2>err.txt
if [ $? = 0 ]; then
    size=$(wc -c <out.txt)
    # The estimate is at least the real size and at most 3 times it.
    awk -v s="$size" -v e="$estimate" 'BEGIN { exit !(s <= e * 1e6 * 1.05 && e * 1e6 <= 3 * s * 1.05) }' && ok ||
        bad "estimate $estimate MB against the real $size bytes"
else
    bad "--max-trace-size $enough: did not run: $(joined)"
fi
# The default limit (1 GB) lets it run.
"$promyk" trace --scene mid.json --pixel 4,4 >/dev/null 2>err.txt && ok || bad "default limit refused mid.json: $(joined)"
# What --max-trace-size takes: a size, not a word, zero or a negative number.
for value in abc 0 -5 1XB 2GiBs ""; do
    "$promyk" trace --max-trace-size "$value" >out.txt 2>err.txt
    [ $? = 2 ] && ok || bad "--max-trace-size '$value' accepted"
done
for value in 500MB 2GB 3GiB 1e12 100000 1.5G; do
    "$promyk" trace --max-trace-size "$value" >out.txt 2>err.txt && ok || bad "--max-trace-size '$value' refused: $(joined)"
done

# 3. diff reads each side up to the trace limit (at least 128 MiB).
"$promyk" trace --format json >a.json 2>/dev/null
head -c 160000000 /dev/zero | "$promyk" diff - a.json --max-trace-size 150MB >out.txt 2>err.txt
[ $? = 3 ] && joined | grep -q "larger than 143 MiB" && ok || bad "diff under a 150MB limit: $(joined)"
head -c 160000000 /dev/zero | "$promyk" diff - a.json >out.txt 2>err.txt
[ $? = 3 ] && ! joined | grep -q "larger than" && ok || bad "diff under the default limit: $(joined)"

# 4. diff: a group index from 2^31 on, or not a number, is refused, not skipped.
"$promyk" trace --scene "$scenes/everything_canonical.json" --pixel 3,4 --format json >e.json 2>/dev/null
"$promyk" trace --scene "$scenes/everything_canonical.json" --pixel 3,4 --format json --real float >f.json 2>/dev/null
grep -q '"index":1,' e.json || bad "everything's trace has no group index 1"
for index in 2147483648 9999999999 -1 1.5; do
    sed "s/\"index\":1,/\"index\":$index,/" e.json >g.json
    "$promyk" diff g.json f.json >out.txt 2>err.txt
    [ $? = 3 ] && joined | grep -q "group index" && ok || bad "group index $index: $(joined)"
done
# 2^31 - 1 is read as an index (then refused as a key the scene does not have).
sed 's/"index":1,/"index":2147483647,/' e.json >g.json
"$promyk" diff g.json f.json >out.txt 2>err.txt
joined | grep -q 'sphere\[2147483647\]' && ok || bad "group index 2147483647: $(joined)"
# A real type promyk does not have.
sed 's/"real":"double"/"real":"octuple"/' e.json >g.json
grep -q octuple g.json || bad "no numeric.real in the trace"
"$promyk" diff g.json f.json >out.txt 2>err.txt
[ $? = 3 ] && joined | grep -q 'real type "octuple" is unknown' && joined | grep -q "/numeric/real" && ok ||
    bad "octuple: $(joined)"
# A key given twice in typed numbers: its lines, no pixel (-1, -1).
printf 'C = 1\nt = 2\nC = 3\n' >twice.txt
"$promyk" diff a.json twice.txt >out.txt 2>err.txt
[ $? = 3 ] && joined | grep -q '"C" was already given at line 1' && ! joined | grep -q -- "-1" && ok ||
    bad "key given twice: $(joined)"
# Traces of different scenes, or of different panes: said before the branches.
"$promyk" trace --format json --pixel 3,4 >article.json 2>/dev/null
"$promyk" diff article.json f.json >out.txt 2>err.txt
grep -q "different scenes" out.txt && ok || bad "different scenes not said: $(cat out.txt)"
[ "$(grep -n "different scenes" out.txt | cut -d: -f1)" -lt "$(grep -n "branches differ\|branch" out.txt | head -1 | cut -d: -f1)" ] 2>/dev/null ||
    grep -qv "branches differ" out.txt && ok || bad "different scenes said after the branches"
"$promyk" trace --format json --pixel 3,4 --w 16 >w16.json 2>/dev/null
"$promyk" diff article.json w16.json >out.txt 2>err.txt
grep -q "different panes, 8 × 8 and 16 × 16" out.txt && ok || bad "different panes not said: $(cat out.txt)"
"$promyk" diff a.json article.json >out.txt 2>err.txt
grep -q "different" out.txt && bad "same scene and pane called different: $(cat out.txt)" || ok

# 5. A lesson file with no name (empty) lists as its file's name.
mkdir -p own/en
: >own/en/empty.md
"$promyk" lesson --list --lessons own >out.txt 2>err.txt
grep -qE "^  empty\.md" out.txt && ok || bad "--list: $(cat out.txt)"
"$promyk" lesson nosuch --lessons own >out.txt 2>err.txt
joined | grep -q "empty\.md" && ok || bad "no lesson: $(joined)"

# 6. lesson --dump that cannot write (a file-size limit standing in for a
# full disk; SIGXFSZ ignored so the write fails with EFBIG): exit 4 and no
# DIR/, DIR/en/ left.
(trap '' XFSZ; ulimit -f 1; "$promyk" lesson --dump dumped >out.txt 2>err.txt)
code=$?
[ $code = 4 ] && ok || bad "--dump on a full disk: exit $code: $(joined)"
[ ! -e dumped ] && ok || bad "--dump left $(find dumped | head -5 | tr '\n' ' ')"
mkdir kept
(trap '' XFSZ; ulimit -f 1; "$promyk" lesson --dump kept/inner >out.txt 2>err.txt)
[ -d kept ] && [ ! -e kept/inner ] && ok || bad "--dump into an existing folder: kept/ removed or kept/inner left"

summary
