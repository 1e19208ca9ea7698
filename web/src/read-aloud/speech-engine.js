// The default voice of read-aloud: the browser's speech synthesis (Web Speech API) behind the small
// engine interface read-aloud.js speaks through, so a host or a test can hand it any other engine.

/**
 * How long the voices are waited for when the browser has listed none yet: browsers list them late
 * (Chrome; Firefox asks speech-dispatcher, which it may first have to start, and lists its 13,000-odd
 * eSpeak voices about 1.9 s after the first getVoices()).
 */
export const VOICES_WAIT_MS = 6000;

const synthOf = () => globalThis.speechSynthesis ?? null;

/**
 * The browser's voices as { name, lang, default, local } (and `voice`, the SpeechSynthesisVoice); []
 * where there is no speech synthesis or it has no voice once `waitMs` passed without `voiceschanged`
 * (waited for once a page: whoever asks meanwhile waits for the same answer).
 */
export async function speechVoices(synth = synthOf(), waitMs = VOICES_WAIT_MS) {
  if (!synth || typeof synth.getVoices !== 'function') return [];
  let voices = synth.getVoices();
  // Waited for once a page: a browser that listed none by then has none (a later voiceschanged is read at once).
  if (voices.length === 0 && typeof synth.addEventListener === 'function') {
    if (!waiting.has(synth)) {
      waiting.set(synth, new Promise((resolve) => {
        const done = () => {
          clearTimeout(timer);
          synth.removeEventListener('voiceschanged', done);
          resolve();
        };
        const timer = setTimeout(done, waitMs);
        synth.addEventListener('voiceschanged', done);
      }));
    }
    await waiting.get(synth);
    voices = synth.getVoices();
  }
  return voices.map((voice) => ({ name: voice.name, lang: voice.lang, default: Boolean(voice.default), local: Boolean(voice.localService), voice }));
}
const waiting = new WeakMap();

/**
 * Calls `listener(count)` once, when the browser lists its voices after having listed none (after
 * speechVoices() gave up waiting); returns what stops listening.
 */
export function whenVoicesArrive(listener, synth = synthOf()) {
  if (!synth || typeof synth.addEventListener !== 'function') return () => {};
  const changed = () => {
    const count = synth.getVoices().length;
    if (count === 0) return;
    synth.removeEventListener('voiceschanged', changed);
    listener(count);
  };
  synth.addEventListener('voiceschanged', changed);
  return () => synth.removeEventListener('voiceschanged', changed);
}

/**
 * The sentences of `text` in language `lang`: [{ start, end }] (UTF-16 offsets, each with the spaces
 * after it; none of spaces alone). Intl.Segmenter's where the browser has it, else at . ! ? and the like.
 */
