// Bundles what the benchmark pages load, the way a site would ship it (Vite production build,
// minified): one bundle per library adapter for the pages, and a second build of each library alone
// (its public exports, no adapter) whose files are the "bytes the page must load" (minified, gzip -9).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { build } from 'vite';

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

function libraryOnlyPlugin() {
  const prefix = 'bench-library:';
  return {
    name: 'bench-library-only',
    resolveId(id) { return id.startsWith(prefix) ? `\0${id}` : null; },
    load(id) { return id.startsWith(`\0${prefix}`) ? LIBRARY_EXPORTS[id.slice(prefix.length + 1)] : null; },
  };
}

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

/**
 * Builds the adapter bundles into `outDir` (served to the pages) and measures each library alone.
 * Returns { [lib]: { js, jsGzip, wasm, wasmGzip, total, totalGzip, files, lazy: { files, js, jsGzip } } }:
 * the totals count what a page loads up front; `lazy` the chunks loaded only on demand.
 */
export async function bundleLibraries(outDir) {
  const adapters = Object.fromEntries(LIBRARIES.map((lib) => [lib, path.join(root, 'scripts/bench/libraries', `${lib}.js`)]));
  await viteBuild(adapters, outDir);
  const sizes = {};
  for (const lib of LIBRARIES) {
    const libDir = path.join(outDir, 'library-only', lib);
    const upFront = upFrontFiles(await viteBuild({ [lib]: `bench-library:${lib}` }, libDir, [libraryOnlyPlugin()]));
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
    sizes[lib] = entry;
  }
  return sizes;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const outDir = path.resolve(process.argv[2] || 'bench-results/bundles');
  const sizes = await bundleLibraries(outDir);
  for (const [lib, s] of Object.entries(sizes)) {
    console.log(`${lib.padEnd(10)} js ${s.js} (gzip ${s.jsGzip})  wasm ${s.wasm} (gzip ${s.wasmGzip})  total gzip ${s.totalGzip}  [${s.files.join(', ')}]`
      + (s.lazy.files.length ? `; on demand: ${s.lazy.jsGzip} gzip [${s.lazy.files.join(', ')}]` : ''));
  }
}
