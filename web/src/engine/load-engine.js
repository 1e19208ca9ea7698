// Loads the wasm engine (math core + WebGL2 renderer, via Embind) once per page and hands out the
// module. The .wasm is found next to the module's JS by default; `wasmUrl` or `locateFile` override it.
import createConeCurlEngine from '../../../dist/conecurl-engine.mjs';

let shared = null;

/**
 * @param {{ wasmUrl?: string, wasmBinary?: ArrayBuffer|Uint8Array, locateFile?: (file: string) => string }} [options]
 * @returns {Promise<object>} the Embind module (ConeCurlEngine in load-engine.d.ts): the curl math
 *   (curlAt, curlPoint, ...) and the classes Book, FrameLoop and BookRenderer (cpp/bindings)
 */
export function loadEngine(options = {}) {
  const custom = options.wasmUrl || options.wasmBinary || options.locateFile;
  if (shared && !custom) return shared;
  const moduleArgs = {};
  if (options.wasmBinary) moduleArgs.wasmBinary = options.wasmBinary;
  if (options.locateFile) moduleArgs.locateFile = options.locateFile;
  else if (options.wasmUrl) moduleArgs.locateFile = (file) => (file.endsWith('.wasm') ? options.wasmUrl : file);
  const loading = createConeCurlEngine(moduleArgs).catch((error) => {
    if (!custom) shared = null;  // let a later call try again
    const failure = new Error(`conecurl: the wasm engine failed to load (${error && error.message ? error.message : error})`,
      { cause: error });
    failure.code = 'engine-unavailable';  // Flipbook falls back to static pages on this code
    throw failure;
  });
  if (!custom) shared = loading;
  return loading;
}
