#!/usr/bin/env bash
# The only way reference images change: rebuilds, rewrites every screenshot reference from the
# current renderer, and lists them. Open each PNG and look at it before committing. Test files given as
# arguments (tests/browser/viewer.spec.js) limit it to their reference images; `tests/engines` (or
# tests/engines/firefox.test.mjs) rewrites only the cross-engine suite's, one folder an engine.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
bash scripts/setup.sh
bash scripts/build-wasm.sh
browser=() engines=()
for arg in "$@"; do
  case "$arg" in
    tests/engines/*.test.mjs) engines+=("$arg") ;;
    tests/engines|tests/engines/) engines+=(tests/engines/firefox.test.mjs tests/engines/webkit.test.mjs) ;;
    *) browser+=("$arg") ;;
  esac
done
if [ $# -eq 0 ]; then engines=(tests/engines/firefox.test.mjs tests/engines/webkit.test.mjs); fi
if [ $# -eq 0 ] || [ ${#browser[@]} -gt 0 ]; then
  npx playwright test "${browser[@]}" --update-snapshots=all --grep "reference image"
fi
if [ ${#engines[@]} -gt 0 ]; then
  CONECURL_UPDATE_REFERENCES=1 node --test --test-concurrency=1 --test-name-pattern="reference images" "${engines[@]}"
fi
echo "Rewritten references (look at each one before committing):"
ls -1 tests/browser/references/*.png tests/engines/references/*/*.png
