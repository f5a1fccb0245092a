#!/usr/bin/env bash
# Runs each libFuzzer harness of tests/fuzz for SECONDS, one after the other (niced), from the
# committed corpus tests/fuzz/corpus/<harness> (the scene harness also from every compare/scenes
# file). New inputs go to BUILD/fuzz-corpus/<harness> (merge the useful ones into the committed
# corpus with `-merge=1`); crashes, leaks, UB and inputs slower than 2 s go to BUILD/fuzz-findings/
# and fail the run. libFuzzer's -timeout is wall time: on a loaded machine an input can be starved
# past it, so a timeout input is run again and counts only if it takes > 2 s of CPU time; if not,
# fuzzing resumes for the time left.  Usage: scripts/run-fuzzers.sh BUILD SECONDS [HARNESS...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=$1 seconds=$2
shift 2
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(scene hcs_args tsv_roundtrip checkpoint)
findings="$build/fuzz-findings"
mkdir -p "$findings"
status=0
for h in "${harnesses[@]}"; do
  bin="$build/tests/fuzz/fuzz_$h" work="$build/fuzz-corpus/$h"
  mkdir -p "$work"
  seeds=("tests/fuzz/corpus/$h")
  [ "$h" = scene ] && seeds+=(compare/scenes)
  end=$((SECONDS + seconds)) run=0
  while [ $SECONDS -lt $end ]; do
    run=$((run + 1))
    log="$findings/$h-$run.log"
    echo "fuzz $h: $((end - SECONDS)) s left, log $log"
    if nice -n 10 "$bin" -max_total_time=$((end - SECONDS)) -timeout=2 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$findings/$h-" "$work" "${seeds[@]}" > "$log" 2>&1; then
      grep -E "^#[0-9]+.*cov:" "$log" | tail -n 1 || true
      continue
    fi
    unit=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -n 1)
    if grep -q "libFuzzer: timeout" "$log" && [ -n "$unit" ]; then
      cpu=$( { TIMEFORMAT='%U %S'; time "$bin" -timeout=60 "$unit" > /dev/null 2>&1; } 2>&1 | awk '{print $1 + $2}')
      if awk -v c="$cpu" 'BEGIN { exit !(c < 2) }'; then
        echo "fuzz $h: timeout not reproduced ($cpu s CPU on replay: machine load), resuming"
        mv "$unit" "$unit.not-reproduced"
        continue
      fi
    fi
    echo "fuzz $h: FINDING $unit (see $log)"
    status=1
    break
  done
  grep -h "stat::number_of_executed_units" "$findings/$h"-*.log | awk -v h="$h" '{n += $2} END {print "fuzz " h ": " n " executions"}'
done
exit $status
