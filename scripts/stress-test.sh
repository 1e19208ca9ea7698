#!/usr/bin/env bash
# `npm run stress-test`: the whole `npm test` on a busy machine, with busy CPU loops alongside (two by
# default, as many as a 2-core machine has cores), to show that no test's outcome depends on speed.
# Exits with npm test's status; the loops end with it, however it ends.
#
#   bash scripts/stress-test.sh            two busy loops
#   STRESS_LOOPS=4 bash scripts/stress-test.sh
set -uo pipefail
cd "$(dirname "$0")/.."
loops=${STRESS_LOOPS:-2}
case "$loops" in ''|*[!0-9]*) echo "stress-test: STRESS_LOOPS must be a whole number, not '$loops'" >&2; exit 2 ;; esac

pids=()
stop_loops() { [ ${#pids[@]} -eq 0 ] || kill "${pids[@]}" 2>/dev/null; wait "${pids[@]}" 2>/dev/null; pids=(); }
trap stop_loops EXIT
trap 'exit 130' INT TERM
for ((i = 0; i < loops; i++)); do
  bash -c 'while :; do :; done' &
  pids+=($!)
done
echo "stress-test: $loops busy loops running (pids ${pids[*]}); npm test starts"
started=$SECONDS
npm test
status=$?
echo "stress-test: npm test exited $status after $((SECONDS - started)) s with $loops busy loops alongside"
exit $status
