// Node tests of the demo's synthetic narrator (web/demo/story-voice.js): a valid 16-bit mono WAV, word
// times in order inside the sound where the sound is, the same bytes for the same seed, and the WebVTT.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { narrate, wordTimesVtt } from '../../web/demo/story-voice.js';

const WORDS = 'Mia folded a boat out of paper. It had a bright red sail! “Quack!” said the duck, and off it went.'.split(' ');
const ascii = (bytes, at, length) => String.fromCharCode(...bytes.subarray(at, at + length));
const rms = (pcm, from, to) => {
  let sum = 0;
  for (let i = from; i < to; i++) sum += pcm[i] * pcm[i];
  return Math.sqrt(sum / Math.max(1, to - from));
};

for (const sampleRate of [22050, 16000]) {
  test(`node: narrate() makes a valid 16-bit mono PCM WAV at ${sampleRate} Hz whose duration is its samples over the rate`, () => {
    const { wav, duration } = narrate(WORDS, { sampleRate });
    assert.ok(wav instanceof Uint8Array);
    const view = new DataView(wav.buffer, wav.byteOffset, wav.byteLength);
    assert.equal(ascii(wav, 0, 4), 'RIFF');
    assert.equal(view.getUint32(4, true), wav.length - 8);
    assert.equal(ascii(wav, 8, 4), 'WAVE');
    assert.equal(ascii(wav, 12, 4), 'fmt ');
    assert.equal(view.getUint32(16, true), 16);            // the PCM fmt chunk's size
    assert.equal(view.getUint16(20, true), 1);             // PCM
    assert.equal(view.getUint16(22, true), 1);             // mono
    assert.equal(view.getUint32(24, true), sampleRate);
    assert.equal(view.getUint32(28, true), sampleRate * 2);  // bytes a second
    assert.equal(view.getUint16(32, true), 2);             // bytes a frame
    assert.equal(view.getUint16(34, true), 16);            // bits a sample
    assert.equal(ascii(wav, 36, 4), 'data');
    const dataBytes = view.getUint32(40, true);
    assert.equal(dataBytes, wav.length - 44);
    assert.equal(duration, dataBytes / 2 / sampleRate);
    assert.ok(duration > 3 && duration < 12, `${WORDS.length} words at 150 a minute last ${duration} s`);
  });
}

test('node: each word has its time, in order, inside the sound, to the millisecond; a word is sound and the gaps are quieter', () => {
  const sampleRate = 22050;
  const { wav, duration, words } = narrate(WORDS, { sampleRate });
  assert.deepEqual(words.map((w) => w.text), WORDS);
  const pcm = new Int16Array(wav.buffer.slice(wav.byteOffset + 44, wav.byteOffset + wav.length));
  let before = 0;
  for (const word of words) {
    for (const t of [word.start, word.end]) assert.equal(t, Math.round(t * 1000) / 1000, `${word.text}: ${t} to the ms`);
    assert.ok(word.start >= before, `${word.text} starts (${word.start}) after the word before ends (${before})`);
    assert.ok(word.end > word.start + 0.05, `${word.text} lasts from ${word.start} to ${word.end}`);
    assert.ok(word.end <= duration, `${word.text} ends inside the sound`);
    before = word.end;
  }
  const at = (seconds) => Math.min(pcm.length, Math.round(seconds * sampleRate));
  const spoken = words.map((w) => rms(pcm, at(w.start), at(w.end)));
  for (const [i, level] of spoken.entries()) assert.ok(level > 1000, `${words[i].text} is heard (RMS ${level.toFixed(0)})`);
  // The gaps, from 20 ms after a word (the resonators ring a moment) to the next word.
  const gaps = words.slice(1).map((w, i) => rms(pcm, at(words[i].end + 0.02), at(w.start)));
  const quietest = Math.min(...spoken);
  for (const [i, level] of gaps.entries()) assert.ok(level < quietest / 4, `the gap after ${words[i].text} (RMS ${level.toFixed(0)}) is quieter`);
  assert.ok(rms(pcm, 0, at(words[0].start)) < 10, 'silence before the first word');
  assert.ok(rms(pcm, at(words.at(-1).end + 0.05), pcm.length) < 10, 'silence after the last');
});

test('node: narrate() pauses longer after a comma and longer still after a full stop', () => {
  const { words } = narrate(['one', 'two,', 'three.', 'Four', 'five'], { seed: 7 });
  const gap = (i) => words[i + 1].start - words[i].end;
  assert.ok(gap(1) > gap(0) * 2, `comma ${gap(1)} vs space ${gap(0)}`);
  assert.ok(gap(2) > gap(1) * 1.5, `full stop ${gap(2)} vs comma ${gap(1)}`);
});

test('node: the same words and seed give the same bytes; another seed, another voice; a faster pace, a shorter one', () => {
  const a = narrate(WORDS, { seed: 5 });
  const b = narrate(WORDS, { seed: 5 });
  assert.deepEqual(a.wav, b.wav);
  assert.deepEqual(a.words, b.words);
  assert.notDeepEqual(narrate(WORDS, { seed: 6 }).wav, a.wav);
  assert.ok(narrate(WORDS, { seed: 5, wordsPerMinute: 220 }).duration < a.duration * 0.8);
});

test('node: wordTimesVtt() is WebVTT with one cue a word, its times and its text', () => {
  const { words } = narrate(['Hello,', 'little', 'boat', '<3', '&', 'goodbye.']);
  const vtt = wordTimesVtt(words);
  assert.match(vtt, /^WEBVTT\n\n/);
  const stamp = (text) => {
    const [h, m, s] = text.split(':');
    return Number(h) * 3600 + Number(m) * 60 + Number(s);
  };
  const cues = vtt.trim().split('\n\n').slice(1).map((block) => block.split('\n'));
  assert.equal(cues.length, words.length);
  cues.forEach(([id, timing, text, ...rest], i) => {
    assert.equal(id, String(i + 1));
    const match = timing.match(/^(\d\d:\d\d:\d\d\.\d\d\d) --> (\d\d:\d\d:\d\d\.\d\d\d)$/);
    assert.ok(match, timing);
    assert.equal(stamp(match[1]), words[i].start);
    assert.equal(stamp(match[2]), words[i].end);
    assert.equal(text.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&amp;/g, '&'), words[i].text);
    assert.doesNotMatch(text, /[<>]|&(?!lt;|gt;|amp;)/, 'cue text escaped');
    assert.deepEqual(rest, []);
  });
  assert.equal(wordTimesVtt([{ start: 3725.5, end: 3725.75, text: 'late' }]).split('\n')[3], '01:02:05.500 --> 01:02:05.750');
});
