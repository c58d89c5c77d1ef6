#!/usr/bin/env bash
# Signals end promyk cleanly: exit 128 + signal and no file left behind (no
# image, no traces, no temporary).
#   - SIGINT, SIGTERM, SIGHUP during a long render (SIGHUP: the terminal closed);
#   - SIGPIPE: traces piped into a reader that quits (`| head -c 100`) give
#     exit 141, quietly, with the image not committed;
#   - SIGINT and SIGTERM while blocked reading a scene from a FIFO with no
#     writer: "interrupted", not an input error ("Interrupted system call");
#   - SIGINT, SIGTERM, SIGHUP while waiting on an input nobody writes: a
#     trace FIFO for diff, answers on standard input, lesson --step's Enter
#     (exit 128 + signal; the lesson's later steps never printed);
#   - SIGINT, SIGTERM, SIGHUP during one pixel's trace of 1,500 spheres and
#     1,500 lights with shadows (2.25 million shadow tests): trace (text and
#     JSON), lesson shadows, render --traces, and scene check of the largest
#     scene the loader takes; within a second (2 s under the sanitizers,
#     PROMYK_SANITIZED=1), with nothing on standard output;
#   - SIGINT, SIGTERM, SIGHUP during bench accuracy (with --json), diff of
#     two big traces, render --map (branch with traces, error, digits-lost)
#     and the trace-size estimate of render --traces: the same exit code, within the
#     same time, no file left. (Under the sanitizers these two groups send
#     one of the three signals a command, in turn.)
# usage: interrupt_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
. "$(dirname "$0")/lib.sh"

fresh() { rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1; }
fail() { echo "$1"; cat err.txt; failed=$((failed + 1)); }
# The files left in the folder besides the test's own.
left() { ls -A | grep -vE '^(out|err)\.txt$|^scene\.json$'; }
# Waits until process $1 has installed its handlers of SIGHUP, SIGINT and
# SIGTERM (bits 0, 1 and 14 of /proc's SigCgt mask) or has ended, for up to
# a minute. A signal sent before that is lost or kills it: a sanitizer build
# takes most of a second to reach main, any build longer on a busy machine.
wait_for_handlers() {
    local k state
    for ((k = 0; k < 3000; ++k)); do
        state=$(awk '/^State:/ {s = $2} /^SigCgt:/ {m = $2} END {print s, m}' "/proc/$1/status" 2>/dev/null)
        case $state in
            "" | " " | Z*) return ;;  # ended
        esac
        (((16#${state#* } & 0x4003) == 0x4003)) && return
        sleep 0.02
    done
}

# interrupt SIGNAL SECONDS COMMAND...: runs promyk COMMAND in the background,
# sends SIGNAL SECONDS after it has its handlers, and sets `code` to its exit
# status. Standard input is $input (default /dev/null).
interrupt() {
    local signal=$1 delay=$2
    shift 2
    "$promyk" "$@" <"${input:-/dev/null}" >out.txt 2>err.txt &
    local pid=$!
    wait_for_handlers "$pid"
    sleep "$delay"
    kill -s "$signal" "$pid"
    local sent
    sent=$(date +%s%N)
    # A signal that came too early is lost (a background job of a script
    # starts with SIGINT ignored, until promyk installs its handlers): fail
    # after a minute rather than hang the suite. (tail --pid ends with
    # promyk. No background watchdog: a sleep left running with the test's
    # standard output open kept CTest waiting for it.)
    timeout 60 tail --pid="$pid" -s 0.01 -f /dev/null || kill -s KILL "$pid" 2>/dev/null
    wait "$pid"
    code=$?
    took_ms=$((($(date +%s%N) - sent) / 1000000))
}

for signal in INT TERM HUP; do
    fresh
    # The largest pane (about 6 s in a release build): still running when the signal comes.
    interrupt "$signal" 0.5 render --w 32768 -o big.png --traces big.jsonl --trace-region 0,0,32767,3
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
    interrupt "$signal" 0.3 trace --scene scene.json
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
interrupt INT 0.3 render --scene scene.json -o x.png
before=$failed
[ "$code" = 130 ] || fail "render scene FIFO SIGINT: exit $code, expected 130"
[ -z "$(left)" ] || fail "render scene FIFO SIGINT: files left behind: $(left)"
[ $failed = $before ] && passed=$((passed + 1))

# Inputs nobody writes: standard input a FIFO this script holds open for
# reading and writing (so it never ends and never has data, like a terminal
# where nobody types). A signal must end the wait, not read on. All three
# signals a case; under the sanitizers (slow to start) one a case, in turn.
k=0
for case in "diff FIFO" "answers -" "lesson --step"; do
    waits=(INT TERM HUP)
    [ "${PROMYK_SANITIZED:-0}" = 1 ] && waits=("${waits[k++ % 3]}")
    for signal in "${waits[@]}"; do
        fresh
        mkfifo quiet
        exec 3<>quiet
        input=/dev/fd/3
        case $case in
            "diff FIFO")
                mkfifo a.jsonl
                interrupt "$signal" 0.3 diff a.jsonl a.jsonl ;;
            "answers -")
                interrupt "$signal" 0.3 lesson sphere --answers - ;;
            "lesson --step")
                interrupt "$signal" 0.3 lesson sphere --step --lang en ;;
        esac
        unset input
        exec 3>&-
        rm -f quiet a.jsonl
        expected=$((128 + $(kill -l "$signal")))
        before=$failed
        [ "$code" = "$expected" ] || fail "$case SIG$signal: exit $code, expected $expected"
        grep -q "interrupted by SIG$signal" err.txt || fail "$case SIG$signal: no 'interrupted' on stderr"
        # The lesson waited at its first step: no second step was printed.
        [ "$case" != "lesson --step" ] || [ "$(grep -c 'Enter: next step' err.txt)" -le 1 ] ||
            fail "$case SIG$signal: the lesson went on after the signal"
        [ -z "$(left)" ] || fail "$case SIG$signal: files left behind: $(left)"
        [ $failed = $before ] && passed=$((passed + 1))
    done
