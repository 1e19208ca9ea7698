// Bundles what the benchmark pages load, the way a site would ship it (Vite production build,
// minified): one bundle per library adapter for the pages, and a second build of each library alone
// (its public exports, no adapter) whose files are the "bytes the page must load" (minified, gzip -9).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { build } from 'vite';
import { BASELINE } from './report.mjs';

// The contenders: conecurl, its two peers, and the two floors (issue 24: the smallest WebGL and 2D-canvas
// books, scripts/bench/libraries/floor-*.js), whose adapters are the libraries themselves.
export const LIBRARIES = ['conecurl', 'page-flip', 'turnjs', 'floor-webgl', 'floor-2d'];

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');

// What a user of each library imports, nothing more.
const LIBRARY_EXPORTS = {
  conecurl: `export { Flipbook } from ${JSON.stringify(path.join(root, 'web/src/book/flipbook.js'))};`,
  'page-flip': "export { PageFlip } from 'page-flip';",
  turnjs: "import $ from 'jquery'; import 'turn.js'; export default $;",
  'floor-webgl': `export { mount } from ${JSON.stringify(path.join(root, 'scripts/bench/libraries/floor-webgl.js'))};`,
  'floor-2d': `export { mount } from ${JSON.stringify(path.join(root, 'scripts/bench/libraries/floor-2d.js'))};`,
};

export async function viteBuild(input, outDir, plugins = [], external = []) {
  return build({
    configFile: false,
    root,
    base: './',  // assets (the wasm) are found next to the bundle, wherever it is served
    logLevel: 'warn',
    plugins,
    build: {
      outDir,
      emptyOutDir: true,
      minify: true,
      modulePreload: false,
      reportCompressedSize: false,
      rollupOptions: {
        input,
        external,
        preserveEntrySignatures: 'exports-only',
        output: { entryFileNames: '[name].js', assetFileNames: '[name][extname]', chunkFileNames: '[name]-[hash].js' },
      },
    },
  });
}

export const gzipSize = (bytes) => zlib.gzipSync(bytes, { level: 9 }).length;

// The files a page loads up front: the entry chunks, what they import statically, and the assets
// (the wasm). Chunks reached only through import() (pdf.js, for PDF books) load on demand.
export function upFrontFiles(result) {
  const output = (Array.isArray(result) ? result[0] : result).output;
  const byName = new Map(output.map((item) => [item.fileName, item]));
  const upFront = new Set(output.filter((item) => item.type === 'asset').map((item) => item.fileName));
  const visit = (name) => {
    if (upFront.has(name)) return;
    upFront.add(name);
    for (const dependency of byName.get(name)?.imports ?? []) visit(dependency);
  };
  for (const item of output) if (item.type === 'chunk' && item.isEntry) visit(item.fileName);
  return upFront;
}

// The folder, inside the bundles folder, of the baseline contender's bundle: its own, because both
// conecurl trees emit an asset named conecurl-engine.wasm ('[name][extname]' below).
export const BASELINE_FOLDER = 'baseline';
export { BASELINE };

/** Vite's input for one library alone (`source`: the module text that exports what a user imports). */
function libraryOnlyInput(lib, source) {
  const id = `bench-library:${lib}`;
  return {
    input: { [lib]: id },
    plugin: {
      name: 'bench-library-only',
      resolveId(request) { return request === id ? `\0${id}` : null; },
      load(request) { return request === `\0${id}` ? source : null; },
    },
  };
}

/** Builds `lib` alone into `libDir` and sizes what a page loads up front and on demand. */
async function measureLibraryOnly(lib, source, libDir, check = () => {}) {
  const { input, plugin } = libraryOnlyInput(lib, source);
  const result = await viteBuild(input, libDir, [plugin]);
  check(result, libDir);
  const upFront = upFrontFiles(result);
  const entry = { files: [], js: 0, jsGzip: 0, wasm: 0, wasmGzip: 0, lazy: { files: [], js: 0, jsGzip: 0 } };
  for (const file of fs.readdirSync(libDir)) {
    const bytes = fs.readFileSync(path.join(libDir, file));
    const kind = file.endsWith('.wasm') ? 'wasm' : file.endsWith('.js') ? 'js' : null;
    if (!kind) throw new Error(`bench bundle: unexpected file ${file} in the ${lib} build`);
    if (!upFront.has(file)) {
      if (kind !== 'js') throw new Error(`bench bundle: ${file} of the ${lib} build is not loaded up front`);
      entry.lazy.js += bytes.length;
      entry.lazy.jsGzip += gzipSize(bytes);
      entry.lazy.files.push(file);
      continue;
    }
    entry[kind] += bytes.length;
    entry[`${kind}Gzip`] += gzipSize(bytes);
    entry.files.push(file);
  }
  entry.total = entry.js + entry.wasm;
  entry.totalGzip = entry.jsGzip + entry.wasmGzip;
  return entry;
}

/**
 * Builds the adapter bundles into `outDir` (served to the pages) and measures each library alone.
 * Returns { [lib]: { js, jsGzip, wasm, wasmGzip, total, totalGzip, files, lazy: { files, js, jsGzip } } }:
 * the totals count what a page loads up front; `lazy` the chunks loaded only on demand.
 */
