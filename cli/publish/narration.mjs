// `conecurl publish --narration <folder>`: each page's recorded narration found by its file names
// (page-N.mp3 … and page-N.vtt or page-N.json, N the PDF's page number from 1) and checked before
// anything is written, the word times by the reader's own parser (web/src/read-aloud/word-times.js), so
// that a bad file is named at publish, by file, page, word or line, and what is wrong, instead of when
// a reader presses Read.
import fs from 'node:fs';
import path from 'node:path';
import { checkWordTimes, parseVtt } from '../../web/src/read-aloud/word-times.js';
import { AUDIO_FORMATS, audioSeconds } from './audio-duration.mjs';
import { inputError } from './errors.mjs';

export const AUDIO_EXTENSIONS = Object.keys(AUDIO_FORMATS);
export const WORD_TIMES_EXTENSIONS = ['vtt', 'json'];
/** A word may end this many seconds past the audio's end as its header gives it (encoders pad the last frame). */
export const END_SLACK = 0.1;

/** page-N.ext, any case, N with or without leading zeros. */
const NAME = /^page-(\d+)\.([a-z0-9]+)$/i;
/** A name meant as a page's narration but not written by the rule (page1.mp3, Page_2.vtt, page 3.json). */
const NEAR = new RegExp(`^page[\\s_]*\\d+\\.(?:${[...AUDIO_EXTENSIONS, ...WORD_TIMES_EXTENSIONS].join('|')})$`, 'i');

const AUDIO_LIST = AUDIO_EXTENSIONS.map((ext) => `.${ext}`).join(', ');
const seconds = (s) => `${Math.round(s * 1000) / 1000} s`;

/** `mm:ss.ttt`, as WebVTT writes a time. */
const vttTime = (s) => `${String(Math.floor(s / 60)).padStart(2, '0')}:${(s % 60).toFixed(3).padStart(6, '0')}`;

/** The files of `folder` by page: { pages: Map(N -> { audio, words }), ignored: [names] }; an error names a bad name. */
function scan(folder, pageCount, input) {
  let names;
  try {
    if (!fs.statSync(folder).isDirectory()) throw inputError(`--narration ${folder} is a file, not a folder: give the folder that holds page-1.mp3 and page-1.vtt (or .json), …`);
    names = fs.readdirSync(folder, { withFileTypes: true }).filter((entry) => entry.isFile()).map((entry) => entry.name).sort();
  } catch (error) {
    if (error.code === 'ENOENT') throw inputError(`--narration ${folder} does not exist: give the folder that holds page-1.mp3 and page-1.vtt (or .json), …`);
    if (error.code) throw Object.assign(inputError(`--narration ${folder} cannot be read (${error.code}): check its permissions`), { cause: error });
    throw error;
  }
  const pages = new Map();
  const ignored = [];
  for (const name of names) {
    if (name.startsWith('.')) continue;
    const file = path.join(folder, name);
    const match = NAME.exec(name);
    const ext = match?.[2].toLowerCase();
    const kind = AUDIO_EXTENSIONS.includes(ext) ? 'audio' : WORD_TIMES_EXTENSIONS.includes(ext) ? 'words' : null;
    if (!match || !kind) {
      if (NEAR.test(name)) {
        throw inputError(`narration ${file} is not named page-N.<ext>: name it like page-1.mp3 (audio: ${AUDIO_LIST}) or page-1.vtt / page-1.json (word times)`);
      }
      ignored.push(name);
      continue;
    }
    const number = Number(match[1]);
    if (number < 1 || number > pageCount) {
      throw inputError(`narration ${file} is for page ${number}, but ${input} has ${pageCount} pages (numbered from 1): rename or remove it`);
    }
    const page = pages.get(number) ?? {};
    if (page[kind]) {
      throw inputError(`narration ${page[kind].file} and ${name} are both page ${number}'s ${kind === 'audio' ? 'audio' : 'word times'}: keep one`);
    }
    page[kind] = { file, name, ext };
    pages.set(number, page);
  }
  for (const [number, page] of pages) {
    if (!page.words) throw inputError(`narration ${page.audio.file} has no word times: add page-${number}.vtt or page-${number}.json beside it`);
    if (!page.audio) throw inputError(`narration ${page.words.file} has no audio: add page-${number}.mp3 (or ${AUDIO_LIST}) beside it`);
  }
  if (pages.size === 0) {
    throw inputError(`--narration ${folder} holds no narration: name each page's audio page-N.mp3 (or ${AUDIO_LIST}) and its word times page-N.vtt or page-N.json`);
  }
  return { pages, ignored };
}

