// The published site's index.html: the reader page (the reader's bundle makes the book in <main id="conecurl-reader">),
// its first chunks preloaded so they load in one round trip, link-preview tags, and a <noscript> copy of the
// pages (images and text) for readers and crawlers without JavaScript, and a description for search results
// and link previews. Every value from the PDF is escaped.
import { cutWords } from '../../web/src/document/format.js';
import { COLORS, VERSION_SLOT, WEB_MANIFEST } from './web-app.mjs';

/** Characters of a page's text in the noscript copy at most, and of all pages' together: the HTML stays small. */
export const NOSCRIPT_CHARS = 400;
export const NOSCRIPT_TOTAL = 24000;
/** Characters of the meta description at most (about what a search result shows). */
export const DESCRIPTION_CHARS = 160;

const ENTITIES = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' };
/** Text made safe for HTML content and double- or single-quoted attributes. */
export const escapeHtml = (value) => String(value).replace(/[&<>"']/g, (c) => ENTITIES[c]);

/** A URL path (relative, with our own file names) percent-encoded where needed, for an attribute. */
const href = (relative) => escapeHtml(relative.split('/').map(encodeURIComponent).join('/'));

/**
 * The page's description: the words the book's first pages begin with (as many pages as it takes to fill
 * DESCRIPTION_CHARS), else, for a book with no text (scanned pages, photographs), its title and page count.
 */
export function describe(title, pages) {
  let words = '';
  for (const page of pages) {
    if (page.failed || !page.text) continue;
    words = `${words} ${page.text}`.replace(/\s+/g, ' ').trim();
    if (words.length >= DESCRIPTION_CHARS) break;
  }
  return cutWords(words, DESCRIPTION_CHARS) || `${title}: ${pages.length} ${pages.length === 1 ? 'page' : 'pages'}`;
}

/**
 * index.html for a site: `title`, `lang`, `manifest` (path of book.json), `cover` (path), `url` (absolute
 * base or null), `runtime` (runtimeFiles(): entry, preload, wasm, under `prefix`, and style), `pages` ([{ src, width, height, alt, text } | { failed }], paths relative to the site),
 * `touchIcon` (path of the home screen icon, or none).
 */
export function indexHtml({ title, lang, manifest, cover, url, runtime, prefix, pages, touchIcon = null }) {
  const absolute = (relative) => (url ? escapeHtml(new URL(relative, url).href) : href(relative));
  const description = escapeHtml(describe(title, pages));
  const lines = [
    '<!doctype html>',
    `<html lang="${escapeHtml(lang || 'en')}">`,
    '<head>',
    '<meta charset="utf-8">',
    '<meta name="viewport" content="width=device-width, initial-scale=1, viewport-fit=cover">',
    `<title>${escapeHtml(title)}</title>`,
    `<meta name="description" content="${description}">`,
    `<meta property="og:title" content="${escapeHtml(title)}">`,
    `<meta property="og:description" content="${description}">`,
    '<meta property="og:type" content="book">',
    `<meta property="og:image" content="${absolute(cover)}">`,
    ...(url ? [`<meta property="og:url" content="${escapeHtml(url)}">`] : []),
    '<meta name="twitter:card" content="summary_large_image">',
    `<style>\n${runtime.style.trim()}\n</style>`,
    '<link rel="icon" href="data:,">',  // none: a cover thumbnail here would come before the first spread
    // Installable (web-app.mjs): the web app manifest beside this page, the bar's colour, the home screen icon.
    `<link rel="manifest" href="${href(WEB_MANIFEST)}">`,
    `<meta name="theme-color" content="${COLORS.theme}">`,
    VERSION_SLOT,
    ...(touchIcon ? [`<link rel="apple-touch-icon" href="${href(touchIcon)}">`] : []),
    // What the first spread needs, asked for at once: the chunks the reader's entry imports (as the bundler's
    // output lists them: build-bundles.mjs), the manifest and the engine's binary, fetched as the book fetches them (CORS mode, credentials of the
    // same origin), so the book's own requests are answered by these. Not the first page: Chromium failed
    // the book's read of a preloaded 600 KB page still arriving over a throttled network ("Failed to
    // fetch"), and the book asks for it itself as soon as it runs.
    ...runtime.preload.map((file) => `<link rel="modulepreload" href="${href(`${prefix}/${file}`)}">`),
    `<link rel="preload" href="${href(manifest)}" as="fetch" crossorigin>`,
    `<link rel="preload" href="${href(`${prefix}/${runtime.wasm}`)}" as="fetch" crossorigin>`,
    `<script type="module" src="${href(`${prefix}/${runtime.entry}`)}"></script>`,
    '</head>',
    '<body>',
    `<main id="conecurl-reader" data-document="${href(manifest)}">`,
    '<noscript>',
    `<h1>${escapeHtml(title)}</h1>`,
  ];
  // Each page's text is cut to NOSCRIPT_CHARS, and to its share of NOSCRIPT_TOTAL (at least 80), here
  // (its whole text is in its text file): the HTML comes before the first spread, and a long book's stays small.
  const share = Math.min(NOSCRIPT_CHARS, Math.max(80, Math.floor(NOSCRIPT_TOTAL / Math.max(1, pages.length))));
  pages.forEach((page, i) => {
    if (page.failed) {
      lines.push(`<section><p>Page ${i + 1} could not be published.</p></section>`);
      return;
    }
    lines.push(`<section><img src="${href(page.src)}" width="${page.imageWidth}" height="${page.imageHeight}" loading="lazy" alt="${escapeHtml(page.alt)}">`
      + (page.text.trim() ? `<p>${escapeHtml(cutWords(page.text, share))}</p>` : '') + '</section>');
  });
  lines.push('</noscript>', '</main>', '</body>', '</html>', '');
  return lines.join('\n');
}
