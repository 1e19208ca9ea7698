// Bundles what the benchmark pages load, the way a site would ship it (Vite production build,
// minified): one bundle per library adapter for the pages, and a second build of each library alone
// (its public exports, no adapter) whose files are the "bytes the page must load" (minified, gzip -9).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { build } from 'vite';

export const LIBRARIES = ['conecurl', 'page-flip', 'turnjs'];

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');

// What a user of each library imports, nothing more.
const LIBRARY_EXPORTS = {
  conecurl: `export { Flipbook } from ${JSON.stringify(path.join(root, 'web/src/flipbook.js'))};`,
  'page-flip': "export { PageFlip } from 'page-flip';",
  turnjs: "import $ from 'jquery'; import 'turn.js'; export default $;",
};

function libraryOnlyPlugin() {
  const prefix = 'bench-library:';
  return {
    name: 'bench-library-only',
    resolveId(id) { return id.startsWith(prefix) ? `\0${id}` : null; },
    load(id) { return id.startsWith(`\0${prefix}`) ? LIBRARY_EXPORTS[id.slice(prefix.length + 1)] : null; },
  };
}

async function viteBuild(input, outDir, plugins = []) {
  await build({
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
        preserveEntrySignatures: 'exports-only',
        output: { entryFileNames: '[name].js', assetFileNames: '[name][extname]', chunkFileNames: '[name]-[hash].js' },
      },
    },
  });
}

const gzipSize = (bytes) => zlib.gzipSync(bytes, { level: 9 }).length;

/**
 * Builds the adapter bundles into `outDir` (served to the pages) and measures each library alone.
 * Returns { [lib]: { js, jsGzip, wasm, wasmGzip, total, totalGzip, files } }.
 */
export async function bundleLibraries(outDir) {
  const adapters = Object.fromEntries(LIBRARIES.map((lib) => [lib, path.join(root, 'scripts/bench/libraries', `${lib}.js`)]));
  await viteBuild(adapters, outDir);
  const sizes = {};
  for (const lib of LIBRARIES) {
    const libDir = path.join(outDir, 'library-only', lib);
    await viteBuild({ [lib]: `bench-library:${lib}` }, libDir, [libraryOnlyPlugin()]);
    const entry = { files: [], js: 0, jsGzip: 0, wasm: 0, wasmGzip: 0 };
    for (const file of fs.readdirSync(libDir)) {
      const bytes = fs.readFileSync(path.join(libDir, file));
      const kind = file.endsWith('.wasm') ? 'wasm' : file.endsWith('.js') ? 'js' : null;
      if (!kind) throw new Error(`bench bundle: unexpected file ${file} in the ${lib} build`);
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
    console.log(`${lib.padEnd(10)} js ${s.js} (gzip ${s.jsGzip})  wasm ${s.wasm} (gzip ${s.wasmGzip})  total gzip ${s.totalGzip}  [${s.files.join(', ')}]`);
  }
}