export async function bundleLibraries(outDir) {
  const adapters = Object.fromEntries(LIBRARIES.map((lib) => [lib, path.join(root, 'scripts/bench/libraries', `${lib}.js`)]));
  await viteBuild(adapters, outDir);
  const sizes = {};
  for (const lib of LIBRARIES) sizes[lib] = await measureLibraryOnly(lib, LIBRARY_EXPORTS[lib], path.join(outDir, 'library-only', lib));
  return sizes;
}

/**
 * A check of a baseline build: every source module outside node_modules comes from `dir` (none from this
 * tree), and the one wasm written is `dir`'s dist/conecurl-engine.wasm, byte for byte.
 */
function fromTree(dir) {
  const tree = fs.realpathSync(dir) + path.sep;
  const wasm = fs.readFileSync(path.join(dir, 'dist/conecurl-engine.wasm'));
  return (result, builtDir) => {
    const output = (Array.isArray(result) ? result[0] : result).output;
    const modules = output.filter((item) => item.type === 'chunk').flatMap((chunk) => chunk.moduleIds ?? Object.keys(chunk.modules));
    const foreign = modules.filter((id) => !id.startsWith('\0') && !id.includes(`${path.sep}node_modules${path.sep}`) && !id.startsWith(tree));
    if (foreign.length) throw new Error(`bench: the baseline build took modules from outside ${dir}: ${foreign.slice(0, 3).join(', ')}`);
    if (!modules.some((id) => id.startsWith(tree))) throw new Error(`bench: the baseline build holds no module of ${dir}`);
    const wasmFiles = fs.readdirSync(builtDir).filter((file) => file.endsWith('.wasm'));
    if (wasmFiles.length !== 1 || !fs.readFileSync(path.join(builtDir, wasmFiles[0])).equals(wasm)) {
      throw new Error(`bench: the baseline build in ${builtDir} does not hold ${dir}'s dist/conecurl-engine.wasm (found ${wasmFiles.join(', ') || 'none'})`);
    }
  };
}

/** The commit of a checkout, short, with "+changes" when tracked files differ from it. */
export function checkoutCommit(dir) {
  const git = (...args) => execFileSync('git', ['-C', dir, ...args], { encoding: 'utf8' }).trim();
  const commit = git('rev-parse', '--short', 'HEAD');
  return git('status', '--porcelain', '--untracked-files=no') ? `${commit}+changes` : commit;
}

/**
 * The baseline contender (`npm run bench -- --baseline <dir>`): conecurl as another checkout of it has
 * it (an older commit, with its own built dist/). Its adapter is this tree's conecurl adapter with the
 * imports pointed at `dir`'s sources, so both play the same turns through the same API; it is bundled
 * into `<outDir>/baseline/` (run after bundleLibraries, which empties outDir) and measured alone the same
 * way as conecurl. Returns { commit, dir, bundles, loadBytes }.
 */
export async function bundleBaseline(dir, outDir) {
  const sources = { flipbook: path.join(dir, 'web/src/book/flipbook.js'), engine: path.join(dir, 'web/src/engine.js') };
  for (const file of [...Object.values(sources), path.join(dir, 'dist/conecurl-engine.wasm')]) {
    if (!fs.existsSync(file)) throw new Error(`bench: --baseline ${dir} has no ${path.relative(dir, file)} (a conecurl checkout with its dist/ built?)`);
  }
  const adapterFile = path.join(root, 'scripts/bench/libraries/conecurl.js');
  let adapter = fs.readFileSync(adapterFile, 'utf8');
  for (const [name, file] of Object.entries(sources)) {
    const relative = `'../../../web/src/${name === 'flipbook' ? 'book/flipbook.js' : 'engine.js'}'`;
    if (!adapter.includes(relative)) throw new Error(`bench: ${adapterFile} no longer imports ${relative}; update bundleBaseline`);
    adapter = adapter.replace(relative, JSON.stringify(file));
  }
  const bundles = path.join(outDir, BASELINE_FOLDER);
  const { input, plugin } = libraryOnlyInput(BASELINE, adapter);
  const check = fromTree(dir);
  check(await viteBuild(input, bundles, [plugin]), bundles);
  const loadBytes = await measureLibraryOnly(BASELINE, `export { Flipbook } from ${JSON.stringify(sources.flipbook)};`,
    path.join(outDir, 'library-only', BASELINE), check);
  return { commit: checkoutCommit(dir), dir: path.resolve(dir), bundles, loadBytes };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const outDir = path.resolve(process.argv[2] || 'bench-results/bundles');
  const sizes = await bundleLibraries(outDir);
  for (const [lib, s] of Object.entries(sizes)) {
    console.log(`${lib.padEnd(10)} js ${s.js} (gzip ${s.jsGzip})  wasm ${s.wasm} (gzip ${s.wasmGzip})  total gzip ${s.totalGzip}  [${s.files.join(', ')}]`
      + (s.lazy.files.length ? `; on demand: ${s.lazy.jsGzip} gzip [${s.lazy.files.join(', ')}]` : ''));
  }
}
