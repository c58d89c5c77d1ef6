# What the CLI test scripts share; each sources it after `promyk=$1 dir=$2`:
#   . "$(dirname "$0")/lib.sh"
# It empties and enters the work folder, makes promyk speak English whatever
# the machine's locale, and keeps the count that `summary` prints last in the
# form CTest's log readers know ("N passed, M failed") and returns as status.
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
export LANG=C.UTF-8 LC_ALL= LC_MESSAGES=
passed=0 failed=0
ok() { passed=$((passed + 1)); }
bad() { echo "FAIL: $*"; failed=$((failed + 1)); }
summary() {
  echo "$passed passed, $failed failed"
  [ "$failed" = 0 ]
}
