#!/usr/bin/env bash
# Hostile input on the lesson surfaces: a teacher's folder (--lessons), a
# student's answer file (--answers) and --dump. Each case must end with the
# documented exit code (3 a bad input file, naming it; 4 an output not
# written), within seconds, with no raw control character on the terminal.
# usage: hostile_lessons_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2 here=$(cd "$(dirname "$0")" && pwd)
. "$(dirname "$0")/lib.sh"

# expect NAME CODE PATTERN -- ARGS...: exit CODE within 20 s (PROMYK_TEST_SECONDS:
# a sanitizer build runs about ten times slower), stderr matching
# PATTERN (grep -E), and no control character but newline and tab in the output.
expect() {
  local name=$1 want=$2 pattern=$3
  shift 4
  timeout "${PROMYK_TEST_SECONDS:-20}" "$promyk" "$@" >out.txt 2>err.txt </dev/null
  local code=$?
  if [ "$code" != "$want" ]; then bad "$name: exit $code, expected $want; $(head -c 300 err.txt)"; return; fi
  # messages are wrapped to 80 columns (continuation lines indented by 4): join them
  sed ':a;N;$!ba;s/\n    / /g' err.txt >joined.txt
  if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" joined.txt; then bad "$name: stderr lacks /$pattern/: $(head -c 300 err.txt)"; return; fi
  if cat out.txt err.txt | LC_ALL=C tr -d '\n\t' | LC_ALL=C grep -qaP '[\x00-\x1f\x7f]'; then
    bad "$name: a raw control character reached the terminal"; return
  fi
  ok
}

header=$'---\nname: x\ntitle: T\nsummary: S\n---\n'
# lesson NAME: a folder NAME with en/01-x.md (standard input) and its Polish copy.
lesson() { rm -rf "$1" && mkdir -p "$1/en" "$1/pl" && cat >"$1/en/01-x.md" && cp "$1/en/01-x.md" "$1/pl/01-x.md"; }
long() { head -c "$1" /dev/zero | tr '\0' "$2"; }

