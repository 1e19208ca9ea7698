// Which voice reads, as readers expect (issue 37, after Readium's voice-selection recommendations): the
// page's language in the reader's own region first, local voices before network ones, eSpeak last; and
// the voice and speed a reader chose, remembered per language in localStorage (the `readAloudMemory` option).

/** The localStorage key the voice and speed are kept under unless a book's `readAloudMemory` names another. */
export const DEFAULT_MEMORY_KEY = 'conecurl-read-aloud';

// A language tag's subtags, lower case: 'en_US' and 'en-US' are ['en', 'us'].
const subtags = (tag) => String(tag ?? '').toLowerCase().replace(/_/g, '-').split('-').filter(Boolean);

/** A tag's language, lower case ('en' for 'en-GB'); '' for none. */
export const languageOfTag = (tag) => subtags(tag)[0] ?? '';

/** A tag's region, upper case ('GB' for 'en-GB', 'CN' for 'zh-Hans-CN', '419' for 'es-419'), or ''. */
export function regionOfTag(tag) {
  const region = subtags(tag).slice(1).find((part) => /^(?:[a-z]{2}|\d{3})$/.test(part));
  return region ? region.toUpperCase() : '';
}

// Where a language is mostly spoken: its voices of that region before the others' when neither the
// page nor the reader names a region (Readium's default regions, for the languages most voices speak).
const MAIN_REGION = {
  ar: 'SA', bn: 'BD', de: 'DE', en: 'US', es: 'ES', fr: 'FR', hi: 'IN', it: 'IT', ja: 'JP', ko: 'KR', nl: 'NL',
  pt: 'BR', ru: 'RU', sv: 'SE', zh: 'CN',
};

/**
 * A voice of a known low-quality engine: eSpeak's (espeak-ng, also as speech-dispatcher lists it to
 * Firefox: a language and an eSpeak variant, 'English (America)+Max') and MBROLA's. `voice`: a
 * SpeechSynthesisVoice, or speechVoices()'s entry (its voiceURI is its `voice`'s).
 */
export function isLowQuality(voice) {
  const name = String(voice?.name ?? '');
  const voiceURI = String(voice?.voiceURI ?? voice?.voice?.voiceURI ?? '');
  const text = `${name} ${voiceURI}`;
  return /e-?speak|mbrola/i.test(text) || (/^urn:moz-tts:speechd:/.test(voiceURI) && /\+[^\s+]+$/.test(name));
}

/** The reader's languages as the browser says them (navigator.languages), [] where there is none. */
export function readerLanguages() {
  const nav = globalThis.navigator;
  const list = nav?.languages?.length ? nav.languages : [nav?.language].filter(Boolean);
  return Array.from(list, String);
}

/**
 * `voices` ({ name, lang, local?, localService?, default?, voiceURI? }) in the order read-aloud offers
 * them for a page in `lang`: that language's first (the tag's language; the reader's first language
 * where `lang` is none), by region (the regions of that language in `languages`, the reader's, in
 * their order; then `lang`'s own; then the language's main region; voices naming no region; the other
 * regions A to Z), within a region eSpeak's last, local before network, the browser's default first,
 * then as listed; the other languages' after, by tag A to Z. A new array; the voices are those given.
 */
export function orderVoices(voices, lang, languages = readerLanguages()) {
  const want = languageOfTag(lang) || languageOfTag(languages[0]);
  const regions = [...languages.filter((tag) => languageOfTag(tag) === want).map(regionOfTag), regionOfTag(lang), MAIN_REGION[want] ?? '']
    .filter((region, at, all) => region && all.indexOf(region) === at);
  const keyed = voices.map((voice, at) => {
    const tag = String(voice?.lang ?? '');
    const mine = want !== '' && languageOfTag(tag) === want;
    const region = regionOfTag(tag);
    const place = regions.indexOf(region);
    return {
      voice, at, mine, region,
      rank: [
        mine ? 0 : 1,
        mine ? (place >= 0 ? place : region === '' ? regions.length : regions.length + 1) : 0,
        isLowQuality(voice) ? 1 : 0,
        (voice?.local ?? voice?.localService) === false ? 1 : 0,
        voice?.default ? 0 : 1,
      ],
      tag: mine ? '' : tag.toLowerCase().replace(/_/g, '-'),
    };
  });
  keyed.sort((a, b) => {
    for (let i = 0; i < 2; i++) if (a.rank[i] !== b.rank[i]) return a.rank[i] - b.rank[i];
    if (a.mine && a.region !== b.region) return a.region < b.region ? -1 : 1;  // other regions A to Z, each together
    if (a.tag !== b.tag) return a.tag < b.tag ? -1 : 1;
    for (let i = 2; i < a.rank.length; i++) if (a.rank[i] !== b.rank[i]) return a.rank[i] - b.rank[i];
    return a.at - b.at;
  });
  return keyed.map(({ voice }) => voice);
}

