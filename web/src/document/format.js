// The published document's format, in one place: what `conecurl publish` writes (cli/) and what a book
// opened with the `document` option reads (published-document.js). A folder holds `book.json` (the
// pages, their images, links and the outline), one text file a page (its words and where they lie), and
// the same files again a few at a time (text groups: what search reads, one request for many pages).
// The same page-text record serves a PDF opened with pdf.js: search and the text layer read only it.

export const FORMAT = 'conecurl-document';
export const FORMAT_VERSION = 1;
/** The manifest's file name in a published folder. */
export const MANIFEST = 'book.json';
/** The folders of a published document, by what they hold. */
export const FOLDERS = { pages: 'pages', zoom: 'zoom', thumbs: 'thumbs', text: 'text' };
/** Characters of a page's text in an `alt` made from it (the noscript copy's images; the whole text is in its text file). */
export const ALT_CHARS = 100;
/** A link's rectangle in the manifest, in fractions of its page to this step (a tenth of a pixel on a 1000 px page). */
const LINK_STEP = 1e4;

const pageNumber = (index) => String(index + 1).padStart(4, '0');

/** The path, inside the folder, of page `index`'s file of `kind` (a FOLDERS key) with extension `ext`. */
export function pagePath(kind, index, ext) {
  return `${FOLDERS[kind]}/${pageNumber(index)}.${ext}`;
}

// ---- a page's text --------------------------------------------------------------------------------

/**
 * A page's text as search and the text layer read it: `text` (the items joined, a line break where a
 * line ends), `items` ({ start, end, str, tx, width, family, ascent, descent }: where each piece lies in
 * `text`, and on the page: `tx` its baseline transform in page units, y down, `width` its advance), and
 * the page's `width` and `height` in the same units.
 */

const multiply = (m, n) => [m[0] * n[0] + m[2] * n[1], m[1] * n[0] + m[3] * n[1], m[0] * n[2] + m[2] * n[3],
  m[1] * n[2] + m[3] * n[3], m[0] * n[4] + m[2] * n[5] + m[4], m[1] * n[4] + m[3] * n[5] + m[5]];

/**
 * The record of a page from pdf.js: `content` is page.getTextContent(), `viewport` its
 * page.getViewport({ scale: 1 }) (as pdf.js's TextLayer places the items).
 */
export function pageTextRecord(content, viewport) {
  let text = '';
  const items = [];
  for (const item of content.items) {
    if (typeof item.str !== 'string') continue;  // marked-content boundaries carry no text
    const start = text.length;
    text += item.str;
    if (item.str.length > 0) {
      const style = content.styles[item.fontName] ?? {};
      items.push({ start, end: text.length, str: item.str, tx: multiply(viewport.transform, item.transform),
        width: item.width * viewport.scale, family: style.fontFamily || 'sans-serif',
        ascent: style.ascent || 0.8, descent: style.descent || -0.2 });
    }
    if (item.hasEOL) text += '\n';
  }
  return { text, items, width: viewport.width, height: viewport.height };
}

/** A page without text (one whose text could not be read, or that has none): search finds nothing there. */
export const emptyPageText = (width = 1, height = 1) => ({ text: '', items: [], width, height });

const round = (v) => Math.round(v * 100) / 100;

/**
 * A record as its text file holds it: fonts listed once, each item
 * [start, end, a, b, c, d, e, f, width, font] (its transform's six numbers, to 1/100 of a unit).
 */
export function encodePageText(record) {
  const fonts = [];
  const fontIndex = new Map();
  const items = record.items.map((item) => {
    const key = `${item.family}|${item.ascent}|${item.descent}`;
    if (!fontIndex.has(key)) {
      fontIndex.set(key, fonts.length);
      fonts.push({ family: item.family, ascent: round(item.ascent), descent: round(item.descent) });
    }
    return [item.start, item.end, ...item.tx.map(round), round(item.width), fontIndex.get(key)];
  });
  return { format: FORMAT, version: FORMAT_VERSION, width: round(record.width), height: round(record.height),
    text: record.text, fonts, items };
}

