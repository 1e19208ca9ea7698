// What makes a published site an installable web app that reads offline: its web app manifest
// (manifest.webmanifest) and its service worker (sw.js, from web/reader/service-worker.js with this
// publish's version and file list put in). The list is what this publish wrote, never a hand list.
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { inputError } from './errors.mjs';

export const WEB_MANIFEST = 'manifest.webmanifest';
export const SERVICE_WORKER = 'sw.js';
/** The icons made from the cover (render-page.mjs), in book/: their side in px, and their file names. */
export const ICON_SIDES = [192, 512];
export const iconFile = (side) => `icon-${side}.png`;
/** The reader page's background, as web/reader/reader.css says it (its one place), read at its first use. */
let background = null;
function readerBackground() {
  if (background) return background;
  const css = fs.readFileSync(fileURLToPath(new URL('../../web/reader/reader.css', import.meta.url)), 'utf8');
  background = /html, body \{[^}]*\bbackground: (#[0-9a-f]{3,8})\b/i.exec(css)?.[1] ?? null;
  if (!background) throw new Error('web/reader/reader.css gives html, body no background colour: reinstall conecurl');
  return background;
}
/**
 * The site's colours: the reader page's background behind the icons and on the splash screen, and the
 * browser's bar. book.json has no colours of its own: these are the reader's.
 */
export const COLORS = { get background() { return readerBackground(); }, get theme() { return readerBackground(); } };
/** The line of the service worker's source that publish replaces with the site's facts. */
const SITE_LINE = 'const SITE = null;  // replaced by conecurl publish';

/**
 * index.html's place for the site's version (web/reader/reader.js reads it and asks the worker for its
 * own): written empty, hashed so, and filled once the version is known.
 */
export const VERSION_SLOT = '<meta name="conecurl-site-version" content="">';
const INDEX = 'index.html';
/** The characters of the title a home screen shows under the icon at most (short_name). */
const SHORT_NAME = 12;

/**
 * manifest.webmanifest: name and short_name from the title, start_url and scope the site's own folder
 * ("./", so it works under any sub-path), standalone, the colours, the two icons (paths from the site).
 */
export function webManifest({ title, lang, icons }) {
  const name = String(title).trim() || 'Book';
  const short = name.length <= SHORT_NAME ? name : `${name.slice(0, SHORT_NAME - 1).trimEnd()}\u2026`;
  return `${JSON.stringify({
    name, short_name: short, ...(lang ? { lang } : {}), start_url: './', scope: './', display: 'standalone',
    background_color: COLORS.background, theme_color: COLORS.theme,
    icons: icons.map(({ src, side }) => ({ src, sizes: `${side}x${side}`, type: 'image/png', purpose: 'any' })),
  }, null, 1)}\n`;
}

/** A file's contents, hashed (sha-256, its first 16 hex digits): sw.js names each file's so. */
const contentHash = (file) => createHash('sha256').update(fs.readFileSync(file)).digest('hex').slice(0, 16);

/**
 * The version of a site: a hash of every file's path and contents (`hashes`: relative path -> its
 * contentHash), so a publish that changes any file gets a new one and one that changes none keeps it.
 */
export function siteVersion(hashes) {
  const hash = createHash('sha256');
  for (const file of [...hashes.keys()].sort()) hash.update(`${file}\0${hashes.get(file)}\0`);
  return hash.digest('hex').slice(0, 16);
}

/**
 * sw.js: `template` (web/reader/service-worker.js's text) with its SITE line holding `version`,
 * `shell` (the files precached at install: relative paths) and `files` ([path, bytes, contents' hash] of
 * every file the site serves: Keep offline fetches them, a new version keeps the old one's unchanged). An error if the template lost its SITE line.
 */
export function serviceWorker(template, { version, shell, files }) {
  if (!template.includes(SITE_LINE)) throw new Error(`the service worker's source has no line "${SITE_LINE}": reinstall conecurl`);
  const missing = shell.filter((file) => !files.some(([name]) => name === file));
  if (missing.length > 0) throw new Error(`the service worker's shell names files the site does not have: ${missing.join(', ')}`);
  return template.replace(SITE_LINE, `const SITE = ${JSON.stringify({ version, shell, files })};`);
}

/** The service worker's source in the package. */
const TEMPLATE = fileURLToPath(new URL('../../web/reader/service-worker.js', import.meta.url));

/**
 * Writes manifest.webmanifest and sw.js into `out` once every other file is written, and records both
 * in `written` (relative path -> { bytes, kind }, main.mjs's). `shell`: whether a file is precached at
 * install; `skip`: files the site does not serve to readers (_headers). The version hashes every file
 * written but sw.js itself (index.html with its VERSION_SLOT empty), and is then written into index.html.
 * Returns { version, files } (files: the sw's list, [path, bytes, hash]).
 */
export function writeWebApp({ out, title, lang, written, icons, shell, skip = [] }) {
  const manifest = webManifest({ title, lang, icons: icons.filter(({ src }) => written.has(src)) });
  fs.writeFileSync(path.join(out, WEB_MANIFEST), manifest);
  written.set(WEB_MANIFEST, { bytes: Buffer.byteLength(manifest), kind: 'text' });
  let template;
  try {
    template = fs.readFileSync(TEMPLATE, 'utf8');
  } catch (error) {
    throw Object.assign(inputError(`${TEMPLATE} is missing from conecurl: reinstall conecurl`), { cause: error });
  }
  const served = [...written.keys()].filter((file) => !skip.includes(file)).sort();
  const hashes = new Map(served.map((file) => [file, contentHash(path.join(out, file))]));
  const version = siteVersion(hashes);
  if (written.has(INDEX)) {
    const page = fs.readFileSync(path.join(out, INDEX), 'utf8');
    if (!page.includes(VERSION_SLOT)) throw new Error(`${INDEX} has no ${VERSION_SLOT}: the reader could not tell a new publish's worker`);
    const filled = page.replace(VERSION_SLOT, VERSION_SLOT.replace('content=""', `content="${version}"`));
    fs.writeFileSync(path.join(out, INDEX), filled);
    written.get(INDEX).bytes = Buffer.byteLength(filled);
    hashes.set(INDEX, contentHash(path.join(out, INDEX)));
  }
  const files = served.map((file) => [file, written.get(file).bytes, hashes.get(file)]);
  const worker = serviceWorker(template, { version, shell: files.map(([file]) => file).filter((file) => shell(file, written.get(file))), files });
  fs.writeFileSync(path.join(out, SERVICE_WORKER), worker);
  written.set(SERVICE_WORKER, { bytes: Buffer.byteLength(worker), kind: 'text' });
  return { version, files };
}