/**
 * The voice read-aloud takes for `lang` when none is chosen: the first of orderVoices() that is not a
 * low-quality engine's, else the first; null where there is none in that language.
 */
export function defaultVoice(voices, lang, languages = readerLanguages()) {
  const want = languageOfTag(lang) || languageOfTag(languages[0]);
  const ordered = orderVoices(voices, lang, languages).filter((voice) => languageOfTag(voice?.lang) === want);
  return ordered.find((voice) => !isLowQuality(voice)) ?? ordered[0] ?? null;
}

/**
 * The reader's voice and speed by language, kept in localStorage under `key` as
 * { [language]: { voice?, rate? } }; `key` false keeps nothing (undefined: DEFAULT_MEMORY_KEY). A storage
 * that throws (private mode, a sandboxed frame) or holds something else reads as empty and writes nothing.
 */
export function voiceMemory(key = DEFAULT_MEMORY_KEY) {
  const storageKey = key === undefined || key === null || key === true ? DEFAULT_MEMORY_KEY : key;
  const read = () => {
    if (storageKey === false) return {};
    try {
      const all = JSON.parse(globalThis.localStorage?.getItem(storageKey) ?? '{}');
      return all !== null && typeof all === 'object' && !Array.isArray(all) ? all : {};
    } catch {
      return {};
    }
  };
  const slot = (lang) => languageOfTag(lang) || languageOfTag(readerLanguages()[0]) || 'und';
  return {
    /** { voice?, rate? } remembered for `lang`'s language; only well-formed values. */
    recall(lang) {
      const kept = read()[slot(lang)] ?? {};
      const out = {};
      if (typeof kept.voice === 'string' && kept.voice !== '') out.voice = kept.voice;
      if (Number.isFinite(kept.rate) && kept.rate >= 0.1 && kept.rate <= 10) out.rate = kept.rate;
      return out;
    },
    /** Keeps `change`'s voice and rate for `lang`'s language; a voice given as undefined is forgotten. */
    remember(lang, change) {
      if (storageKey === false) return;
      const all = read();
      const kept = { ...(all[slot(lang)] ?? {}) };
      if ('voice' in change) {
        if (change.voice === undefined) delete kept.voice; else kept.voice = change.voice;
      }
      if (change.rate !== undefined) kept.rate = change.rate;
      all[slot(lang)] = kept;
      try { globalThis.localStorage?.setItem(storageKey, JSON.stringify(all)); } catch { /* storage off: nothing kept */ }
    },
  };
}

/**
 * `engine` (speech-engine.js speechEngine) speaking with the voice chosen for each text's language where
 * the reading names none: the one remembered for it (when the browser has it), else defaultVoice().
 * `voices`: speechVoices()'s list ({ name, lang, local, default, voice }).
 */
export function choosingEngine(engine, voices, memory) {
  const defaults = new Map();  // by language tag: ordering thousands of voices once a tag, not once a page
  return {
    speak(text, options) {
      if (options.voice !== undefined && options.voice !== null) return engine.speak(text, options);
      const remembered = memory.recall(options.lang).voice;
      if (!defaults.has(options.lang)) defaults.set(options.lang, defaultVoice(voices, options.lang));
      const chosen = voices.find((v) => remembered !== undefined && v.name === remembered) ?? defaults.get(options.lang);
      return engine.speak(text, chosen ? { ...options, voice: chosen.voice ?? chosen.name } : options);
    },
  };
}

/**
 * What a reading was given, kept in `memory` for `lang`. With `settings` (readAloud()'s, checked): a voice
 * and a rate given are kept, and a rate not given is the one remembered (set in `settings`, returned).
 * Without (update()'s checked changes, returned): a rate given is kept, a voice given is kept and one
 * given as undefined forgotten (back to the default voice).
 */
export function keepChoice(memory, lang, given, settings) {
  const change = {};
  if (settings ? given?.voice !== undefined : given && 'voice' in given) change.voice = settings ? settings.voice : given.voice;
  if (given?.rate !== undefined) change.rate = given.rate;
  if (settings && given?.rate === undefined) {
    const { rate } = memory.recall(lang);
    if (rate !== undefined) settings.rate = rate;
  }
  if (Object.keys(change).length > 0) memory.remember(lang, change);
  return settings ?? given;
}
