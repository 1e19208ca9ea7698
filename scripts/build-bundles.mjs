// Bundles the package's browser code with rolldown (the bundler vite runs on, already in our tree), so
// that nothing at run time has to walk ninety source modules: dist/reader/, the published site's reader
// (minified, content-hashed, the first spread's chunk apart from lazy ones) with reader.html for a PDF at
// run time, and dist/cdn/conecurl.js,
// one ES module for a <script type="module"> that finds the engine's wasm beside it.
// Usage: node scripts/build-bundles.mjs [--quiet]   (scripts/build-wasm.sh runs it after the engine)
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
let build;  // rolldown's, imported below: a checkout without its devDependencies gets one line, not a stack
const quiet = process.argv.includes('--quiet');

/** What `conecurl publish` reads to copy and preload the reader: written last, so its presence means a whole build. */
export const READER_BUNDLE = 'dist/reader/bundle.json';

// Never bundled: pdf.js (an optional dependency the page maps to where it is installed; only the
// reader.html#file= road imports it) and the frameworks the React and Vue wrappers take from their host.
const EXTERNAL = [/^pdfjs-dist(\/|$)/, /^react(\/|$)/, /^vue$/];

// The reader's lazy chunks, by what they serve: code a published book's first spread never runs goes into
// one of these, loaded when the reader first asks for it. Whatever no group takes and the first spread
// reaches is in the entry's chunk or in a chunk shared with a lazy one.
const LAZY = [
  { name: 'pdf', test: /[\\/]web[\\/]src[\\/]document[\\/]pdf-(pages|document)\.js$/ },
  // The browser's voices, asked for at once by the toolbar (whether to show Read aloud), and the Voice and speed popup.
  { name: 'speech', test: /[\\/]web[\\/]src[\\/]read-aloud[\\/]speech-engine\.js$/ },
  { name: 'voices', test: /[\\/]web[\\/]src[\\/](engine[\\/]voice-choice|viewer[\\/]read-aloud-menu)\.js$/ },
  { name: 'read-aloud', test: /[\\/]web[\\/]src[\\/](read-aloud[\\/]|layers[\\/]reading-mark\.js$)/ },
  { name: 'panels', test: /[\\/]web[\\/]src[\\/](viewer[\\/](thumbnails|contents|search)-panel|document[\\/]page-thumbnails)\.js$/ },
  { name: 'search', test: /[\\/]web[\\/]src[\\/](document[\\/](book-search|text-index)|layers[\\/]search-hits)\.js$/ },
  { name: 'html-pages', test: /([\\/]web[\\/]src[\\/]layers[\\/]html-pages\.js|[\\/]node_modules[\\/]modern-screenshot[\\/])/ },
  { name: 'static-book', test: /[\\/]web[\\/]src[\\/]book[\\/]static-book\.js$/ },
  // What the book builds once its first spread shows (book-controller.js _buildAfterFirstSpread): input, the
  // toolbar, a document's text layer, the edge marks. Not what comes before: the viewer's options and the
  // toolbar's room, the keys the book's element names (input-keys.js), the turn area the options check.
  { name: 'after-first-spread', test: /[\\/]web[\\/]src[\\/](viewer[\\/](?!viewer-options|viewer-labels|toolbar-room|keep-offline)[\w-]+|input[\\/](book-input|input-taps|pointer-drag|tap-swipe|zoom-input)|layers[\\/](text-layer|edge-tabs)|document[\\/]edge-marks)\.js$/ },
  // What a book does only when asked: live pages, autoplay, the page sound, a passage's link, download and
  // print, Keep offline (loaded once a service worker controls the page).
  { name: 'features', test: /[\\/]web[\\/]src[\\/](book[\\/](live-pages|autoplay|page-sound)|document[\\/](passage-link|book-document)|viewer[\\/]keep-offline)\.js$/ },
];
const isLazy = (id) => LAZY.some((group) => group.test.test(id));

// A module imported by import() only when an option asks for it (so that a page of source modules fetches it
// only then) that another module imports statically (the viewer's options, the toolbar's room) stays in
// whichever chunk that puts it in: as meant, so rolldown's note on it is not passed on.
const onLog = (level, log, pass) => { if (log.code !== 'INEFFECTIVE_DYNAMIC_IMPORT') pass(level, log); };

/**
 * The modules the entry reaches without passing through a lazy group's module (static and dynamic
 * imports alike): those make the first chunk. The rest is left to rolldown, beside the lazy chunks.
 */
async function firstChunkModules(input) {
  let graph = null;
  await build({
    input, external: EXTERNAL, logLevel: 'silent', experimental: { resolveNewUrlToAsset: true },
    plugins: [{
      name: 'conecurl-module-graph',
      buildEnd() {
        graph = new Map([...this.getModuleIds()].map((id) => {
          const info = this.getModuleInfo(id);
          return [id, [...info.importedIds, ...info.dynamicallyImportedIds]];
        }));
      },
    }],
    output: { format: 'es' },
    write: false,
  });
  const reached = new Set(Object.values(input));
  for (const id of reached) for (const next of graph.get(id) ?? []) if (!isLazy(next) && graph.has(next)) reached.add(next);
  return reached;
}

const gzipSize = (data) => zlib.gzipSync(data, { level: 9 }).length;