/** The words of a word-times file (WebVTT or JSON, by its extension), checked; an error says where and what. */
function readWords({ file, ext }, number) {
  const at = `narration ${file} (page ${number})`;
  // word-times.js says `conecurl: <where>[i] …` or `conecurl: <where> line N: …`: the same, with the word's
  // number (from 1), its text and its time in place of [i].
  const fail = (error, words) => {
    let message = String(error.message).replace(/^conecurl: /, '').replace(file, '');
    const index = /^\[(\d+)\]/.exec(message);
    if (index) {
      const word = words?.[Number(index[1])];
      const said = word && typeof word === 'object' ? ` "${word.text}"${Number.isFinite(word.start) ? ` at ${vttTime(word.start)}` : ''}` : '';
      message = `word ${Number(index[1]) + 1}${said}${message.slice(index[0].length).replace(/^\.(\w+)/, ': its $1')}`;
    }
    return Object.assign(inputError(`${at} ${message.trim()}: fix the file and publish again`), { cause: error });
  };
  let text;
  try {
    text = fs.readFileSync(file, 'utf8');
  } catch (error) {
    throw Object.assign(inputError(`${at} cannot be read (${error.code ?? error.message})`), { cause: error });
  }
  let words;
  if (ext === 'vtt') {
    try {
      words = parseVtt(text, file);
    } catch (error) {
      // A cue whose text is JSON that does not parse: JSON.parse's message names no line; the first
      // line that opens such a text and does not parse alone is most likely it.
      if (error instanceof SyntaxError) {
        const parses = (line) => { try { JSON.parse(line); return true; } catch { return false; } };
        const line = text.split(/\r\n|\r|\n/).findIndex((l) => l.trim().startsWith('{') && !parses(l));
        throw fail(new Error(`${line >= 0 ? `line ${line + 1}: ` : ''}a cue's JSON text cannot be read (${error.message})`));
      }
      throw fail(error);
    }
  } else {
    let json;
    try {
      json = JSON.parse(text.replace(/^\uFEFF/, ''));
    } catch (error) {
      throw fail(new Error(`is not JSON (${error.message})`));
    }
    words = Array.isArray(json) ? json : json?.words;
  }
  try {
    words = checkWordTimes(words, file);
  } catch (error) {
    throw fail(error, words);
  }
  if (words.length === 0) throw inputError(`${at} holds no words: give each word said with its start and end in seconds`);
  return words;
}

/**
 * The narration of the published pages, read from `folder` and checked (nothing is written): `numbers`
 * are the PDF's page numbers published, `pageCount` the PDF's. `onPage(done, total)` is called after
 * each page is checked. Returns { pages: Map(N -> { audio, words, seconds, wordCount }), unpublished: [N], ignored: [names] }.
 */
export function readNarration(folder, { pageCount, numbers, input, onPage = () => {} }) {
  const { pages, ignored } = scan(folder, pageCount, input);
  const published = new Set(numbers);
  const unpublished = [...pages.keys()].filter((n) => !published.has(n)).sort((a, b) => a - b);
  const checked = new Map();
  const toCheck = [...pages.keys()].filter((n) => published.has(n)).sort((a, b) => a - b);
  for (const number of toCheck) {
    const { audio, words: wordsFile } = pages.get(number);
    const words = readWords(wordsFile, number);
    let length;
    try {
      length = audioSeconds(fs.readFileSync(audio.file), audio.ext);
    } catch (error) {
      throw Object.assign(inputError(`narration ${audio.file} (page ${number}) ${error.code ? `cannot be read (${error.code})` : error.message}: `
        + 'give the page\'s recording in that format, or rename it to its own extension'), { cause: error });
    }
    if (length !== null) {
      const past = words.findIndex((word) => word.end > length + END_SLACK);
      if (past >= 0) {
        const word = words[past];
        throw inputError(`narration ${wordsFile.file} (page ${number}) word ${past + 1} "${word.text}" ends at ${seconds(word.end)}, `
          + `past the end of ${audio.name} (${seconds(length)} long): fix the times, or give the whole recording`);
      }
    }
    checked.set(number, { audio, words: wordsFile, seconds: length, wordCount: words.length });
    onPage(checked.size, toCheck.length);
  }
  return { pages: checked, unpublished, ignored };
}
