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

/**
 * The engine over `speechSynthesis`: speak(text, { lang, rate, pitch, voice, onSentence, onWord, onEnd,
 * onError }) says `text` a sentence an utterance, calls onSentence(start, end) as each begins (where the
 * voice reports no words, that is all that says where it is) and onWord(charIndex, charLength) at each
 * word boundary the voice reports; returns { pause, resume, cancel }. `voice` is a SpeechSynthesisVoice or a voice's name.
 *
 * Each utterance is spoken, and onEnd called, in a later task than the `end` of the one before: WebKitGTK
 * fires `end` from inside its own reset of the synthesiser, and forgets an utterance spoken before that
 * reset returns (it starts, and never ends).
 */
export function speechEngine(synth = synthOf()) {
  return {
    speak(text, { lang, rate = 1, pitch = 1, voice, onSentence, onWord, onEnd, onError }) {
      if (!synth) throw new Error('conecurl: this browser has no speech synthesis (speechSynthesis)');
      const chosen = typeof voice === 'string' ? synth.getVoices().find((v) => v.name === voice || v.voiceURI === voice) : voice;
      const sentences = sentencesOf(text, lang);
      let over = false;
      let paused = false;
      let held = null;      // the next sentence's index, held while paused
      let current = null;   // the utterance being said
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
        utterance.addEventListener('start', () => { if (mine()) onSentence?.(start, end); });
        utterance.addEventListener('boundary', (event) => {
          if (mine() && (event.name ?? 'word') === 'word') onWord?.(start + event.charIndex, event.charLength ?? 0);
        });
        utterance.addEventListener('end', () => {
          if (!mine()) return;
          current = null;
          setTimeout(() => next(index + 1));
        });
        utterance.addEventListener('error', (event) => {
          if (!mine()) return;
          over = true;
          current = null;
          // A cancel() is not a failure: 'interrupted' and 'canceled' are the engine stopping as asked.
          if (event.error === 'interrupted' || event.error === 'canceled') return;
          const error = new Error(`conecurl: speech synthesis failed (${event.error})`);
          setTimeout(() => { if (onError) onError(error); else onEnd?.(); });
        });
        current = utterance;
        synth.speak(utterance);
      };
      next(0);
      return {
        pause: () => {
          paused = true;
          synth.pause();
        },
        resume: () => {
          paused = false;
          synth.resume();
          if (held !== null) {
            const index = held;
            held = null;
            next(index);
          }
        },
        cancel: () => {
          over = true;
          current = null;
          synth.cancel();
        },
      };
    },
  };
}
