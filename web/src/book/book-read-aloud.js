// Read-aloud as the controller holds it before anything is read: read-aloud/book-reader.js imported
// at the first readAloud(), and the word read aloud handed to the page images (`marksOn`) once it is.
// Whether a book can read aloud, and the voices, are answered with read-aloud/speech-engine.js alone
// (the voices put in order by engine/voice-choice.js; the toolbar asks at once); a book that never
// asks fetches neither.
import { pageLanguage } from '../engine/language.js';

/**
 * Read-aloud (read-aloud/book-reader.js, imported at the first readAloud()): readAloud(), readingAloud,
 * readAloudVoices(), canReadAloud(); `pageText(index)` is a document page's text record.
 * @param {import('./book-wiring.js').BookPort} book
 */
export function makeReadAloud(controller, book, pageText) {
  let reader = null;
  let loading = null;
  const load = () => (loading ??= import('../read-aloud/book-reader.js').then(({ BookReader }) => {
    book.alive();
    return (reader ??= new BookReader(controller, book, pageText));
  }));
  const speech = () => import('../read-aloud/speech-engine.js');
  const speechVoices = async () => (await speech()).speechVoices();
  // Voices listed after canReadAloud() answered false: `readaloudvoices` tells the toolbar (and the host).
  let stopListening = null;
  const listenForVoices = async () => {
    const { whenVoicesArrive } = await speech();
    if (stopListening || book.destroyed()) return;
    stopListening = whenVoicesArrive((count) => {
      stopListening = null;
      if (!book.destroyed()) book.emit('readaloudvoices', { count });
    });
  };
  return {
    start: async (options) => (await load()).start(options),
    current: () => reader?.current ?? null,
    /** The language page `index` is read in (engine/language.js pageLanguage). */
    lang: (index) => pageLanguage(book.entries[index], book.document()?.lang, book.root),
    /**
     * The browser's voices: [{ name, lang, default, local, voiceURI }], in the order engine/voice-choice.js
     * gives them for the language of the open page (its own first, by region; the others after).
     */
    voices: async (lang) => {
      const [voices, { orderVoices }] = await Promise.all([speechVoices(), import('../engine/voice-choice.js')]);
      return orderVoices(voices, lang).map(({ name, lang: tag, default: isDefault, local, voice }) => ({
        name, lang: tag, default: isDefault, local, voiceURI: String(voice?.voiceURI ?? '') }));
    },
    /** Whether readAloud() can read this book: a page has recorded narration, or the browser has a voice. */
    can: async () => {
      if (book.entries.some((entry) => entry.narration)) return true;
      const can = (await speechVoices()).length > 0;
      if (!can) await listenForVoices();
      return can;
    },
    /** The word read aloud, drawn into its page's image while its leaf turns: the marks of page `index`. */
    marksOn: (index) => reader?.marksOn(index) ?? [],
    stop: () => {
      stopListening?.();
      stopListening = null;
      reader?.stop();
    },
  };
}
