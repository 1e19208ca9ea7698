// What a host needs to put a published site on its pages and behind a CDN: the <iframe> snippet that
// `conecurl publish` prints, and the site's _headers file (cache rules read by Netlify and Cloudflare Pages).
import path from 'node:path';
import { ICON_SIDES, SERVICE_WORKER, WEB_MANIFEST, iconFile } from './web-app.mjs';

/** The headers file's name at the site's root. */
export const HEADERS = '_headers';
/** How long the numbered files may be kept before they are revalidated: they are not content-hashed. */
export const NUMBERED_MAX_AGE = 3600;

const attr = (text) => String(text).replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');

/** Where an embedding page finds the site: `url` (--url) if given, else `out` relative to `cwd`, ending in '/'. */
export function embedSrc({ out, url = null, cwd = process.cwd() }) {
  if (url) return url;
  const relative = path.relative(cwd, out).split(path.sep).join('/');
  return relative === '' ? './' : `${relative}/`;
}

/** The one-line <iframe> that shows the book on another page (fullscreen allowed, loaded when scrolled near). */
export function iframeSnippet({ src, title }) {
  return `<iframe src="${attr(src)}" title="${attr(title)}" width="100%" height="600" style="border:0" `
    + 'allow="fullscreen" allowfullscreen loading="lazy"></iframe>';
}

/** How long the reader's files may be kept: their names carry a hash of their content (build-bundles.mjs). */
export const HASHED = 'Cache-Control: public, max-age=31536000, immutable';

/**
 * The _headers file: index.html, book.json, the service worker and the web app manifest always
 * revalidate (a new publish changes them); the page images, text, thumbnails, cover, icons, narration
 * and the PDF are numbered or named the same at each publish, not content-hashed, so they are kept
 * NUMBERED_MAX_AGE and then revalidated; the reader's files under conecurl/ are content-hashed, so they
 * are immutable. No file is
 * matched by two rules (both hosts join the headers of every rule that matches). `download`: the PDF's
 * name in book/, or null.
 */
export function headersFile({ download = null }) {
  const revalidate = 'Cache-Control: no-cache';
  const keep = `Cache-Control: public, max-age=${NUMBERED_MAX_AGE}`;
  const rules = [
    ['/', revalidate], ['/index.html', revalidate], ['/book/book.json', revalidate],
    // The service worker and the web app manifest name this publish's version: a browser must see a new one.
    [`/${SERVICE_WORKER}`, revalidate], [`/${WEB_MANIFEST}`, revalidate],
    ...['pages', 'zoom', 'thumbs', 'text', 'narration'].map((folder) => [`/book/${folder}/*`, keep]),
    ['/book/cover.jpg', keep], ...ICON_SIDES.map((side) => [`/book/${iconFile(side)}`, keep]),
    ...(download ? [[`/book/${download}`, keep]] : []), ['/conecurl/*', HASHED],
  ];
  return [
    '# Cache rules for Netlify and Cloudflare Pages, written by conecurl publish (docs/publish.md#caching-and-embedding).',
    '# The page files are numbered, not content-hashed: a new publish rewrites them under the same names, so they',
    `# are kept ${NUMBERED_MAX_AGE / 3600} hour and revalidated; index.html, book.json, sw.js and the manifest always revalidate;`,
    '# the reader\'s files under conecurl/ have a hash of their content in their names, so they never change.',
    '# Paths are from the site\'s root: if the site lives under a folder of the deploy, put that folder before each.',
    ...rules.flatMap(([where, header]) => [where, `  ${header}`]),
    '',
  ].join('\n');
}
