#!/usr/bin/env bash
# Signals end promyk cleanly: exit 128 + signal and no file left behind (no
# image, no traces, no temporary).
#   - SIGINT, SIGTERM, SIGHUP during a long render (SIGHUP: the terminal closed);
#   - SIGPIPE: traces piped into a reader that quits (`| head -c 100`) give
#     exit 141, quietly, with the image not committed;
#   - SIGINT and SIGTERM while blocked reading a scene from a FIFO with no
#     writer: "interrupted", not an input error ("Interrupted system call").
# usage: interrupt_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
passed=0 failed=0

fresh() { rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1; }
fail() { echo "$1"; cat err.txt; failed=$((failed + 1)); }
# The files left in the folder besides the test's own.
left() { ls -A | grep -vE '^(out|err)\.txt$|^scene\.json$'; }
# interrupt SIGNAL SECONDS COMMAND...: runs promyk COMMAND in the background,
# sends SIGNAL after SECONDS, and sets `code` to its exit status.
interrupt() {
    local signal=$1 delay=$2
    shift 2
    "$promyk" "$@" >out.txt 2>err.txt &
    local pid=$!
    sleep "$delay"
    kill -s "$signal" "$pid"
    # A signal that came too early is lost (a background job of a script
    # starts with SIGINT ignored, until promyk installs its handlers): fail
    # after a minute rather than hang the suite.
    (sleep 60 && kill -s KILL "$pid" 2>/dev/null) &
    local watchdog=$!
    wait "$pid"
    code=$?
    kill "$watchdog" 2>/dev/null
    wait "$watchdog" 2>/dev/null
}

for signal in INT TERM HUP; do
    fresh
    # The largest pane (about 6 s in a release build): still running when the signal comes.
    # The signal must come after promyk has started: a sanitizer build takes
    # most of a second to reach main (PROMYK_SIGNAL_DELAY, set by CMake there).
    interrupt "$signal" "${PROMYK_SIGNAL_DELAY:-0.5}" render --w 32768 -o big.png --traces big.jsonl --trace-region 0,0,32767,3
    expected=$((128 + $(kill -l "$signal")))
    before=$failed
    [ "$code" = "$expected" ] || fail "render SIG$signal: exit $code, expected $expected"
    [ -z "$(left)" ] || fail "render SIG$signal: files left behind: $(left)"
    grep -q "interrupted by SIG$signal" err.txt || fail "render SIG$signal: no message on stderr"
    [ $failed = $before ] && passed=$((passed + 1))
done

# SIGPIPE: the reader of --traces - quits after 100 bytes.
fresh
"$promyk" render --w 2048 -o x.png --traces - 2>err.txt | head -c 100 >out.txt
codes=("${PIPESTATUS[@]}")
before=$failed
[ "${codes[0]}" = 141 ] || fail "SIGPIPE: exit ${codes[0]}, expected 141"
[ "$(wc -c <out.txt)" = 100 ] || fail "SIGPIPE: head did not get its 100 bytes"
[ -z "$(left)" ] || fail "SIGPIPE: files left behind: $(left)"
[ ! -s err.txt ] || fail "SIGPIPE: not quiet"
[ $failed = $before ] && passed=$((passed + 1))

# The same for a PNG on standard output.
fresh
"$promyk" render --w 4096 -o - 2>err.txt | head -c 100 >out.txt
codes=("${PIPESTATUS[@]}")
before=$failed
[ "${codes[0]}" = 141 ] || fail "SIGPIPE (PNG): exit ${codes[0]}, expected 141"
[ -z "$(left)" ] || fail "SIGPIPE (PNG): files left behind: $(left)"
[ $failed = $before ] && passed=$((passed + 1))

# A signal while blocked opening a scene FIFO that has no writer.
for signal in INT TERM; do
    fresh
    mkfifo scene.json
    interrupt "$signal" "${PROMYK_SIGNAL_DELAY:-0.3}" trace --scene scene.json
    expected=$((128 + $(kill -l "$signal")))
    before=$failed
    [ "$code" = "$expected" ] || fail "scene FIFO SIG$signal: exit $code, expected $expected"
    grep -q "interrupted by SIG$signal" err.txt || fail "scene FIFO SIG$signal: no 'interrupted' on stderr"
    grep -q "Interrupted system call" err.txt && fail "scene FIFO SIG$signal: reported as an input error"
    [ -z "$(left)" ] || fail "scene FIFO SIG$signal: files left behind: $(left)"
    [ $failed = $before ] && passed=$((passed + 1))
done

# The same for render, which must not have created its image's temporary yet.
fresh
mkfifo scene.json
interrupt INT "${PROMYK_SIGNAL_DELAY:-0.3}" render --scene scene.json -o x.png
before=$failed
[ "$code" = 130 ] || fail "render scene FIFO SIGINT: exit $code, expected 130"
[ -z "$(left)" ] || fail "render scene FIFO SIGINT: files left behind: $(left)"
[ $failed = $before ] && passed=$((passed + 1))

echo "interrupt test: $passed passed, $failed failed"
[ $failed = 0 ]
