// Loads the built wasm module in Node. Emscripten 3.1.6's ES-module output cannot fetch its .wasm
// under Node, so the bytes are read here and passed as wasmBinary (see DEVELOPERS.md).
import fs from 'node:fs';

// 'test' (dist/test/): the package's bindings plus the readbacks and references only tests call;
// 'package' (dist/): what ships (CMakeLists.txt builds both).
const DIST = {
  test: new URL('../../dist/test/', import.meta.url),
  package: new URL('../../dist/', import.meta.url),
};

export async function loadEngineForNode({ build = 'test' } = {}) {
  const dist = DIST[build];
  const { default: createConeCurlEngine } = await import(new URL('conecurl-engine.mjs', dist));
  return createConeCurlEngine({ wasmBinary: fs.readFileSync(new URL('conecurl-engine.wasm', dist)) });
}
