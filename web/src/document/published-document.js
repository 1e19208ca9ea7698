// A published document (the `document` option: a book.json that `conecurl publish` wrote, or a host's
// own pipeline): its pages are images, and its text, outline and links come from the files beside them
// (format.js), read with fetch. No pdf.js: search, the text layer and outline() read the same records
// as for a PDF opened at run time. A page's text comes from its own file (the text layer of a page opened),
// or from its text group (search reads many pages a request; offline, a page whose own file was never read).
import { MANIFEST, altText, checkManifest, checkTextGroup, decodePageText, emptyPageText } from './format.js';

const copyOutline = (entries) => entries.map(({ title, page, children }) => ({ title, page, children: copyOutline(children ?? []) }));

async function fetchJson(url, what) {
  let response;
  try {
    response = await fetch(url);
  } catch (error) {
    throw new Error(`conecurl: could not fetch ${what} ${url} (${error?.message ?? error})`);
  }
  if (!response.ok) throw new Error(`conecurl: could not fetch ${what} ${url}: HTTP ${response.status}`);
  try {
    return await response.json();
  } catch {
    throw new Error(`conecurl: ${what} ${url} is not JSON`);
  }
}

/** A page that was not published (its PDF page failed to draw): the book shows its placeholder. */
const missingPage = (index, why) => () => Promise.reject(new Error(`page ${index + 1} was not published (${why})`));

/**
 * Opens the published document whose manifest is at `url` (a folder's URL is taken to mean its
 * book.json). Resolves with what a book over it needs: its pages, shape, title, and the document's
 * pageText(), outline() and downloadUrl(). Rejects with an Error naming the file and what is wrong.
 * @param {string} url
 */
export async function openPublished(url) {
  const manifestUrl = new URL(url.endsWith('/') ? `${url}${MANIFEST}` : url, document.baseURI).href;
  const manifest = checkManifest(await fetchJson(manifestUrl, 'the document'), manifestUrl);
  const at = (path) => new URL(path, manifestUrl).href;
  const pages = manifest.pages.map((page, index) => {
    if (page.failed !== undefined) return { src: missingPage(index, page.failed), alt: `Page ${index + 1}` };
    const entry = { src: at(page.src), alt: page.alt ?? `Page ${index + 1}` };  // without one, from the page's text once read
    if (page.zoomSrc) entry.zoomSrc = at(page.zoomSrc);
    if (page.thumbSrc) entry.thumbSrc = at(page.thumbSrc);
    // Drawn while the page image loads: the manifest's own (the first spread's, inline), else the thumbnail.
    const placeholder = page.placeholder ?? page.thumbSrc;
    if (placeholder) entry.placeholder = at(placeholder);
    if (page.links?.length) entry.links = page.links.map((link) => ({ ...link }));
    // Recorded narration (`conecurl publish --narration`): its audio and word-times files, beside the pages.
    if (page.narration !== undefined) {
      const { src, words } = page.narration ?? {};
      if (!(typeof src === 'string' && src !== '' && typeof words === 'string' && words !== '')) {
        throw new Error(`conecurl: ${manifestUrl} is not a conecurl document: 'pages[${index}].narration' needs src and words, the paths of its audio and word-times files`);
      }
      entry.narration = { src: at(src), words: at(words) };
    }
    return entry;
  });
  const texts = new Map();  // page index -> Promise of its record, read once
  const groups = manifest.textGroups ?? [];
  const groupReads = new Map();  // a text group -> Promise of its read
  const held = new Map();  // page index -> its text file as its group held it (null: none), until its record is made
  const made = new Set();  // the pages whose record was made
  const emptyText = (index) => emptyPageText(manifest.pages[index]?.width, manifest.pages[index]?.height);
  const keep = (index, record) => {
    if (manifest.pages[index].alt === undefined) pages[index].alt = altText(index, record.text);
    made.add(index);
    held.delete(index);
    return record;
  };
  const groupOf = (index) => groups.find(({ first, count }) => index >= first && index < first + count) ?? null;
  const readGroup = (group) => {
    if (!groupReads.has(group)) {
      groupReads.set(group, fetchJson(at(group.src), 'the text group').then((json) => {
        checkTextGroup(json, at(group.src), group).forEach((page, k) => { if (!made.has(group.first + k)) held.set(group.first + k, page); });
      }));
    }
    return groupReads.get(group);
  };
  const fromGroup = (index, group) => {
    const page = held.get(index);
    return keep(index, page ? decodePageText(page, `${at(group.src)} (page ${index + 1})`) : emptyText(index));
  };
  // From the page's own file; where that cannot be read (offline, a page whose file was never read), from its group.
  const ownText = (index, file, group) => fetchJson(at(file), 'the page text').then((json) => keep(index, decodePageText(json, at(file))))
    .catch((error) => (group ? readGroup(group).then(() => fromGroup(index, group), () => { throw error; }) : Promise.reject(error)));
  const first = manifest.pages[0];
  return {
    pages,
    aspect: first.width / first.height,
    title: manifest.title || '',
    lang: manifest.lang || '',
    /** The manifest's URL. */
    url: manifestUrl,
    /**
     * Page `index`'s text record (format.js): from its text group where that is read or on its way (search,
     * read-aloud), else from its own file (a page's text layer). A page without a text file has no text.
     */
    pageText(index) {
      if (!texts.has(index)) {
        const file = manifest.pages[index]?.text;
        const group = groupOf(index);
        texts.set(index, !file ? Promise.resolve(emptyText(index))
          : groupReads.has(group) ? groupReads.get(group).then(() => fromGroup(index, group), () => ownText(index, file, group))
            : ownText(index, file, group));
      }
      return texts.get(index);
    },
    /**
     * Reads the text group that holds page `index` (one request for its pages, whose pageText() then needs
     * none); resolves once it is read, or could not be (pageText() then reads the page's own file), or at once without one.
     */
    async readTextGroup(index) {
      const group = groupOf(index);
      if (group) await readGroup(group).catch(() => {});
    },
    outline: async () => copyOutline(manifest.outline ?? []),
    /** The document's PDF, when it was published with it. */
    downloadUrl: async () => (manifest.download ? { url: at(manifest.download), made: false } : null),
    destroy() {},
  };
}
