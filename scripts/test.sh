#!/usr/bin/env bash
# `npm test`: set-up, then every suite (native C++, wasm build, Node, browser in Chromium, then in Firefox and WebKit). Each suite runs even if
# an earlier one failed; the last line sums them up and the exit status is non-zero if any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
bash scripts/setup.sh || { echo "setup failed"; exit 1; }

logs=build/test-logs
rm -rf "$logs"  # a suite that did not run this time must not be summed from an earlier run's report
mkdir -p "$logs"
status=0
run() {  # run NAME COMMAND...: tee output into build/test-logs/NAME.log, its seconds into times.tsv
  local name=$1; shift
  echo "=== $name"
  local started=$SECONDS
  "$@" 2>&1 | tee "$logs/$name.log"
  local rc=${PIPESTATUS[0]}
  printf '%s\t%s\n' "$name" $((SECONDS - started)) >> "$logs/times.tsv"
  [ "$rc" -eq 0 ] || { echo "=== $name FAILED (exit $rc)"; status=1; }
  return 0
}

run native bash scripts/test-native.sh
run wasm-build bash scripts/build-wasm.sh
if [ -f dist/conecurl-engine.wasm ]; then
  run node node --test --test-reporter=spec --test-reporter-destination=stdout \
    --test-reporter=tap --test-reporter-destination="$logs/node.tap" tests/node/
  PLAYWRIGHT_JSON_OUTPUT_NAME="$logs/browser.json" run browser npx playwright test --reporter=list,json
  # The same journeys in Firefox and WebKit (tests/engines/), one engine after the other.
  run engines node --test --test-concurrency=1 --test-reporter=spec --test-reporter-destination=stdout \
    --test-reporter=tap --test-reporter-destination="$logs/engines.tap" tests/engines/
else
  echo "=== node and browser suites skipped: the wasm build failed"; status=1
fi

node scripts/summarize-tests.mjs "$logs" || status=1
exit $status
