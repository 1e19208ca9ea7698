// What read-aloud says on a page and where each of its words lies on the page: the page's script,
// from its recorded narration, a document's text record, a live HTML page's text or its alt text.
import { recordRects, htmlPageBox, htmlPageText, foldText } from '../document/text-index.js';
import { loadWordTimes } from './word-times.js';

const WORDS = /\S+/gu;
const folded = (text) => foldText(text).folded.replace(/[^\p{L}\p{N}]/gu, '');

/** The words of `text`: [{ start, end, text }] (UTF-16 offsets; a word is a run without spaces). */
export function wordsOf(text) {
  return [...text.matchAll(WORDS)].map((m) => ({ start: m.index, end: m.index + m[0].length, text: m[0] }));
}

/** The index of the word that holds (or follows) character `charIndex`; -1 past the last. */
export function wordAt(words, charIndex) {
  for (let i = 0; i < words.length; i++) if (charIndex < words[i].end) return i;
  return -1;
}

/**
 * A page's script: { page, kind, text, words, lang, audio? }. kind 'narration' (audio, words with
 * times), 'text' (a document's or an HTML page's text, words with their rects), 'alt' (the page's alt
 * text: words without places) or 'none' (nothing to say: skipped with a short pause).
 * @param {number} page
 * @param {{ entry: object, record: () => Promise<object|null>, lang: string }} from
 *   entry: the page's entry; record: a document's text record of it (null for other books)
 */
export async function pageScript(page, { entry, record, lang }) {
  const text = await pageText(entry, record);
  if (entry.narration) {
    const timed = await loadWordTimes(entry.narration.words, `page ${page} narration.words`);
    return { page, kind: 'narration', text: text.text, words: placeTimedWords(timed, text), lang, audio: entry.narration.src };
  }
  if (text.text.trim() !== '') return { page, kind: 'text', text: text.text, words: wordsOf(text.text).map((w) => ({ ...w, rects: text.rects(w.start, w.end) })), lang };
  const alt = (entry.alt ?? '').trim();
  if (alt !== '') return { page, kind: 'alt', text: alt, words: wordsOf(alt).map((w) => ({ ...w, rects: [] })), lang };
  return { page, kind: 'none', text: '', words: [], lang };
}

// The page's own text and where a range of it lies: a document's record, a live HTML page's text, or none.
async function pageText(entry, record) {
  if (entry.html) {
    const box = htmlPageBox(entry.html);
    const read = htmlPageText(entry.html);
    return { text: read.text, rects: (start, end) => (box ? read.rects(start, end, box) : []) };
  }
  const found = await record();
  if (found) return { text: found.text, rects: (start, end) => recordRects(found, start, end) };
  return { text: '', rects: () => [] };
}

/**
 * Narration's words with their places: a word's own `rect`, else the page's word it was matched to
 * (the next page word with the same letters, a few words ahead at most), else none.
 */
function placeTimedWords(timed, text) {
  const pageWords = wordsOf(text.text);
  const keys = pageWords.map((w) => folded(w.text));
  let next = 0;
  return timed.map((word) => {
    const placed = { start: word.start, end: word.end, text: word.text, rects: word.rect ? [word.rect] : [] };
    const key = folded(word.text);
    if (key === '') return placed;
    for (let k = next; k < Math.min(keys.length, next + 6); k++) {
      if (keys[k] !== key) continue;
      next = k + 1;
      if (!word.rect) placed.rects = text.rects(pageWords[k].start, pageWords[k].end);
      break;
    }
    return placed;
  });
}