export function sentencesOf(text, lang) {
  let segments;
  if (typeof Intl.Segmenter === 'function') {
    let segmenter;
    try { segmenter = new Intl.Segmenter(lang || undefined, { granularity: 'sentence' }); } catch { segmenter = new Intl.Segmenter(undefined, { granularity: 'sentence' }); }
    segments = [...segmenter.segment(text)].map(({ index, segment }) => ({ start: index, end: index + segment.length }));
  } else {
    segments = [...text.matchAll(/[^.!?。！？…]*(?:[.!?。！？…]+["'”’)\]]*\s*|$)/gu)].map((m) => ({ start: m.index, end: m.index + m[0].length }));
  }
  return segments.filter(({ start, end }) => /\S/u.test(text.slice(start, end)));
}

/** A sentence longer than this is said in pieces, split at a clause (or, where none, at a space). */
export const MAX_UTTERANCE_CHARS = 200;

// Where a sentence may be split: after a clause's punctuation and the spaces that follow it.
const CLAUSE_END = /[,;:\u2013\u2014\u3001\uff0c\uff1b)\]]["'\u201d\u2019]*\s+/gu;

/**
 * What is said an utterance at a time: the sentences of `text` (sentencesOf), each longer than
 * MAX_UTTERANCE_CHARS cut into pieces at most that long, at the last clause end that fits, else at
 * the last space (a run of letters longer than that is cut where it must): [{ start, end }].
 */
export function utterancesOf(text, lang) {
  const pieces = [];
  for (let { start, end } of sentencesOf(text, lang)) {
    while (end - start > MAX_UTTERANCE_CHARS) {
      const window = text.slice(start, start + MAX_UTTERANCE_CHARS);
      let cut = 0;
      for (const m of window.matchAll(CLAUSE_END)) cut = m.index + m[0].length;
      if (cut === 0) for (const m of window.matchAll(/\s+/gu)) if (m.index > 0) cut = m.index + m[0].length;
      if (cut === 0 || cut >= end - start) cut = MAX_UTTERANCE_CHARS;
      pieces.push({ start, end: start + cut });
      start += cut;
    }
    pieces.push({ start, end });
  }
  return pieces;
}

/**
 * How long an utterance of `chars` characters may go without an event (start, a word, its end) before the
 * watchdog takes it for stalled: its text said at a slow voice's pace at `rate`, with a margin, plus time
 * for a voice to start (speech-dispatcher starts its module at the first word).
 */
export function stallLimitMs(chars, rate) {
  const SLOW_CHARS_PER_SECOND = 8;
  return (1.5 * 1000 * chars) / (SLOW_CHARS_PER_SECOND * rate) + 5000;
}

/**
 * The engine over `speechSynthesis`: speak(text, { lang, rate, pitch, voice, onSentence, onWord, onEnd,
 * onError }) says `text` a sentence an utterance, calls onSentence(start, end) as each begins (where the
 * voice reports no words, that is all that says where it is) and onWord(charIndex, charLength) at each
 * word boundary the voice reports; returns { pause, resume, cancel }. `voice` is a SpeechSynthesisVoice or a voice's name.
 *
 * Each utterance is spoken, and onEnd called, in a later task than the `end` of the one before: WebKitGTK
 * fires `end` from inside its own reset of the synthesiser, and forgets an utterance spoken before that
 * reset returns (it starts, and never ends).
 *
 * A watchdog: an utterance that gives no event for longer than stallLimitMs (Chrome's network voices stop
 * after about 15 s of speech with no `end` and no `error`; engines that break on long texts) is cancelled
 * and said again from its start; a second stall in a row ends the speech with onError, naming the voice.
 */
export function speechEngine(synth = synthOf()) {
  return {
    speak(text, { lang, rate = 1, pitch = 1, voice, onSentence, onWord, onEnd, onError }) {
      if (!synth) throw new Error('conecurl: this browser has no speech synthesis (speechSynthesis)');
      const chosen = typeof voice === 'string' ? synth.getVoices().find((v) => v.name === voice || v.voiceURI === voice) : voice;
      const sentences = utterancesOf(text, lang);
      let over = false;
      let paused = false;
      let held = null;      // the next sentence's index, held while paused
      let current = null;   // the utterance being said
      let currentIndex = 0; // its piece's index
      let watchdog = 0;     // its timer: no event by then, and it is taken for stalled
      let stalls = 0;       // stalls in a row
      const voiceName = () => chosen?.name ?? synth.getVoices().find((v) => v.default)?.name ?? 'the default voice';
      const watch = (index) => {
        clearTimeout(watchdog);
        if (over || paused) return;
        const { start, end } = sentences[index];
        watchdog = setTimeout(() => stalled(index), stallLimitMs(end - start, rate));
      };
      const stalled = (index) => {
        if (over || paused) return;
        current = null;  // its cancel's 'interrupted' (if any) is not ours
        synth.cancel();
        if (++stalls < 2) {
          setTimeout(() => next(index));
          return;
        }
        over = true;
        const seconds = Math.round(stallLimitMs(sentences[index].end - sentences[index].start, rate) / 1000);
        const error = new Error(`conecurl: the voice '${voiceName()}' stopped mid-sentence twice in a row (no event for ${seconds} s): reading ended`);
        setTimeout(() => { if (onError) onError(error); else onEnd?.(); });
      };
      const next = (index) => {
        if (over) return;
        if (paused) {
          held = index;
        } else if (index >= sentences.length) {
          over = true;
          onEnd?.();
        } else {
          say(index);
        }
      };
      const say = (index) => {
        const { start, end } = sentences[index];
        const utterance = new SpeechSynthesisUtterance(text.slice(start, end));
        if (lang) utterance.lang = lang;
        utterance.rate = rate;
        utterance.pitch = pitch;
        if (chosen) utterance.voice = chosen;
        const mine = () => !over && current === utterance;
        utterance.addEventListener('start', () => {
          if (!mine()) return;
          watch(index);
          onSentence?.(start, end);
        });
        utterance.addEventListener('boundary', (event) => {
          if (!mine()) return;
          watch(index);
          if ((event.name ?? 'word') === 'word') onWord?.(start + event.charIndex, event.charLength ?? 0);
        });
        utterance.addEventListener('end', () => {
          if (!mine()) return;
          clearTimeout(watchdog);
          stalls = 0;
          current = null;
          setTimeout(() => next(index + 1));
        });
        utterance.addEventListener('error', (event) => {
          if (!mine()) return;
          clearTimeout(watchdog);
          over = true;
          current = null;
          // A cancel() is not a failure: 'interrupted' and 'canceled' are the engine stopping as asked.
          if (event.error === 'interrupted' || event.error === 'canceled') return;
          const error = new Error(`conecurl: speech synthesis failed (${event.error})`);
          setTimeout(() => { if (onError) onError(error); else onEnd?.(); });
        });
        current = utterance;
        currentIndex = index;
        synth.speak(utterance);
        watch(index);
      };
      next(0);
      return {
        pause: () => {
          paused = true;
          clearTimeout(watchdog);  // a paused voice gives no event: not a stall
          synth.pause();
        },
        resume: () => {
          paused = false;
          synth.resume();
          if (held !== null) {
            const index = held;
            held = null;
            next(index);
          } else if (current) {
            watch(currentIndex);
          }
        },
        cancel: () => {
          over = true;
          clearTimeout(watchdog);
          current = null;
          synth.cancel();
        },
      };
    },
  };
}
