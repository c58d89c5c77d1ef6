#!/usr/bin/env bash
# Outputs into a folder promyk may not write (issue 19, hostile runs): render
# -o, render --traces, render --map, lesson --dump, export and bench accuracy
# --json give exit 4, a message naming the path, and leave no file (not the
# image either, when only its traces could not be written).
#
# CI runs as root, which writes anywhere: as root the cases run as an
# unprivileged user (uid and gid 65534, via setpriv), with promyk and its
# inputs copied into a temporary folder that user can read. As another user
# they run as that user. When no such run is possible (root without setpriv,
# or a user who can write into a read-only folder anyway) the test is
# skipped (exit 77, CTest's SKIP_RETURN_CODE), not passed.
# usage: readonly_dir_test.sh PROMYK WORKDIR
set -u
promyk=$1 dir=$2
scenes=$(cd "$(dirname "$0")/../../lessons/scenes" && pwd)
. "$(dirname "$0")/lib.sh"

# A folder every user can enter, outside the build tree (whose parents an
# unprivileged user may not be able to traverse).
top=$(mktemp -d /tmp/promyk_readonly.XXXXXX) || exit 1
trap 'chmod -R u+w "$top" 2>/dev/null; rm -rf "$top"' EXIT
chmod 755 "$top"
cp "$promyk" "$top/promyk" && chmod 755 "$top/promyk" || exit 1
cp "$scenes/floor.json" "$top/scene.json" && chmod 644 "$top/scene.json" || exit 1
mkdir "$top/ro" "$top/rw" && chmod 555 "$top/ro" && chmod 777 "$top/rw" || exit 1

as_user=()
if [ "$(id -u)" = 0 ]; then
  if ! command -v setpriv >/dev/null; then
    echo "SKIPPED: running as root and setpriv is not installed: no unprivileged user to run as"
    exit 77
  fi
  as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups --)
fi
if (cd "$top/rw" && "${as_user[@]}" sh -c 'echo x > ../ro/probe') 2>/dev/null; then
  echo "SKIPPED: $(id -un) (run as ${as_user[*]:-itself}) can write into a folder of mode 555"
  exit 77
fi

# denied NAME PATH ARGS...: promyk ARGS run in rw/ as the user: exit 4, the
# message names PATH, and ro/ and rw/ stay empty.
denied() {
  local name=$1 path=$2
  shift 2
  (cd "$top/rw" && "${as_user[@]}" "$top/promyk" "$@") >out.txt 2>err.txt
  local code=$?
  local before=$failed
  [ "$code" = 4 ] || bad "$name: exit $code, expected 4: $(cat err.txt)"
  grep -qF "$path" err.txt || bad "$name: the message does not name $path: $(cat err.txt)"
  [ -z "$(ls -A "$top/ro")" ] || bad "$name: left in the read-only folder: $(ls -A "$top/ro")"
  [ -z "$(ls -A "$top/rw")" ] || bad "$name: left in the working folder: $(ls -A "$top/rw")"
  rm -rf "${top:?}/rw/"* "${top:?}/rw/".[!.]* 2>/dev/null
  [ "$failed" = "$before" ] && ok
}

denied "render -o" ../ro/x.png render --scene ../scene.json --w 8 -o ../ro/x.png
denied "render -o .ppm" ../ro/x.ppm render --scene ../scene.json --w 8 -o ../ro/x.ppm
denied "render --traces" ../ro/t.jsonl render --scene ../scene.json --w 8 -o x.png --traces ../ro/t.jsonl --trace-pixel 1,1
denied "render -o with --traces" ../ro/x.png render --scene ../scene.json --w 8 -o ../ro/x.png --traces t.jsonl --trace-pixel 1,1
denied "render --map" ../ro/m.png render --scene ../scene.json --w 8 --map branch -o ../ro/m.png
denied "lesson --dump" ../ro/lessons lesson --dump ../ro/lessons
denied "lesson --dump into a subfolder" ../ro/a/b lesson --dump ../ro/a/b
denied "export" ../ro/x.html export --scene ../scene.json --w 8 -o ../ro/x.html
denied "bench accuracy --json" ../ro/a.json bench accuracy --w 8 --repetitions 1 --spp 1 --json ../ro/a.json
# The read-only folder as the working folder: promyk's default output names.
(cd "$top/ro" && "${as_user[@]}" "$top/promyk" render --scene ../scene.json --w 8) >out.txt 2>err.txt
code=$?
if [ "$code" = 4 ] && grep -q "promyk.png" err.txt && [ -z "$(ls -A "$top/ro")" ]; then ok
else bad "render's default promyk.png in a read-only folder: exit $code: $(cat err.txt)"; fi

summary
