// A tiny murmuring voice for the demo's picture book: no recordings ship and nothing is downloaded, so each
// page's narration is synthesised here (a WAV and its word times), in the browser or in Node.
import { mulberry32 } from './seeded-random.js';

const VOWELS = {  // formant frequencies (Hz) of a few vowels, F1 F2 F3, and a gain that evens their loudness
  a: [730, 1090, 2440, 1.5], e: [530, 1840, 2480, 1], i: [300, 2200, 2950, 0.45], o: [570, 840, 2410, 1],
  u: [320, 900, 2250, 0.38], y: [300, 2100, 2900, 0.45],
};
const BANDWIDTHS = [80, 100, 140];
const FORMANT_GAINS = [1, 0.55, 0.25];

/** A word's syllables: each a vowel group (its vowel) and the consonants before it (its onset). */
function syllables(word) {
  const letters = word.toLowerCase().replace(/[^a-z]/g, '');
  const parts = [...letters.matchAll(/([^aeiouy]*)([aeiouy]+)/g)].map((m) => ({ onset: m[1], vowel: m[2][0] }));
  if (parts.length === 0) return { parts: [{ onset: letters, vowel: 'u' }], coda: '' };  // "Hmm", a number: a murmur
  let coda = letters.replace(/^.*[aeiouy]/, '');
  const last = parts.at(-1);
  if (parts.length > 1 && !coda && last.vowel === 'e' && last.onset.length === 1 && !letters.endsWith('le')) {
    coda = parts.pop().onset;  // a silent e: "made", "stone"
  }
  return { parts, coda };
}

/** The kind of noise a consonant cluster makes: a hiss, a short burst, or a hum (voiced, no noise). */
function consonant(cluster) {
  if (!cluster) return null;
  if (/[sfzcxh]|th|sh|ch/.test(cluster)) return { seconds: 0.07, gain: 0.22, hiss: true };
  if (/[ptkbdgqj]/.test(cluster)) return { seconds: 0.03, gain: 0.5, hiss: false };
  return { seconds: 0.04, gain: 0, hiss: false };  // m n l r w v: voiced, the vowel starts low and soft
}

