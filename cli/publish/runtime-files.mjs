// The reader a published site carries under conecurl/: the bundle scripts/build-bundles.mjs made in
// dist/reader/ (content-hashed chunks, the engine's wasm, the page's CSS), as its bundle.json lists it.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const PACKAGE_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
/** The bundle's folder in the package, and the file that lists it. */
export const READER_DIR = 'dist/reader';
export const READER_BUNDLE = `${READER_DIR}/bundle.json`;

/**
 * The reader's files to copy (`files`, names inside READER_DIR), its `entry` chunk, the chunks the entry
 * imports before it runs (`preload`: the first spread's, as the bundler's output says), its `wasm`, and
 * `style`, the page's CSS, which index.html holds itself (a style sheet file would hold back the first paint
 * by a round trip). A missing or partial bundle throws, saying how to make it.
 */
export function runtimeFiles(root = PACKAGE_ROOT) {
  const rebuild = `reinstall conecurl (or, in a checkout, build it: npm run build)`;
  let bundle;
  try {
    bundle = JSON.parse(fs.readFileSync(path.join(root, READER_BUNDLE), 'utf8'));
  } catch {
    throw new Error(`${READER_BUNDLE} is missing from conecurl at ${root}: ${rebuild}`);
  }
  const { entry, preload, css, wasm, files } = bundle;
  if (!Array.isArray(files) || !Array.isArray(preload) || ![entry, css, wasm].every((file) => files.includes(file))) {
    throw new Error(`${READER_BUNDLE} at ${root} does not list the reader's entry, CSS and wasm: ${rebuild}`);
  }
  for (const file of files) {
    if (!fs.existsSync(path.join(root, READER_DIR, file))) throw new Error(`${READER_DIR}/${file} is missing from conecurl at ${root}: ${rebuild}`);
  }
  const style = fs.readFileSync(path.join(root, READER_DIR, css), 'utf8');
  return { dir: path.join(root, READER_DIR), files: files.filter((file) => file !== css), preload, entry, style, wasm };
}