done

# A scene of 1,500 spheres and 1,500 lights with shadows (many_scene, lib.sh):
# pixel (4, 4) tests every sphere on the way to every light, a trace of about
# 1 GB, past the default limit: --max-trace-size lets it run.
# Within a second of the signal; under the sanitizers 2 s, for a machine
# running other tests beside them (on a quiet one every case here ended
# within 100 ms of the signal, 2026-12-06). That limit was 6 s while the
# scene's report probed a pane with no look at the signal (1.5 s for this
# scene under the sanitizers, found with gdb); it had been put down to
# unwinding a big trace.
limit_ms=1000
sanitized=${PROMYK_SANITIZED:-0}
[ "$sanitized" = 1 ] && limit_ms=2000
# The signals sent during each long command: all three in the release pass;
# under the sanitizers, where each case waits 3 s for promyk to reach main,
# one a command, in turn, so every signal still meets every kind of loop.
turn=0 sent=0
pick_signals() {
    if [ "$sanitized" = 1 ]; then
        local all=(INT TERM HUP)
        signals=("${all[turn % 3]}")
        turn=$((turn + 1))
    else
        signals=(INT TERM HUP)
    fi
    sent=$((sent + ${#signals[@]}))
}
for case in "trace text" "trace json" "lesson" "render traces" "scene check"; do
    pick_signals
    for signal in "${signals[@]}"; do
        fresh
        many_scene 1500 1500 >scene.json
        big="--scene scene.json --max-trace-size 1TB"
        case $case in
            # The largest scene the loader takes (14,000 spheres and as many
            # lights, just under 1 MiB): parsed, validated and probed before
            # anything is drawn (0.9 s in a release build), each step
            # looking at the signal as it goes.
            "scene check")
                many_scene 14000 14000 >scene.json
                interrupt "$signal" 0.2 scene check scene.json ;;
            "trace text") interrupt "$signal" 0.5 trace $big --pixel 4,4 ;;
            "trace json") interrupt "$signal" 0.5 trace $big --pixel 4,4 --format json ;;
            "lesson") interrupt "$signal" 0.5 lesson shadows $big --pixel 4,4 ;;
            "render traces")
                interrupt "$signal" 0.5 render $big --w 8 -o x.png --traces t.jsonl \
                    --trace-pixel 4,4 ;;
        esac
        expected=$((128 + $(kill -l "$signal")))
        before=$failed
        [ "$code" = "$expected" ] || fail "$case SIG$signal: exit $code, expected $expected"
        [ "$took_ms" -le "$limit_ms" ] || fail "$case SIG$signal: ended ${took_ms} ms after the signal (at most $limit_ms)"
        [ ! -s out.txt ] || fail "$case SIG$signal: $(wc -c <out.txt) bytes on standard output"
        [ -z "$(left)" ] || fail "$case SIG$signal: files left behind: $(left)"
        grep -q "interrupted by SIG$signal" err.txt || fail "$case SIG$signal: no message on stderr"
        [ $failed = $before ] && passed=$((passed + 1))
    done
