#!/usr/bin/env bash
# tests/fuzz/run.sh, the fuzz step of CI, before it runs a fuzzer: it runs
# every target the build makes (its table against tests/fuzz/CMakeLists.txt's
# list, given as arguments), and it refuses a target or a job count it cannot
# honour (exit 2, saying what is wrong) instead of running less than asked.
#   run_sh_test.sh RUN_SH TARGET...
set -uo pipefail
run_sh=$1
shift
failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

listed=$(bash "$run_sh" --list | sort)
built=$(printf '%s\n' "$@" | sort)
[ "$listed" = "$built" ] || fail "run.sh runs [$(echo $listed)], the build makes [$(echo $built)]"

# expect_refusal WHAT ENV... -- ARGS...: exit 2 and a message naming WHAT.
expect_refusal() {
  local what=$1 err status=0
  shift
  local env=()
  while [ "$1" != "--" ]; do env+=("$1"); shift; done
  shift
  err=$(env "${env[@]}" bash "$run_sh" "$@" 2>&1 >/dev/null) || status=$?
  [ "$status" = 2 ] || fail "run.sh $* (${env[*]}): exit $status, expected 2"
  [[ "$err" == *"$what"* ]] || fail "run.sh $* (${env[*]}): said '$err', expected it to name '$what'"
}
expect_refusal "no fuzz target 'nosuch'" -- --no-build nosuch
expect_refusal "no fuzz target 'scen'" -- --no-build scene scen
expect_refusal "not '0'" PROMYK_FUZZ_JOBS=0 -- --no-build scene
expect_refusal "not 'two'" PROMYK_FUZZ_JOBS=two -- --no-build scene
expect_refusal "not '-1'" PROMYK_FUZZ_JOBS=-1 -- --no-build scene

[ "$failed" = 0 ] && echo "run.sh: every target listed, bad targets and job counts refused"
exit "$failed"
