#!/usr/bin/env bash
# The only way reference images change: rebuilds, rewrites every screenshot reference from the
# current renderer, and lists them. Open each PNG and look at it before committing. Test files given as
# arguments (tests/browser/viewer.spec.js) limit it to their reference images.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
bash scripts/setup.sh
bash scripts/build-wasm.sh
npx playwright test "$@" --update-snapshots=all --grep "reference image"
echo "Rewritten references (look at each one before committing):"
ls -1 tests/browser/references/*.png