done

# Long commands of other kinds: bench accuracy, the maps, and render --traces
# with a map. (An error map at w 1024 with 16 samples a pixel: a row takes
# about 30 ms, 0.3 s under the sanitizers, the whole map over 15 s. At w 4096
# the error map keeps its 128 MB of values until it has its range: the
# allocation must not hide a signal; maps_test checks that it touches no page.)
# diff reads two traces of 14 MB each (a pixel of 250 spheres and 250
# lights with shadows, 230,000 steps) for 3.6 s, the sanitizers' build for a
# minute: the signal is looked at while their JSON is parsed, their steps
# read and compared.
trace_file=${dir}_trace.json
many_scene 250 250 >"${dir}_scene.json"
"$promyk" trace --scene "${dir}_scene.json" --pixel 4,4 --format json --max-trace-size 1TB >"$trace_file"
for case in "bench accuracy" "bench accuracy json" "map branch traces" "map error" "map error 4096" \
    "map digits-lost" "diff traces"; do
    pick_signals
    for signal in "${signals[@]}"; do
        fresh
        case $case in
            "diff traces") interrupt "$signal" 0.5 diff "$trace_file" "$trace_file" ;;
            "bench accuracy") interrupt "$signal" 0.5 bench accuracy --threads 1 ;;
            "bench accuracy json")
                interrupt "$signal" 0.5 bench accuracy --threads 1 --json a.json ;;
            "map branch traces")
                interrupt "$signal" 0.5 render --w 16384 --map branch -o m.png \
                    --traces t.jsonl --trace-region 0,0,16383,7 ;;
            "map error")
                interrupt "$signal" 0.5 render --w 1024 --spp 16 --map error -o m.png ;;
            "map error 4096")
                interrupt "$signal" 0.5 render --w 4096 --map error -o m.png ;;
            "map digits-lost")
                interrupt "$signal" 0.5 render --w 1024 --spp 16 --map digits-lost \
                    --traces t.jsonl --trace-pixel 5,5 -o m.png ;;
        esac
        expected=$((128 + $(kill -l "$signal")))
        before=$failed
        [ "$code" = "$expected" ] || fail "$case SIG$signal: exit $code, expected $expected"
        [ "$took_ms" -le "$limit_ms" ] || fail "$case SIG$signal: ended ${took_ms} ms after the signal (at most $limit_ms)"
        [ -z "$(left)" ] || fail "$case SIG$signal: files left behind: $(left)"
        grep -q "interrupted by SIG$signal" err.txt || fail "$case SIG$signal: no message on stderr"
        [ $failed = $before ] && passed=$((passed + 1))
    done
done

rm -f "$trace_file" "${dir}_scene.json"
# Twelve long commands: each got its signals (one under the sanitizers, else three).
[ "$sent" = $((sanitized ? 12 : 36)) ] || fail "the long commands got $sent signals, expected $((sanitized ? 12 : 36))"
echo "interrupt test: $passed passed, $failed failed"
[ $failed = 0 ]