# --- a teacher's folder -----------------------------------------------------
{ printf '%s## [a] ' "$header"; long 2000000 a; echo; } | lesson long_heading
expect "2 MB step heading" 0 "" -- lesson x --lessons long_heading --lang en
{ printf '%s## [a] A\n\n::: pixel\n{' "$header"; long 2000000 a; printf '}\n:::\n'; } | lesson long_placeholder
expect "2 MB placeholder" 1 "long_placeholder/en/01-x.md:9: malformed placeholder" -- lesson --check --lessons long_placeholder --lang en
printf -- '---\nname: %s\ntitle: T\nsummary: S\n---\n## [a] A\n\nx\n' "$(long 2000000 a)" | lesson long_name
expect "2 MB name" 0 "" -- lesson --list --lessons long_name --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\npixels: 1,%s\n---\n## [a] A\n\nx\n' "$(long 2000000 1)" | lesson long_pixels
expect "2 MB pixel number" 3 "long_pixels/en/01-x.md: line 5: bad value of \"pixels\"" -- lesson x --lessons long_pixels --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\npixels: 99999999999,1\n---\n## [a] A\n\nx\n' | lesson huge_pixel
expect "pixels: 99999999999,1" 3 "huge_pixel/en/01-x.md: line 5: bad value of \"pixels\"" -- lesson x --lessons huge_pixel --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\nw: 4\npixels: 5,1\n---\n## [a] A\n\nx\n' | lesson pixel_outside
expect "pixels outside w" 3 "pixel_outside/en/01-x.md: line 6: bad value of \"pixels\"" -- lesson x --lessons pixel_outside --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\nscene: ..\n---\n## [a] A\n\nx\n' | lesson scene_dots
expect "scene: .." 3 "scene_dots/en/01-x.md: line 5: bad value of \"scene\"" -- lesson x --lessons scene_dots --lang en
{ printf '%s' "$header"; for k in $(seq 100000); do printf '## [s%d] S\n\nx\n' "$k"; done; } | lesson many_steps
expect "100 000 steps" 0 "" -- lesson --check --lessons many_steps --lang en
{ printf '%s## [a] A\n\n::: pixel\n' "$header"; for k in $(seq 100000); do printf '{t} '; done; printf '\n:::\n'; } | lesson many_placeholders
expect "100 000 placeholders" 0 "" -- lesson --check --lessons many_placeholders --lang en
printf '%s## [a] A\n\nhello \0 world\n' "$header" | lesson nul
expect "NUL byte" 3 "nul/en/01-x.md: line 8: .*\\\\u0000" -- lesson x --lessons nul --lang en
printf '%s## [a] A\n\nbad \xff utf\n' "$header" | lesson bad_utf8
expect "invalid UTF-8" 1 "bad_utf8/en/01-x.md:8: .*\\\\xff" -- lesson --check --lessons bad_utf8 --lang en
printf -- '---\nname: x\ntitle: T\x1b[31mred\nsummary: S\n---\n## [a] A\x1b]0;title\x07\n\nprose\x1b[5m\n' | lesson ansi
expect "ANSI escapes in a lesson" 3 "ansi/en/01-x.md: line 3: .*\\\\u001b" -- lesson x --lessons ansi --lang en
expect "ANSI escapes, --check" 1 "ansi/en/01-x.md:3: " -- lesson --check --lessons ansi --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\n\x1b[31mfield: v\n---\n## [a] A\n\nx\n' | lesson ansi_field
expect "ANSI escape in a header field" 1 "ansi_field/en/01-x.md:5: " -- lesson --check --lessons ansi_field --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\n---\n## [a] A\n\n\tx\n' | lesson tab
expect "a tab is fine" 0 "" -- lesson x --lessons tab --lang en
# The same name in two files of one language: which one would run?
lesson twice <tab/en/01-x.md && cp twice/en/01-x.md twice/en/02-y.md && cp twice/pl/01-x.md twice/pl/02-y.md
expect "one name, two files" 3 "twice/en/0[12]-[xy].md.*twice/en/0[12]-[xy].md" -- lesson x --lessons twice --lang en
expect "one name, two files, --check" 1 "twice/en/02-y.md:2: " -- lesson --check --lessons twice --lang en
# A worksheet of 100 000 pixels (a blank each, and the answer file's form).
{ printf -- '---\nname: x\ntitle: T\nsummary: S\nw: 400\npixels:'; for i in $(seq 0 399); do for j in $(seq 0 249); do printf ' %d,%d' "$i" "$j"; done; done
  printf -- '\n---\n## [a] A\n\n= t delta\n\n::: pixel\n{t}\n:::\n'; } | lesson many_pixels
expect "a worksheet of 100 000 pixels" 0 "" -- lesson x --lessons many_pixels --lang en --worksheet --key
# --check reads the scene a lesson names: a broken one is reported at the lesson's scene: line.
printf -- '---\nname: x\ntitle: T\nsummary: S\nscene: b.json\n---\n## [a] A\n\nx\n' | lesson broken_scene
mkdir -p broken_scene/scenes && echo '{"spheres": [' >broken_scene/scenes/b.json
expect "a broken scene, --check" 1 "broken_scene/en/01-x.md:5: the scene \"b.json\" cannot be read: broken_scene/scenes/b.json: line 2" -- lesson --check --lessons broken_scene --lang en
printf -- '---\nname: x\ntitle: T\nsummary: S\nscene: none.json\n---\n## [a] A\n\nx\n' | lesson missing_scene
expect "a missing scene, --check" 1 "missing_scene/en/01-x.md:5: the scene \"none.json\"" -- lesson --check --lessons missing_scene --lang en
: | lesson empty_file
expect "an empty lesson file" 1 "empty_file/en/01-x.md:1: the lesson has no step" -- lesson --check --lessons empty_file --lang en
# A folder EN/ (or de/) is not read: --check says so rather than pass in silence.
rm -rf upper && mkdir -p upper/EN && cp tab/en/01-x.md upper/EN/
expect "a folder EN/, --check" 1 "upper/EN/01-x.md:1: this file is not read" -- lesson --check --lessons upper --lang en
# A huge file in the folder (lessons are read when the folder is opened): refused, not read into memory.
rm -rf huge && mkdir -p huge/scenes && head -c 20000000 /dev/zero >huge/scenes/big.json
expect "a 20 MB file in scenes/" 3 "huge/scenes/big.json: the file is larger than the limit" -- lesson --list --lessons huge
rm -rf loop && mkdir -p loop/en && ln -s b.md loop/en/a.md && ln -s a.md loop/en/b.md
expect "symlink loop" 3 "loop/en/[ab].md: .*symbolic links" -- lesson --list --lessons loop
rm -rf fifo && mkdir -p fifo/en && mkfifo fifo/en/01-x.md
expect "a FIFO is skipped" 0 "" -- lesson --list --lessons fifo

# --- a student's answer file -----------------------------------------------
python3 -c "print('{\"C\": ' + '[' * 100000 + ']' * 100000 + '}')" >deep.json
expect "JSON nested 100 000 deep" 3 "deep.json: line 1: JSON nested deeper" -- lesson sphere --lang en --answers deep.json
printf '{"C": 6.4, "C": 6.5}' >twice.json
# A key twice makes it unreadable; with nothing else in the file, the file is refused.
expect "a JSON key twice" 3 "twice.json: /C: .*more than once.*no answer in the file can be read" -- lesson sphere --lang en --answers twice.json
"$promyk" trace --format json --pixel 3,4 --scene "$here/scenes/far_pane.json" >far.json 2>/dev/null
# 10^5 pixel headings in a 32768 × 32768 pane (each is traced and checked).
python3 -c "print('\\n'.join('[%d,%d]\\nC = 1' % (k // 1000, k % 1000) for k in range(100000)))" >headings.txt
expect "100 000 pixel headings" 1 "" -- lesson sphere --lang en --w 32768 --answers headings.txt
# A NUL in a value: the message shows it escaped and goes on past it.
printf 'C = 6\0.4\n' >nul.txt
expect "a NUL in an answer" 3 'nul.txt: line 1: "6\\u0000\.4" is not a number' -- lesson sphere --lang en --answers nul.txt
printf '{"pixel": [3, 4], "steps": []}' >pixel_array.json
expect "a trace whose pixel is not an object" 3 "pixel_array.json: /pixel: " -- lesson sphere --lang en --answers pixel_array.json
expect "a trace of another scene" 3 "far.json: /scene_hash: the trace is of another scene \\(\"far pane\"\\)" -- lesson sphere --lang en --pixel 3,4 --answers far.json
expect "a trace with non-finite points" 0 "" -- lesson sphere --lang en --pixel 3,4 --scene "$here/scenes/far_pane.json" --answers far.json
expect "answers: a folder" 3 "\\.: .*folder" -- lesson sphere --lang en --answers .

# --- --dump ------------------------------------------------------------------
expect "--dump: a name with ESC" 0 "\\\\u001b" -- lesson --dump $'d\x1b[31m'
echo x >file
expect "--dump under a file" 4 "file/sub" -- lesson --dump file/sub
expect "--dump into /dev/full" 4 "/dev/full" -- lesson --dump /dev/full
# A failure part way (here: scenes/ is a file) leaves none of the files written before it.
mkdir -p partial && echo x >partial/scenes
expect "--dump failing part way" 4 "partial/scenes" -- lesson --dump partial
[ -z "$(find partial -type f ! -path partial/scenes)" ] && ok || bad "--dump failing part way left $(find partial -type f | head -3)"

# Standard output that cannot be written: exit 4 (141 when the reader quits), never 0.
for args in "sphere --lang en" "sphere --lang en --worksheet" "--list" "--check"; do
  # shellcheck disable=SC2086
  "$promyk" lesson $args >/dev/full 2>err.txt; code=$?
  [ "$code" = 4 ] && grep -q "standard output" err.txt && ok || bad "lesson $args >/dev/full: exit $code"
done
sed -i 's/^C = .*/C = 6.4/' nul.txt
"$promyk" lesson sphere --lang en --answers nul.txt >/dev/full 2>err.txt; code=$?
[ "$code" = 4 ] && ok || bad "lesson --answers >/dev/full: exit $code"
# (megabytes of output, more than a pipe holds, so that the reader surely quits first)
"$promyk" lesson x --lessons many_pixels --lang en | head -c 10 >/dev/null; code=${PIPESTATUS[0]}
[ "$code" = 141 ] && ok || bad "lesson | head -c 10: exit $code"

summary
