#!/usr/bin/env bash
# The fuzz step of CI: builds the fuzz targets of the asan preset (clang,
# libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer; CI has built the
# whole preset and passes --no-build), then runs each target over its seed corpus
# (tests/fuzz/corpus/TARGET/) and a fixed number of new executions from a
# fixed seed (-runs=N -seed=1), so a run is repeatable and a chance finding
# cannot block unrelated work. Fails on any crash, leak, undefined behaviour,
# timeout or out-of-memory, and prints the reproducer's path.
#
#   tests/fuzz/run.sh [--no-build] [TARGET ...]     (TARGET: scene, lesson, ...)
#   tests/fuzz/run.sh --list                        the targets, a line each
#
# PROMYK_FUZZ_SCALE multiplies every target's executions (default 1; 0 runs
# the corpus alone); PROMYK_FUZZ_JOBS how many targets run at once (default:
# the processors). New inputs go to a scratch folder, never into the corpus:
# build/asan/fuzz-runs/TARGET/ (PROMYK_FUZZ_OUT for another folder; the
# targets are taken from PROMYK_FUZZ_BIN, default build/asan, which
# run_sh_test.sh points at stand-ins to check the verdicts).
# Reproduce a finding: build/asan/fuzz_TARGET REPRODUCER
# Explore longer: build/asan/fuzz_TARGET -dict=tests/fuzz/TARGET.dict \
#   -max_total_time=900 NEW_DIR tests/fuzz/corpus/TARGET
set -euo pipefail
cd "$(dirname "$0")/../.."

build=1
list=0
if [ "${1:-}" = "--no-build" ]; then
  build=0
  shift
elif [ "${1:-}" = "--list" ]; then
  list=1
  shift
fi

# target  new executions  longest input (bytes)  least coverage (half of
# the edges a run reached when measured: far fewer means the core lost
# libFuzzer's counters, src/CMakeLists.txt)
# (measured on a 2-core machine, unoptimised as the asan preset is: 141 s
# in all one after another, corpus included, 77 s two at a time; 54 s
# optimised, in the fuzz build it replaced)
table=(
  "scene       11000  16384  4500"
  "lesson       3000  20000  2700"
  "answers      6000   8192  5800"
  "diff         7500   8192  4700"
  "trace        5000  16384  2500"
  "cli_values  30000     64   500"
  "accuracy     4000  16384  1400"
)
wanted=("$@")
scale="${PROMYK_FUZZ_SCALE:-1}"

names=()
for row in "${table[@]}"; do
  read -r name _ <<<"$row"
  names+=("$name")
done
if [ "$list" = 1 ]; then  # the targets CI runs, a line each (tests/fuzz/CMakeLists.txt checks them)
  printf '%s\n' "${names[@]}"
  exit 0
fi
for name in "${wanted[@]}"; do
  if [[ ! " ${names[*]} " == *" $name "* ]]; then
    echo "run.sh: no fuzz target '$name'; the targets: ${names[*]}" >&2
    exit 2
  fi
done
jobs="${PROMYK_FUZZ_JOBS:-$(nproc)}"
if ! [[ "$jobs" =~ ^[1-9][0-9]*$ ]]; then
  echo "run.sh: PROMYK_FUZZ_JOBS must be a whole number from 1 up, not '$jobs'" >&2
  exit 2
fi
if [ "$build" = 1 ]; then
  echo "== the fuzz targets (preset asan)"
  cmake --preset asan -DPROMYK_WEB=OFF >/dev/null
  cmake --build --preset asan --target "${names[@]/#/fuzz_}"
fi

bin="${PROMYK_FUZZ_BIN:-build/asan}"
out="${PROMYK_FUZZ_OUT:-build/asan/fuzz-runs}"
mkdir -p "$out"

# One target's run; what it found goes to $out/NAME/verdict, the lines to
# print, the first "fuzz_NAME: ok, ..." where it passed.
fuzz_one() {
  local name=$1 runs=$2 max_len=$3 least_cov=$4
  local log="$out/$name/log.txt" verdict="$out/$name/verdict" start=$SECONDS status=0 last cov reproducer
  # -runs counts the new executions after the corpus is read; the corpus is
  # read from tests/fuzz/corpus/NAME and what is new goes to the scratch folder.
  "$bin/fuzz_$name" -seed=1 -runs="$runs" -max_len="$max_len" -rss_limit_mb=2048 -timeout=20 \
    -dict="tests/fuzz/$name.dict" -artifact_prefix="$out/$name/" -print_final_stats=1 \
    "$out/$name/new" "tests/fuzz/corpus/$name" >"$log" 2>&1 || status=$?
  last=$(grep -E '^#[0-9]+.*(cov|DONE)' "$log" | tail -1 || true)
  if [ "$status" -ne 0 ]; then
    {
      echo "fuzz_$name: FAILED (exit $status) after $((SECONDS - start)) s; the end of $log:"
      tail -40 "$log" | sed 's/^/  /'
      reproducer=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
      if [ -n "$reproducer" ]; then
        echo "fuzz_$name: reproducer: $reproducer"
        echo "fuzz_$name: rerun with: $bin/fuzz_$name $reproducer"
      fi
    } >"$verdict"
  elif cov=$(sed -n 's/.*DONE *cov: \([0-9]*\).*/\1/p' "$log" | tail -1) && [ "${cov:-0}" -lt "$least_cov" ]; then
    echo "fuzz_$name: FAILED: coverage ${cov:-none} edges, expected at least $least_cov: $last" >"$verdict"
  else
    echo "fuzz_$name: ok, $runs new executions in $((SECONDS - start)) s: $last" >"$verdict"
  fi
}

# The targets run side by side, as many at once as there are processors
# (PROMYK_FUZZ_JOBS to choose): each is one process with its own seed and
# count, so what it does is the same as alone; only its seconds grow on a
# busy machine. Their verdicts are printed in the table's order.
ran=()
for row in "${table[@]}"; do
  read -r name runs max_len least_cov <<<"$row"
  if [ ${#wanted[@]} -gt 0 ] && [[ ! " ${wanted[*]} " == *" $name "* ]]; then continue; fi
  # A free slot: wait for a run to end (none running: go on, never spin).
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ] && [ -n "$(jobs -rp)" ]; do wait -n || true; done
  rm -rf "${out:?}/$name"  # the last run's, of this target only
  mkdir -p "$out/$name/new"
  fuzz_one "$name" "$((runs * scale))" "$max_len" "$least_cov" &
  ran+=("$name")
done
wait
failed=0
for name in "${ran[@]}"; do
  if [ -f "$out/$name/verdict" ]; then
    cat "$out/$name/verdict"
  else
    echo "fuzz_$name: FAILED: its run ended without a verdict (see $out/$name/)"
  fi
  if ! head -n 1 "$out/$name/verdict" 2>/dev/null | grep -q "^fuzz_$name: ok, "; then failed=1; fi
done
exit "$failed"
