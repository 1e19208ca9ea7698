// The default voice of read-aloud: the browser's speech synthesis (Web Speech API) behind the small
// engine interface read-aloud.js speaks through, so a host or a test can hand it any other engine.

/** How long the voices are waited for when the browser has listed none yet (Chrome lists them late). */
export const VOICES_WAIT_MS = 1500;

const synthOf = () => globalThis.speechSynthesis ?? null;

/**
 * The browser's voices as { name, lang, default, local } (and `voice`, the SpeechSynthesisVoice); []
 * where there is no speech synthesis or it has no voice once `waitMs` passed without `voiceschanged`
 * (waited for the first time only).
 */
export async function speechVoices(synth = synthOf(), waitMs = VOICES_WAIT_MS) {
  if (!synth || typeof synth.getVoices !== 'function') return [];
  let voices = synth.getVoices();
  // Waited for once a page: a browser that listed none by then has none (a later voiceschanged is read at once).
  if (voices.length === 0 && typeof synth.addEventListener === 'function' && !waited.has(synth)) {
    waited.add(synth);
    voices = await new Promise((resolve) => {
      const done = () => {
        clearTimeout(timer);
        synth.removeEventListener('voiceschanged', done);
        resolve(synth.getVoices());
      };
      const timer = setTimeout(done, waitMs);
      synth.addEventListener('voiceschanged', done);
    });
  }
  return voices.map((voice) => ({ name: voice.name, lang: voice.lang, default: Boolean(voice.default), local: Boolean(voice.localService), voice }));
}
const waited = new WeakSet();

/**
 * The engine over `speechSynthesis`: speak(text, { lang, rate, pitch, voice, onWord, onEnd, onError })
 * says `text` as one utterance and calls onWord(charIndex, charLength) at each word boundary it reports;
 * returns { pause, resume, cancel }. `voice` is a SpeechSynthesisVoice or a voice's name.
 */
export function speechEngine(synth = synthOf()) {
  return {
    speak(text, { lang, rate = 1, pitch = 1, voice, onWord, onEnd, onError }) {
      if (!synth) throw new Error('conecurl: this browser has no speech synthesis (speechSynthesis)');
      const utterance = new SpeechSynthesisUtterance(text);
      if (lang) utterance.lang = lang;
      utterance.rate = rate;
      utterance.pitch = pitch;
      const chosen = typeof voice === 'string' ? synth.getVoices().find((v) => v.name === voice || v.voiceURI === voice) : voice;
      if (chosen) utterance.voice = chosen;
      let over = false;
      utterance.addEventListener('boundary', (event) => {
        if (!over && (event.name ?? 'word') === 'word') onWord?.(event.charIndex, event.charLength ?? 0);
      });
      utterance.addEventListener('end', () => {
        if (over) return;
        over = true;
        onEnd?.();
      });
      utterance.addEventListener('error', (event) => {
        if (over) return;
        over = true;
        // A cancel() is not a failure: 'interrupted' and 'canceled' are the engine stopping as asked.
        if (event.error === 'interrupted' || event.error === 'canceled') return;
        const error = new Error(`conecurl: speech synthesis failed (${event.error})`);
        if (onError) onError(error); else onEnd?.();
      });
      synth.speak(utterance);
      return {
        pause: () => synth.pause(),
        resume: () => synth.resume(),
        cancel: () => {
          over = true;
          synth.cancel();
        },
      };
    },
  };
}