/** The record in a text file (`json`, read from `where`); an Error names the file and what is wrong. */
export function decodePageText(json, where) {
  const bad = (what) => new Error(`conecurl: the page text ${where} ${what}`);
  if (!json || typeof json !== 'object' || typeof json.text !== 'string' || !Array.isArray(json.items) || !Array.isArray(json.fonts)) {
    throw bad('is not a conecurl page-text file ({ text, fonts, items })');
  }
  if (json.version > FORMAT_VERSION) throw bad(`is format version ${json.version}; this conecurl reads version ${FORMAT_VERSION}: update conecurl`);
  if (!(json.width > 0 && json.height > 0)) throw bad('has no page size (width, height)');
  const items = json.items.map((row, i) => {
    const font = Array.isArray(row) && row.length === 10 ? json.fonts[row[9]] : undefined;
    if (!font || !row.slice(0, 9).every(Number.isFinite) || !(row[0] >= 0 && row[1] <= json.text.length && row[0] < row[1])) {
      throw bad(`has a bad item ${i}`);
    }
    const [start, end, a, b, c, d, e, f, width] = row;
    return { start, end, str: json.text.slice(start, end), tx: [a, b, c, d, e, f], width,
      family: String(font.family), ascent: Number(font.ascent), descent: Number(font.descent) };
  });
  return { text: json.text, items, width: json.width, height: json.height };
}

/** `text` with its white space folded, cut after at most `max` characters at a word's end with an ellipsis. */
export function cutWords(text, max = Infinity) {
  const words = text.replace(/\s+/g, ' ').trim();
  return words.length > max ? `${words.slice(0, max).replace(/\s+\S*$/, '')}…` : words;
}

/** A page's `alt` from its text: "Page N: its words" (at most `max` characters of them), or "Page N". */
export function altText(index, text, max = Infinity) {
  const words = cutWords(text, max);
  return words ? `Page ${index + 1}: ${words}` : `Page ${index + 1}`;
}

// ---- text groups: many pages' text files in one ---------------------------------------------------

/** Pages a text group holds (the last one fewer): one request for that many pages' text, and a short parse. */
export const TEXT_GROUP_PAGES = 32;

/** The path, inside the folder, of the text group of pages `first` to `last` (from 0): text/pages-0001-0032.json. */
export function textGroupPath(first, last) {
  return `${FOLDERS.text}/pages-${pageNumber(first)}-${pageNumber(last)}.json`;
}

/** The text groups of a document of `pageCount` pages, as book.json names them: [{ first, count, src }]. */
export function planTextGroups(pageCount, size = TEXT_GROUP_PAGES) {
  return Array.from({ length: Math.ceil(pageCount / size) }, (_, k) => {
    const first = k * size;
    const count = Math.min(size, pageCount - first);
    return { first, count, src: textGroupPath(first, first + count - 1) };
  });
}

/** A text group's file from its pages' text files as written (JSON text each, or null for a page without one). */
export function encodeTextGroup(first, files) {
  return `{"format":"${FORMAT}","version":${FORMAT_VERSION},"first":${first},"pages":[${files.map((file) => file ?? 'null').join(',')}]}\n`;
}

/**
 * The pages of a text group's file (`json`, read from `where`) for the group `{ first, count }` the manifest
 * names: each page's text file as it holds it (decodePageText() reads one when it is wanted, so that no task
 * decodes a whole group), null for a page without one. An Error names the file and what is wrong.
 */
export function checkTextGroup(json, where, { first, count }) {
  const bad = (what) => new Error(`conecurl: the text group ${where} ${what}`);
  if (!json || typeof json !== 'object' || json.format !== FORMAT || !Array.isArray(json.pages)) {
    throw bad(`is not a conecurl text group ({ format: "${FORMAT}", first, pages })`);
  }
  if (json.version > FORMAT_VERSION) throw bad(`is format version ${json.version}; this conecurl reads version ${FORMAT_VERSION}: update conecurl`);
  if (json.first !== first || json.pages.length !== count) throw bad(`holds pages ${json.first} + ${json.pages.length}, not the ${first} + ${count} book.json names`);
  return json.pages;
}

// ---- the manifest ---------------------------------------------------------------------------------

