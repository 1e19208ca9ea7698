// The reader's runtime files a published site carries under conecurl/: reader.js, reader.css, every
// module reachable from reader.js by relative imports (static and dynamic; bare ones such as pdfjs-dist,
// react or vue are never followed), and the engine in dist/, all at their places in the package.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { FIRST_VIEW_MODULES } from '../../web/reader/first-view-modules.js';

export const PACKAGE_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const READER = 'web/reader/reader.js';
export const READER_CSS = 'web/reader/reader.css';
export const ENGINE_FILES = ['dist/conecurl-engine.mjs', 'dist/conecurl-engine.wasm', 'dist/engine-constants.js'];
/** The engine's binary: index.html preloads it (the book fetches it as soon as it is made). */
export const ENGINE_WASM = 'dist/conecurl-engine.wasm';

/** A source without its comments (JSDoc may name any module in an import() type). */
const withoutComments = (source) => source.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:'"`\\])\/\/.*$/gm, '$1');

/** The relative specifiers a module imports: { static: [...], dynamic: [...] } (import('…') with a literal). */
export function importsOf(source) {
  const code = withoutComments(source);
  const found = { static: [], dynamic: [] };
  for (const match of code.matchAll(/(?:^|[;\n}])\s*(?:import|export)\s*(?:[\w*${}\s,]+?\s*from\s*)?(['"])(\.{1,2}\/[^'"]+)\1/g)) found.static.push(match[2]);
  for (const match of code.matchAll(/\bimport\s*\(\s*(['"])(\.{1,2}\/[^'"]+)\1\s*\)/g)) found.dynamic.push(match[2]);
  return found;
}

/**
 * The modules reachable from `entry` (a path relative to `root`): `all` (static and dynamic imports) and
 * `statics` (those loaded before it runs: static imports only, from the entry through static imports),
 * each a sorted list of paths relative to `root`. An import of a missing file throws, naming both.
 */
export function moduleGraph(root, entry) {
  const imports = new Map();  // file -> its resolved { static, dynamic }, each file read once
  const importsOfFile = (file) => {
    if (!imports.has(file)) {
      if (file.startsWith('../')) throw new Error(`${entry} reaches ${file}, outside the package`);
      let source;
      try {
        source = fs.readFileSync(path.join(root, file), 'utf8');
      } catch {
        throw new Error(`${file} is missing from the package at ${root}`);
      }
      const found = importsOf(source);
      const resolve = (specifier) => path.posix.normalize(path.posix.join(path.posix.dirname(file), specifier.split(/[?#]/)[0]));
      imports.set(file, { static: found.static.map(resolve), dynamic: found.dynamic.map(resolve) });
    }
    return imports.get(file);
  };
  const closure = (kinds) => {
    const seen = new Set([entry]);
    for (const file of seen) for (const kind of kinds) for (const target of importsOfFile(file)[kind]) seen.add(target);
    return [...seen].sort();
  };
  return { all: closure(['static', 'dynamic']), statics: closure(['static']) };
}

/**
 * The runtime files to copy (paths relative to the package root); `preload`: the modules index.html
 * preloads, the static graph and the modules the reader imports on the way to its first spread.
 */
export function runtimeFiles(root = PACKAGE_ROOT, entry = READER, css = READER_CSS) {
  for (const file of [entry, css, ...ENGINE_FILES]) {
    if (!fs.existsSync(path.join(root, file))) {
      throw new Error(`${file} is missing from conecurl at ${root}: reinstall conecurl (or build it: npm run build)`);
    }
  }
  const graph = moduleGraph(root, entry);
  const files = [...new Set([...graph.all, css, ...ENGINE_FILES])].sort();
  const missing = FIRST_VIEW_MODULES.filter((file) => !graph.all.includes(file));
  if (missing.length > 0) throw new Error(`${missing.join(', ')} (web/reader/first-view-modules.js) cannot be reached from ${entry}`);
  const preload = [...new Set([...graph.statics, ...FIRST_VIEW_MODULES])].filter((file) => file !== entry).sort();
  return { files, statics: graph.statics, preload, entry, css, wasm: ENGINE_WASM };
}
