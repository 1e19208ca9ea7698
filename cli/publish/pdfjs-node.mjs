// pdf.js and @napi-rs/canvas in Node, for `conecurl publish`: the two polyfills Node 20 needs, where the
// canvas package is found, and the options that let pdf.js find its fonts, cmaps and image decoders.
import { createRequire } from 'node:module';
import path from 'node:path';

// Node 20 support: pdfjs-dist 6 asks for Node >= 22.13 but renders on Node 20 with these two. Without
// transferToFixedLength pages come out BLANK (pdf.js only warns), so they must run before pdf.js loads,
// in the main thread and in every worker thread (each imports this module first).
if (!Promise.withResolvers) {
  Promise.withResolvers = function withResolvers() {
    let resolve;
    let reject;
    const promise = new this((yes, no) => { resolve = yes; reject = no; });
    return { promise, resolve, reject };
  };
}
if (!ArrayBuffer.prototype.transferToFixedLength) {
  // eslint-disable-next-line no-extend-native
  ArrayBuffer.prototype.transferToFixedLength = function transferToFixedLength(length = this.byteLength) {
    const copy = new ArrayBuffer(length);
    new Uint8Array(copy).set(new Uint8Array(this, 0, Math.min(length, this.byteLength)));
    return copy;
  };
}

const require = createRequire(import.meta.url);

// pdf.js leaves some internal promises unhandled when a file is damaged (a page tree with a bad entry
// rejects a lookup nobody awaits): the failure reaches the caller that asked, so these are only noted.
export const strayRejections = [];
process.on('unhandledRejection', (reason) => { strayRejections.push(reason); });

/** What to install when a part is missing (one line, for the error message). */
export const INSTALL_HINT = 'install them next to conecurl (npm leaves pdf.js out on Node 20): npm install pdfjs-dist @napi-rs/canvas@1.0.11';

/** pdfjs-dist's folder, or null when it is not installed. */
export function pdfjsFolder() {
  try {
    return path.dirname(require.resolve('pdfjs-dist/package.json'));
  } catch {
    return null;
  }
}

/**
 * @napi-rs/canvas: from conecurl's own place first, else from pdfjs-dist's (npm may nest it there), so
 * that it is the same copy pdf.js draws with. Throws when neither has it.
 */
export function loadCanvas() {
  try {
    return require('@napi-rs/canvas');
  } catch (first) {
    const folder = pdfjsFolder();
    if (!folder) throw first;
    return createRequire(path.join(folder, 'package.json'))('@napi-rs/canvas');
  }
}

/** pdf.js's Node build (the legacy build). */
export async function loadPdfjs() {
  return import('pdfjs-dist/legacy/build/pdf.mjs');
}

/**
 * getDocument's options for `data` in Node: the standard fonts, cmaps and wasm decoders read from
 * pdfjs-dist's folders (Node reads them as file paths, each ending in a slash).
 */
export function documentOptions(data, password) {
  const folder = pdfjsFolder();
  const dir = (name) => `${path.join(folder, name)}${path.sep}`;
  return {
    data, password, standardFontDataUrl: dir('standard_fonts'), cMapUrl: dir('cmaps'), cMapPacked: true,
    wasmUrl: dir('wasm'), isEvalSupported: false, verbosity: 0,
  };
}