/**
 * The manifest of a published document. `pages[i]`: { width, height (page units), src, zoomSrc?,
 * thumbSrc?, placeholder? (a small image drawn while `src` loads: a path or a data: URL), text?, alt? (else made from
 * the text once read), links? ([{ rect, href } | { rect, page }]) } with paths relative to the manifest, or { width, height, failed: 'why' } for a page that could not be drawn.
 * `textGroups` (optional): [{ first, count, src }], the text groups, in page order, each naming its file.
 * @param {{ title?: string, lang?: string, pages: object[], outline?: object[], download?: string|null, textGroups?: object[] }} parts
 */
export function makeManifest({ title = '', lang = '', pages, outline = [], download = null, textGroups }) {
  const step = (v) => Math.round(v * LINK_STEP) / LINK_STEP;
  const rounded = pages.map((page) => (page.links ? { ...page, links: page.links.map((link) => ({ ...link, rect: link.rect.map(step) })) } : page));
  return { format: FORMAT, version: FORMAT_VERSION, title, lang, pageCount: pages.length, pages: rounded, outline, download,
    ...(textGroups ? { textGroups } : {}) };
}

const isRect = (r) => Array.isArray(r) && r.length === 4 && r.every((v) => Number.isFinite(v) && v >= 0 && v <= 1);
const isPath = (v) => typeof v === 'string' && v !== '';

function checkOutline(entries, count, bad, where = 'outline') {
  if (!Array.isArray(entries)) throw bad(`'${where}' is not an array`);
  entries.forEach((entry, i) => {
    if (!entry || typeof entry.title !== 'string' || !(Number.isInteger(entry.page) && entry.page >= 0 && entry.page < count)) {
      throw bad(`'${where}[${i}]' needs a title and a page below ${count}`);
    }
    checkOutline(entry.children ?? [], count, bad, `${where}[${i}].children`);
  });
}

/**
 * A manifest read from `where` (its URL or path), checked: an Error names the file and the first thing
 * wrong. Returns it as given.
 */
export function checkManifest(json, where) {
  const bad = (what) => new Error(`conecurl: ${where} is not a conecurl document: ${what}`);
  if (!json || typeof json !== 'object' || json.format !== FORMAT) throw bad(`its 'format' is not "${FORMAT}"`);
  if (!(Number.isInteger(json.version) && json.version >= 1)) throw bad("it has no 'version'");
  if (json.version > FORMAT_VERSION) {
    throw new Error(`conecurl: ${where} is format version ${json.version}; this conecurl reads version ${FORMAT_VERSION}: update conecurl`);
  }
  if (!Array.isArray(json.pages) || json.pages.length === 0) throw bad("'pages' is empty or missing");
  const count = json.pages.length;
  json.pages.forEach((page, i) => {
    if (!page || !(page.width > 0 && page.height > 0)) throw bad(`'pages[${i}]' has no width and height`);
    if (page.failed !== undefined) return;
    if (!isPath(page.src)) throw bad(`'pages[${i}].src' is not a path`);
    for (const key of ['zoomSrc', 'thumbSrc', 'placeholder', 'text']) {
      if (page[key] !== undefined && !isPath(page[key])) throw bad(`'pages[${i}].${key}' is not a path`);
    }
    (page.links ?? []).forEach((link, k) => {
      const ok = link && isRect(link.rect) && (typeof link.href === 'string' || (Number.isInteger(link.page) && link.page >= 0 && link.page < count));
      if (!ok) throw bad(`'pages[${i}].links[${k}]' needs a rect and an href or a page below ${count}`);
    });
  });
  checkOutline(json.outline ?? [], count, bad);
  if (json.download != null && !isPath(json.download)) throw bad("'download' is not a path");
  if (json.textGroups !== undefined) {
    if (!Array.isArray(json.textGroups)) throw bad("'textGroups' is not an array");
    let next = 0;  // groups come in page order and do not overlap
    json.textGroups.forEach((group, i) => {
      const ok = group && isPath(group.src) && Number.isInteger(group.first) && Number.isInteger(group.count)
        && group.first >= next && group.count > 0 && group.first + group.count <= count;
      if (!ok) throw bad(`'textGroups[${i}]' needs a src and pages (first, count) after the group before it and below ${count}`);
      next = group.first + group.count;
    });
  }
  return json;
}
