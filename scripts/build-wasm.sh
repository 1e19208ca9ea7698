#!/usr/bin/env bash
# Builds the wasm engine (core + renderer + bindings) into dist/ with emcmake (incremental), then the
# browser bundles made from it (scripts/build-bundles.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/env.sh
# Closure on the package build's glue (CMakeLists.txt, CONECURL_CLOSURE), from the first compiler found:
# CONECURL_CLOSURE_COMPILER=<command>; an emsdk's own (its emscripten/node_modules); else the one
# package.json pins for Debian's Emscripten 3.1.6, which has none (google-closure-compiler 20220104, the
# version 3.1.6 was made with: newer ones reject its --language_in).
closure=ON
emscripten_dir=$(dirname "$(readlink -f "$(command -v emcc)")")
if [ -n "${CONECURL_CLOSURE_COMPILER:-}" ]; then
  export EM_CLOSURE_COMPILER="$CONECURL_CLOSURE_COMPILER"
elif [ -x "$emscripten_dir/node_modules/.bin/google-closure-compiler" ]; then
  :
elif [ -x node_modules/.bin/google-closure-compiler ]; then
  export EM_CLOSURE_COMPILER="$PWD/node_modules/.bin/google-closure-compiler"
else
  echo "build-wasm: no closure compiler (npm ci installs one): the engine's glue is built without it, about 2 KB gzip larger" >&2
  closure=OFF
fi
if [ ! -f build/wasm/CMakeCache.txt ] || ! grep -q "^CONECURL_CLOSURE:BOOL=$closure\$" build/wasm/CMakeCache.txt; then
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=MinSizeRel -DCONECURL_CLOSURE=$closure >/dev/null
fi
cmake --build build/wasm -j2
test -f dist/conecurl-engine.wasm && test -f dist/conecurl-engine.mjs && test -f dist/engine-constants.js
test -f dist/test/conecurl-engine.wasm && test -f dist/test/conecurl-engine.mjs
# The browser bundles (dist/reader/, dist/cdn/) from the engine just built and the sources: a second or so.
node scripts/build-bundles.mjs --quiet