function pauseAfter(text) {
  if (/[.!?]["'”’)]*$/.test(text)) return 0.45;
  if (/[,;:—–]["'”’)]*$/.test(text)) return 0.22;
  return 0.07;
}

/**
 * Speaks `words` (strings) in a synthetic murmur: a glottal pulse train through three formant
 * resonators whose vowel changes per syllable, noise bursts for consonants, pauses between words.
 * Returns { wav (16-bit PCM mono WAV bytes), duration (seconds), words: [{ start, end, text }] } with
 * word times in seconds to the millisecond. The same words and seed give the same bytes.
 */
export function narrate(words, { sampleRate = 22050, wordsPerMinute = 150, seed = 1 } = {}) {
  const rate = sampleRate;
  const random = mulberry32(seed);
  const pace = 150 / wordsPerMinute;
  const base = 135 + 60 * random();  // the speaker's pitch, 135..195 Hz
  const plan = [];  // segments: { kind: 'voice' | 'noise' | 'rest', seconds, ... }
  const spans = [];
  let sentenceStart = 0;
  const texts = words.map(String);
  texts.forEach((text, w) => {
    const { parts, coda } = syllables(text);
    const sentenceEnd = texts.findIndex((t, k) => k >= w && /[.!?]["'”’)]*$/.test(t));
    const last = sentenceEnd === -1 ? texts.length - 1 : sentenceEnd;
    const along = (w - sentenceStart) / Math.max(1, last - sentenceStart);  // 0..1 through the sentence
    const question = /\?["'”’)]*$/.test(texts[last] ?? '');
    const begin = plan.length;
    parts.forEach((part, s) => {
      const noise = consonant(part.onset);
      if (noise?.gain) plan.push({ kind: 'noise', seconds: noise.seconds * pace, ...noise });
      const final = w === last && s === parts.length - 1;
      const pitch = base * (1.08 - 0.16 * along) * (s === 0 ? 1.04 : 0.98) * (0.97 + 0.06 * random());
      plan.push({
        kind: 'voice', seconds: (0.13 + 0.06 * random() + (noise && !noise.gain ? noise.seconds : 0)) * pace,
        formants: VOWELS[part.vowel], soft: noise && !noise.gain,
        pitch, glide: final ? (question ? 1.25 : 0.78) : 0.96,
      });
    });
    const tailNoise = consonant(coda);
    if (tailNoise?.gain) plan.push({ kind: 'noise', seconds: tailNoise.seconds * pace * 0.8, ...tailNoise });
    spans.push({ text, first: begin, last: plan.length });
    plan.push({ kind: 'rest', seconds: pauseAfter(text) * pace * (0.9 + 0.2 * random()) });
    if (w === last) sentenceStart = w + 1;
  });

  const lead = Math.round(0.15 * rate);
  const starts = [];
  let total = lead;
  for (const seg of plan) {
    starts.push(total);
    seg.samples = Math.max(1, Math.round(seg.seconds * rate));
    total += seg.samples;
  }
  total += Math.round(0.2 * rate);
  const out = new Float32Array(total);
  const formant = [...VOWELS.e];  // the resonators glide from one vowel to the next
  const state = FORMANT_GAINS.map(() => [0, 0]);
  const radii = BANDWIDTHS.map((bandwidth) => Math.exp(-Math.PI * bandwidth / rate));
  const glide = 1 - Math.exp(-1 / (0.012 * rate));  // formants move over about 12 ms
  let phase = 0, flowBefore = 0, low = 0;
  plan.forEach((seg, k) => {
    const at = starts[k], n = seg.samples;
    for (let i = 0; i < n; i++) {
      const t = i / n;
      const envelope = Math.min(1, i / (0.018 * rate)) * Math.min(1, (n - i) / (0.04 * rate));
      let source = 0;
      if (seg.kind === 'voice') {
        const pitch = seg.pitch * (1 + (seg.glide - 1) * t) * (1 + 0.012 * Math.sin(2 * Math.PI * 5 * (at + i) / rate));
        phase = (phase + pitch / rate) % 1;
        // Rosenberg's glottal flow, differentiated: the breath of a pulse each period.
        const flow = phase < 0.4 ? 0.5 * (1 - Math.cos(Math.PI * phase / 0.4))
          : phase < 0.56 ? Math.cos(Math.PI * (phase - 0.4) / 0.32) : 0;
        source = (flow - flowBefore) * 9 * seg.formants[3] * envelope * (seg.soft && t < 0.3 ? 0.45 : 1) * Math.sin(Math.PI * (0.1 + 0.8 * t));
        flowBefore = flow;
        for (let f = 0; f < 3; f++) formant[f] += (seg.formants[f] - formant[f]) * glide;
      } else if (seg.kind === 'noise') {
        const white = random() * 2 - 1;
        low += 0.35 * (white - low);  // low-passed; a hiss (s, f, sh) is what that leaves out
        out[at + i] += (seg.hiss ? white - low : low) * seg.gain * envelope;
      }
      let voiced = 0;
      for (let f = 0; f < 3; f++) {  // two-pole resonators in parallel
        const r = radii[f], [y1, y2] = state[f];
        const y = (1 - r) * source + 2 * r * Math.cos(2 * Math.PI * formant[f] / rate) * y1 - r * r * y2;
        state[f][0] = y;
        state[f][1] = y1;
        voiced += y * FORMANT_GAINS[f];
      }
      out[at + i] += voiced;
    }
  });
  let peak = 1e-9;
  for (const v of out) peak = Math.max(peak, Math.abs(v));
  const ms = (sample) => Math.round(sample / rate * 1000) / 1000;
  return {
    wav: encodeWav(out, rate, 0.8 / peak),
    duration: total / rate,
    words: spans.map(({ text, first, last }) => ({
      start: ms(starts[first]), end: ms(starts[last - 1] + plan[last - 1].samples), text,
    })),
  };
}

/** 16-bit PCM mono WAV bytes of `samples` (floats, times `gain`, clipped to -1..1). */
function encodeWav(samples, rate, gain) {
  const bytes = new Uint8Array(44 + samples.length * 2);
  const view = new DataView(bytes.buffer);
  const ascii = (at, text) => { for (let i = 0; i < text.length; i++) bytes[at + i] = text.charCodeAt(i); };
  ascii(0, 'RIFF'); view.setUint32(4, bytes.length - 8, true); ascii(8, 'WAVE');
  ascii(12, 'fmt '); view.setUint32(16, 16, true); view.setUint16(20, 1, true); view.setUint16(22, 1, true);
  view.setUint32(24, rate, true); view.setUint32(28, rate * 2, true); view.setUint16(32, 2, true); view.setUint16(34, 16, true);
  ascii(36, 'data'); view.setUint32(40, samples.length * 2, true);
  samples.forEach((v, i) => view.setInt16(44 + i * 2, Math.round(Math.max(-1, Math.min(1, v * gain)) * 32767), true));
  return bytes;
}

/** A WebVTT file with one cue per word (its text the word), from `words` as narrate() gives them. */
export function wordTimesVtt(words) {
  const stamp = (seconds) => {
    const ms = Math.round(seconds * 1000);
    const pad = (n, width = 2) => String(n).padStart(width, '0');
    return `${pad(Math.floor(ms / 3600000))}:${pad(Math.floor(ms / 60000) % 60)}:${pad(Math.floor(ms / 1000) % 60)}.${pad(ms % 1000, 3)}`;
  };
  const escape = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
  return ['WEBVTT', ...words.map((word, i) => `${i + 1}\n${stamp(word.start)} --> ${stamp(word.end)}\n${escape(word.text)}`)]
    .join('\n\n') + '\n';
}
