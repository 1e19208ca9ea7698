// A published document (the `document` option: a book.json that `conecurl publish` wrote, or a host's
// own pipeline): its pages are images, and its text, outline and links come from the files beside them
// (format.js), read with fetch. No pdf.js: search, the text layer and outline() read the same records
// as for a PDF opened at run time.
import { MANIFEST, altText, checkManifest, decodePageText, emptyPageText } from './format.js';

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
  const texts = new Map();  // page index -> Promise of its record, fetched once
  const first = manifest.pages[0];
  return {
    pages,
    aspect: first.width / first.height,
    title: manifest.title || '',
    lang: manifest.lang || '',
    /** The manifest's URL. */
    url: manifestUrl,
    /** Page `index`'s text record (format.js); a page without a text file has no text. */
    pageText(index) {
      if (!texts.has(index)) {
        const file = manifest.pages[index]?.text;
        texts.set(index, file
          ? fetchJson(at(file), 'the page text').then((json) => {
            const record = decodePageText(json, at(file));
            if (manifest.pages[index].alt === undefined) pages[index].alt = altText(index, record.text);
            return record;
          })
          : Promise.resolve(emptyPageText(manifest.pages[index]?.width, manifest.pages[index]?.height)));
      }
      return texts.get(index);
    },
    outline: async () => copyOutline(manifest.outline ?? []),
    /** The document's PDF, when it was published with it. */
    downloadUrl: async () => (manifest.download ? { url: at(manifest.download), made: false } : null),
    destroy() {},
  };
}
