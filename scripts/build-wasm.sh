#!/usr/bin/env bash
# Builds the wasm engine (core + renderer + bindings) into dist/ with emcmake (incremental), then the
# browser bundles made from it (scripts/build-bundles.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
# CONECURL_CLOSURE_COMPILER=<a closure-compiler command> runs closure on the package's glue (CMakeLists.txt).
closure=OFF
if [ -n "${CONECURL_CLOSURE_COMPILER:-}" ]; then
  export EM_CLOSURE_COMPILER="$CONECURL_CLOSURE_COMPILER"
  closure=ON
fi
if [ ! -f build/wasm/CMakeCache.txt ] || ! grep -q "^CONECURL_CLOSURE:BOOL=$closure\$" build/wasm/CMakeCache.txt; then
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=MinSizeRel -DCONECURL_CLOSURE=$closure >/dev/null
fi
cmake --build build/wasm -j2
test -f dist/conecurl-engine.wasm && test -f dist/conecurl-engine.mjs && test -f dist/engine-constants.js
test -f dist/test/conecurl-engine.wasm && test -f dist/test/conecurl-engine.mjs
# The browser bundles (dist/reader/, dist/cdn/) from the engine just built and the sources: a second or so.
node scripts/build-bundles.mjs --quiet
