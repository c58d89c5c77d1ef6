#!/usr/bin/env bash
# Messages never print raw control characters that came from the input: a
# scene key holding an escape sequence, a file name holding a newline or an
# escape, an unknown command with one. Each is shown escaped (\u001b, \n).
# usage: escapes_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
passed=0 failed=0
esc=$(printf '\033')
check() {  # check NAME EXPECTED-EXIT FIXED-STRING-EXPECTED ARGS...
  local name=$1 expected=$2 text=$3; shift 3
  "$promyk" "$@" >out.txt 2>err.txt
  local code=$?
  # a message is wrapped to 80 columns (continuation lines indented by 4): join it
  local joined
  joined=$(sed ':a;N;$!ba;s/\n    / /g' err.txt)
  if [ "$code" = "$expected" ] && ! grep -q "$esc" err.txt && [ "$(wc -l <err.txt)" -le 6 ] &&
     printf '%s' "$joined" | grep -qF -- "$text"; then
    passed=$((passed + 1))
  else
    echo "$name: exit $code (expected $expected); stderr:"; od -c err.txt | head -5; failed=$((failed + 1))
  fi
}
printf '%s' '{"spheres": [{"S": [0, 0, 3.2], "r": 1.1}], "lights": [{"L": [1, 1, 1]}], "\u001b[31mEVIL": 1}' > evil_key.json
check "key with ESC" 3 '/\u001b[31mEVIL' trace --scene evil_key.json
newline_name=$'bad\nname.json'
check "missing file with a newline in its name" 3 'bad\nname.json' trace --scene "$newline_name"
cp evil_key.json "$newline_name"
check "file with a newline and a key with ESC" 3 'bad\nname.json: /\u001b[31mEVIL' trace --scene "$newline_name"
check "command with ESC" 2 "unknown command '\\u001b[2J'" $'\033[2J'
check "option value with ESC" 2 "got '\\u001b[1m8'" trace --w $'\033[1m8'
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
