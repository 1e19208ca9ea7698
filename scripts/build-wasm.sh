#!/usr/bin/env bash
# Builds the wasm engine (core + renderer + bindings) into dist/ with emcmake; incremental.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
if [ ! -f build/wasm/CMakeCache.txt ]; then
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=MinSizeRel >/dev/null
fi
cmake --build build/wasm -j2
test -f dist/conecurl-engine.wasm && test -f dist/conecurl-engine.mjs && test -f dist/engine-constants.js
test -f dist/test/conecurl-engine.wasm && test -f dist/test/conecurl-engine.mjs
