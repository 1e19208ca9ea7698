// Recorded narration's word times: a page's `narration.words` as an array, a JSON file of one, or a
// WebVTT file (a cue a word, or a cue a line with <00:00:01.200> timestamps before its words),
// checked and read into [{ start, end, text, rect? }] in seconds.

/** A WebVTT time ("01:02.500" or "1:01:02.500") in seconds, or NaN. */
function vttTime(text) {
  const m = /^(?:(\d+):)?(\d{1,2}):(\d{2})\.(\d{3})$/.exec(text.trim());
  return m ? Number(m[1] ?? 0) * 3600 + Number(m[2]) * 60 + Number(m[3]) + Number(m[4]) / 1000 : NaN;
}

const stripTags = (text) => text.replace(/<[^>]*>/g, '').replace(/&amp;/g, '&').replace(/&lt;/g, '<').replace(/&gt;/g, '>').trim();

/**
 * The words of a WebVTT file: one a cue, or, where a cue holds timestamps (<00:01.200>), one a stretch
 * between them; a cue whose text is JSON ({ "text", "rect" }) gives the word's rectangle too.
 */
export function parseVtt(source, where = 'the WebVTT file') {
  const lines = source.replace(/^\uFEFF/, '').split(/\r\n|\r|\n/);
  if (!/^WEBVTT(?:[ \t].*)?$/.test(lines[0])) throw new Error(`conecurl: ${where} is not WebVTT (its first line must be WEBVTT)`);
  const words = [];
  for (let i = 1; i < lines.length; i++) {
    const timing = /^\s*(\S+)\s+-->\s+(\S+)/.exec(lines[i]);
    if (!timing) continue;
    const [start, end] = [vttTime(timing[1]), vttTime(timing[2])];
    if (!(end >= start)) throw new Error(`conecurl: ${where} line ${i + 1}: a cue's times must be mm:ss.ttt --> mm:ss.ttt, start before end`);
    const body = [];
    while (i + 1 < lines.length && lines[i + 1].trim() !== '') body.push(lines[++i]);
    const text = body.join(' ').trim();
    if (text.startsWith('{')) {
      const cue = JSON.parse(text);
      words.push({ start, end, text: String(cue.text ?? ''), ...(cue.rect ? { rect: cue.rect } : {}) });
      continue;
    }
    // Karaoke-style timestamps inside the cue: each starts the stretch after it.
    const parts = text.split(/<(\d[\d:.]*)>/);
    const stretches = [{ start, text: parts[0] }];
    for (let k = 1; k < parts.length; k += 2) stretches.push({ start: vttTime(parts[k]), text: parts[k + 1] ?? '' });
    stretches.forEach((stretch, k) => {
      const said = stripTags(stretch.text);
      if (said === '') return;
      const stop = k + 1 < stretches.length ? stretches[k + 1].start : end;
      for (const word of said.split(/\s+/)) words.push({ start: stretch.start, end: stop, text: word });
    });
  }
  return words;
}

const fraction = (v) => Number.isFinite(v) && v >= -1e-9 && v <= 1 + 1e-9;

/** `words` checked: each { start, end, text, rect? } in order; an Error names the word and what is wrong. */
export function checkWordTimes(words, where) {
  if (!Array.isArray(words)) throw new TypeError(`conecurl: ${where} must be an array of { start, end, text, rect }, a WebVTT file or a JSON file of one`);
  let last = -Infinity;
  return words.map((word, i) => {
    const at = `${where}[${i}]`;
    if (word === null || typeof word !== 'object') throw new TypeError(`conecurl: ${at} must be { start, end, text, rect }`);
    const { start, end, text, rect } = word;
    if (!Number.isFinite(start) || !Number.isFinite(end) || start < 0 || end < start) {
      throw new RangeError(`conecurl: ${at} must have start and end in seconds, 0 <= start <= end; got start ${start}, end ${end}`);
    }
    if (start < last) throw new RangeError(`conecurl: ${at} starts before the word before it (words go in the order they are said)`);
    last = start;
    if (typeof text !== 'string') throw new TypeError(`conecurl: ${at}.text must be the word, a string`);
    if (rect !== undefined && !(Array.isArray(rect) && rect.length === 4 && rect.every(fraction))) {
      throw new TypeError(`conecurl: ${at}.rect must be [x, y, width, height] as fractions of the page (0 to 1)`);
    }
    return rect === undefined ? { start, end, text } : { start, end, text, rect: rect.slice() };
  });
}

/** A page's narration words, fetched when given as a file (`base`: where relative URLs are from). */
export async function loadWordTimes(words, where, base = globalThis.document?.baseURI) {
  if (typeof words !== 'string') return checkWordTimes(words, where);
  const url = new URL(words, base).href;
  let response;
  try {
    response = await fetch(url);
  } catch (error) {
    throw new Error(`conecurl: ${where} (${url}) could not be fetched: ${error.message}`);
  }
  if (!response.ok) throw new Error(`conecurl: ${where} (${url}) could not be fetched: HTTP ${response.status}`);
  const text = await response.text();
  if (text.replace(/^\uFEFF/, '').startsWith('WEBVTT')) return checkWordTimes(parseVtt(text, `${where} (${url})`), where);
  let json;
  try {
    json = JSON.parse(text);
  } catch {
    throw new Error(`conecurl: ${where} (${url}) is neither WebVTT nor JSON`);
  }
  return checkWordTimes(Array.isArray(json) ? json : json?.words, `${where} (${url})`);
}
