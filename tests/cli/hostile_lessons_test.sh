#!/usr/bin/env bash
# Hostile input on the lesson surfaces: a teacher's folder (--lessons), a
# student's answer file (--answers) and --dump. Each case must end with the
# documented exit code (3 a bad input file, naming it; 4 an output not
# written), within seconds, with no raw control character on the terminal.
# usage: hostile_lessons_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
export LANG=C.UTF-8 LC_ALL= LC_MESSAGES=
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { echo "FAIL: $*"; failed=$((failed + 1)); }

# expect NAME CODE PATTERN -- ARGS...: exit CODE within 10 s, stderr matching
# PATTERN (grep -E), and no control character but newline and tab in the output.
expect() {
  local name=$1 want=$2 pattern=$3
  shift 4
  timeout 10 "$promyk" "$@" >out.txt 2>err.txt </dev/null
  local code=$?
  if [ "$code" != "$want" ]; then bad "$name: exit $code, expected $want; $(head -c 300 err.txt)"; return; fi
  if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" err.txt; then bad "$name: stderr lacks /$pattern/: $(head -c 300 err.txt)"; return; fi
  if cat out.txt err.txt | LC_ALL=C tr -d '\n\t' | LC_ALL=C grep -qaP '[\x00-\x1f\x7f]'; then
    bad "$name: a raw control character reached the terminal"; return
  fi
  ok
}

header=$'---\nname: x\ntitle: T\nsummary: S\n---\n'
# lesson NAME: a folder NAME with en/01-x.md (standard input) and its Polish copy.
lesson() { rm -rf "$1" && mkdir -p "$1/en" "$1/pl" && cat >"$1/en/01-x.md" && cp "$1/en/01-x.md" "$1/pl/01-x.md"; }
long() { head -c "$1" /dev/zero | tr '\0' "$2"; }

# --- a student's answer file -----------------------------------------------
python3 -c "print('{\"C\": ' + '[' * 100000 + ']' * 100000 + '}')" >deep.json
expect "JSON nested 100 000 deep" 3 "deep.json: line 1: JSON nested deeper" -- lesson sphere --lang en --answers deep.json
printf '{"C": 6.4, "C": 6.5}' >twice.json
expect "a JSON key twice" 3 "twice.json: /C: .*twice|twice.json: /C: .*already" -- lesson sphere --lang en --answers twice.json
"$promyk" trace --format json --pixel 3,4 --scene "$here/scenes/far_pane.json" >far.json 2>/dev/null
expect "a trace with non-finite points" 0 "" -- lesson sphere --lang en --pixel 3,4 --scene "$here/scenes/far_pane.json" --answers far.json


echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
