#!/usr/bin/env bash
# promyk render's outputs where the set-up needs more than an empty folder:
# the same file by other paths, symbolic links written through, devices and
# FIFOs written directly (never replaced), /dev/full, a directory, standard
# output redirected to a file.
# usage: outputs_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
passed=0 failed=0

fresh() { rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1; }
check() {  # check NAME CONDITION...: counts and reports
    local name=$1; shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $name"; cat err.txt 2>/dev/null; fi
}
only() {  # only NAME...: the folder holds exactly these names (hidden ones included)
    [ "$(ls -A | sort | tr '\n' ' ')" = "$(printf '%s\n' "$@" | sort | tr '\n' ' ')" ]
}
is_png() { [ "$(head -c 4 "$1" | tail -c 3)" = PNG ]; }

# 1. The same file by another path: exit 2, nothing computed or created.
fresh; mkdir a
"$promyk" render --w 8 -o x.png --traces a/../x.png >out.txt 2>err.txt
check "a/../x is x" [ $? = 2 ]
check "a/../x: nothing created" only a out.txt err.txt
check "a/../x: says why" grep -q "same file" err.txt

fresh; echo old >x.png; ln -s x.png link.png; ln x.png hard.png
"$promyk" render --w 8 -o link.png --traces x.png >out.txt 2>err.txt
check "symbolic link to x is x" [ $? = 2 ]
"$promyk" render --w 8 -o x.png --traces hard.png >out.txt 2>err.txt
check "hard link to x is x" [ $? = 2 ]
check "x untouched" [ "$(cat x.png)" = old ]
check "links: nothing created" only x.png link.png hard.png out.txt err.txt

fresh; ln -s new.png dangling.png
"$promyk" render --w 8 -o new.png --traces dangling.png >out.txt 2>err.txt
check "dangling link to a new file is that file" [ $? = 2 ]
check "dangling: nothing created" only dangling.png out.txt err.txt

fresh; : >t.jsonl
"$promyk" render --w 8 -o t.jsonl --traces - >t.jsonl 2>err.txt
check "- redirected to the image file is that file" [ $? = 2 ]

# 2. A symbolic link as -o: the link stays, its target gets the image.
fresh; mkdir real; echo old >real/x.png; ln -s real/x.png link.png
"$promyk" render --w 8 -o link.png >out.txt 2>err.txt
check "through a link: exit 0" [ $? = 0 ]
check "the link stays a link" [ -L link.png ]
check "its target is the new PNG" is_png real/x.png
check "no temporary left beside the target" [ "$(ls -A real)" = x.png ]

# A link to /proc/self/fd/1 is followed to standard output, not replaced.
fresh; ln -s /proc/self/fd/1 out.link
"$promyk" render --w 8 -o a.png --traces out.link --trace-pixel 3,4 >out.txt 2>err.txt
check "link to fd 1: exit 0" [ $? = 0 ]
check "link to fd 1: still a link" [ -L out.link ]
check "link to fd 1: the trace went to stdout" grep -q '"schema":1' out.txt

# 3. Devices are written through, never replaced. As root (CI) only devices
# made here with mknod are written: a promyk with the bug this tests for
# would replace the real /dev/null or /dev/full with a regular file.
if [ "$(id -u)" = 0 ]; then
    fresh; mknod null c 1 3; mknod full c 1 7
    "$promyk" render --w 8 -o null --traces null >out.txt 2>err.txt
    check "one device twice is the same file" [ $? = 2 ]
    "$promyk" render --w 8 -o a.png --traces null >out.txt 2>err.txt
    check "--traces to a null device: exit 0" [ $? = 0 ]
    check "the null device is still a device" [ -c null ]
    check "null device: the image is there" is_png a.png
    "$promyk" render --w 8 -o null >out.txt 2>err.txt
    check "-o a null device: exit 0" [ $? = 0 ]
    check "-o null device: still a device" [ -c null ]
    rm -f a.png
    "$promyk" render --w 8 -o a.png --traces full >out.txt 2>err.txt
    check "--traces to a full device: exit 4" [ $? = 4 ]
    check "full device: the errno text" grep -q "cannot write full: No space left on device" err.txt
    check "full device: image not committed, no temporaries" only null full out.txt err.txt
else
    fresh
    "$promyk" render --w 8 -o /dev/null --traces - >out.txt 2>err.txt
    check "-o /dev/null: exit 0 (PNG for an extensionless device)" [ $? = 0 ]
    "$promyk" render --w 8 -o /dev/null --traces /dev/null >out.txt 2>err.txt
    check "/dev/null twice is the same file" [ $? = 2 ]
    "$promyk" render --w 8 -o a.png --traces /dev/full >out.txt 2>err.txt
    check "/dev/full: exit 4" [ $? = 4 ]
    check "/dev/full: the errno text" grep -q "No space left on device" err.txt
    check "/dev/full: nothing committed" only out.txt err.txt
fi

# 4. A FIFO is written as produced, and stays a FIFO.
fresh; mkfifo f
# Timeouts, so that a promyk that replaced the FIFO cannot hang the test.
timeout 10 cat f >got.txt &
reader=$!
timeout 10 "$promyk" render --w 8 -o a.png --traces f --trace-pixel 1,1 --trace-pixel 2,2 >out.txt 2>err.txt
check "FIFO: exit 0" [ $? = 0 ]
wait $reader
check "FIFO: the reader got 2 traces" [ "$(wc -l <got.txt)" = 2 ]
check "FIFO: still a FIFO" [ -p f ]
check "FIFO: no temporary" only f got.txt a.png out.txt err.txt

# 5. The trace size guard: regular files (standard output redirected to one
# included), not pipes.
fresh
"$promyk" render --w 2048 --traces - >t.jsonl 2>err.txt
check "guard on stdout redirected to a file: exit 2" [ $? = 2 ]
check "guard: says --force" grep -q -- "--force" err.txt
check "guard: nothing written" only t.jsonl err.txt
"$promyk" render --w 2048 -o a.png --traces - --trace-region 0,0,0,2047 2>err.txt | wc -l >lines.txt
check "no guard for a pipe; a row of 2048 traces" [ "$(tr -d ' ' <lines.txt)" = 2048 ]

# 6. PNG to standard output, and plain PGM.
fresh
"$promyk" render --w 8 -o - >img.png 2>err.txt
check "-o - to a file: a PNG" is_png img.png
"$promyk" render --w 4 -o p.pgm --plain >out.txt 2>err.txt
check "--plain: P2" [ "$(head -n 1 p.pgm)" = P2 ]
"$promyk" render --w 4 -o b.pgm >out.txt 2>err.txt
check ".pgm: P5" [ "$(head -n 1 b.pgm)" = P5 ]

echo "outputs test: $passed passed, $failed failed"
[ $failed = 0 ]