/** The reader for published sites: dist/reader/, and bundle.json saying which files the first spread loads. */
async function buildReader() {
  const dir = path.join(root, 'dist/reader');
  fs.rmSync(dir, { recursive: true, force: true });
  const input = { reader: path.join(root, 'web/reader/reader.js') };
  const first = await firstChunkModules(input);
  const { output } = await build({
    cwd: root,
    input,
    external: EXTERNAL,
    preserveEntrySignatures: 'allow-extension',  // the reader's `book` stays exported; its chunk may take shared code too
    logLevel: 'warn',
    onLog,
    // The engine's glue finds its wasm by new URL('conecurl-engine.wasm', import.meta.url): emitted as a
    // hashed asset beside the chunks, its name written into the glue.
    experimental: { resolveNewUrlToAsset: true },
    output: {
      dir, format: 'es', minify: true,
      entryFileNames: '[name]-[hash].js', chunkFileNames: '[name]-[hash].js', assetFileNames: '[name]-[hash][extname]',
      // The lazy groups first; the rest of what the reader reaches, one chunk with the entry's code.
      codeSplitting: { includeDependenciesRecursively: false, groups: [...LAZY.map((group, i) => ({ ...group, priority: LAZY.length - i + 1 })), { name: 'reader', test: (id) => first.has(id), priority: 0 }] },
    },
  });
  const chunks = output.filter((file) => file.type === 'chunk');
  const entry = chunks.find((chunk) => chunk.isEntry);
  const byName = new Map(chunks.map((chunk) => [chunk.fileName, chunk]));
  // What the first spread loads before it runs: the entry and its static imports, each once.
  const loaded = [entry.fileName];
  for (const file of loaded) for (const imported of byName.get(file).imports) if (byName.has(imported) && !loaded.includes(imported)) loaded.push(imported);
  const wasm = output.find((file) => file.type === 'asset' && file.fileName.endsWith('.wasm'));
  if (!wasm) throw new Error('the engine\'s wasm was not emitted beside the reader: has dist/conecurl-engine.mjs changed how it finds it?');
  const css = `reader-${createHash('sha256').update(fs.readFileSync(path.join(root, 'web/reader/reader.css'))).digest('hex').slice(0, 8)}.css`;
  fs.copyFileSync(path.join(root, 'web/reader/reader.css'), path.join(dir, css));
  const files = [...output.map((file) => file.fileName), css].sort();
  const firstGzip = loaded.reduce((sum, file) => sum + gzipSize(byName.get(file).code), 0);
  const manifest = {
    note: 'written by scripts/build-bundles.mjs: the published reader; conecurl publish copies files and preloads preload',
    entry: entry.fileName, preload: loaded.slice(1).sort(), css, wasm: wasm.fileName, files,
    firstSpreadGzip: firstGzip,
  };
  writeReaderPage(dir, manifest);
  fs.writeFileSync(path.join(root, READER_BUNDLE), `${JSON.stringify(manifest, null, 1)}\n`);
  return { chunks: chunks.length, first: loaded, firstGzip };
}

/**
 * dist/reader/reader.html: web/reader/reader.html (reader.html#file=book.pdf, a PDF at run time) on the
 * bundle: its stylesheet and entry by their hashed names, the first spread's chunks preloaded. Its import
 * map finds pdf.js from dist/reader/ as from web/reader/ (the same depth in the package).
 */
function writeReaderPage(dir, { entry, preload, css }) {
  const source = path.join(root, 'web/reader/reader.html');
  let page = fs.readFileSync(source, 'utf8');
  const swap = (from, to) => {
    if (!page.includes(from)) throw new Error(`${path.relative(root, source)} no longer has ${from}: say in build-bundles.mjs how its bundled copy is made`);
    page = page.replace(from, to);
  };
  swap('<link rel="stylesheet" href="reader.css">', `<link rel="stylesheet" href="${css}">`);
  swap('<script type="module" src="reader.js"></script>',
    [...preload.map((file) => `<link rel="modulepreload" href="${file}">`), `<script type="module" src="${entry}"></script>`].join('\n'));
  fs.writeFileSync(path.join(dir, 'reader.html'), page);
}

/** dist/cdn/conecurl.js: Flipbook and <cone-flipbook> in one module; the wasm beside it keeps its name. */
async function buildCdn() {
  const dir = path.join(root, 'dist/cdn');
  fs.rmSync(dir, { recursive: true, force: true });
  await build({
    cwd: root,
    input: path.join(root, 'web/src/cdn.js'),
    external: EXTERNAL,
    logLevel: 'warn',
    onLog,
    output: { file: path.join(dir, 'conecurl.js'), format: 'es', minify: true, codeSplitting: false },
  });
  fs.copyFileSync(path.join(root, 'dist/conecurl-engine.wasm'), path.join(dir, 'conecurl-engine.wasm'));
  return { gzip: gzipSize(fs.readFileSync(path.join(dir, 'conecurl.js'))) };
}

try {
  try {
    ({ build } = await import('rolldown'));
  } catch {
    throw new Error('rolldown is not installed: run npm install (or npm run build, which does)');
  }
  const reader = await buildReader();
  const cdn = await buildCdn();
  if (!quiet) {
    console.log(`bundles: dist/reader/ (${reader.chunks} chunks; the first spread's ${reader.first.length}, ${(reader.firstGzip / 1024).toFixed(1)} KB gzip), `
      + `dist/cdn/conecurl.js (${(cdn.gzip / 1024).toFixed(1)} KB gzip)`);
  }
} catch (error) {
  console.error(`build-bundles: ${error.message ?? error}`);
  if (process.env.DEBUG) console.error(error);
  process.exit(1);
}
