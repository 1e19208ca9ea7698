// Node: recorded narration's word times (web/src/read-aloud/word-times.js): WebVTT with a cue a word,
// with <timestamps> inside a cue, and with JSON cues giving places; the checks that name a bad word;
// and the word said at a time (narration-player.js wordAtTime), without a browser.
import test from 'node:test';
import assert from 'node:assert/strict';
import { checkWordTimes, parseVtt } from '../../web/src/read-aloud/word-times.js';
import { wordAtTime } from '../../web/src/read-aloud/narration-player.js';
import { wordAt, wordsOf } from '../../web/src/read-aloud/page-script.js';

test('node: parseVtt reads a cue a word, karaoke timestamps inside a cue, and JSON cues with a rect', () => {
  assert.deepEqual(parseVtt('WEBVTT\n\n00:00.000 --> 00:00.320\nOnce\n\n1\n00:00.360 --> 00:00.610\nupon\n'), [
    { start: 0, end: 0.32, text: 'Once' }, { start: 0.36, end: 0.61, text: 'upon' }]);
  assert.deepEqual(parseVtt('WEBVTT - a story\r\n\r\n00:01.000 --> 00:02.500\r\nOnce <00:01.400>upon <00:01.700>a <00:01.800><c.x>time</c>\r\n'), [
    { start: 1, end: 1.4, text: 'Once' }, { start: 1.4, end: 1.7, text: 'upon' }, { start: 1.7, end: 1.8, text: 'a' }, { start: 1.8, end: 2.5, text: 'time' }]);
  assert.deepEqual(parseVtt('WEBVTT\n\n01:00:00.000 --> 01:00:01.000\n{"text": "Hi", "rect": [0.1, 0.2, 0.3, 0.04]}\n'), [
    { start: 3600, end: 3601, text: 'Hi', rect: [0.1, 0.2, 0.3, 0.04] }]);
  assert.throws(() => parseVtt('00:00.000 --> 00:01.000\nx', 'p.vtt'), /p\.vtt is not WebVTT \(its first line must be WEBVTT\)/);
  assert.throws(() => parseVtt('WEBVTT\n\n00:02.000 --> 00:01.000\nx', 'p.vtt'), /p\.vtt line 3: a cue's times/);
});

test('node: checkWordTimes keeps good words and names the first bad one and what is wrong', () => {
  const good = [{ start: 0, end: 0.5, text: 'a', rect: [0, 0, 0.1, 0.1] }, { start: 0.5, end: 0.9, text: 'b' }];
  assert.deepEqual(checkWordTimes(good, 'w'), good);
  assert.throws(() => checkWordTimes('x', 'page 1 narration.words'), /page 1 narration\.words must be an array/);
  assert.throws(() => checkWordTimes([{ start: 1, end: 0.5, text: 'a' }], 'w'), /w\[0\] must have start and end in seconds, 0 <= start <= end; got start 1, end 0\.5/);
  assert.throws(() => checkWordTimes([good[1], good[0]], 'w'), /w\[1\] starts before the word before it/);
  assert.throws(() => checkWordTimes([{ start: 0, end: 1, text: 3 }], 'w'), /w\[0\]\.text must be the word/);
  assert.throws(() => checkWordTimes([{ start: 0, end: 1, text: 'a', rect: [0, 0, 2, 0.1] }], 'w'), /w\[0\]\.rect must be \[x, y, width, height\] as fractions/);
});

test('node: the word said at a time is the last one started by then; a speech engine\'s character index finds its word', () => {
  const words = [{ start: 0.2, end: 0.4 }, { start: 0.5, end: 0.8 }, { start: 0.8, end: 1 }];
  assert.deepEqual([0, 0.2, 0.45, 0.5, 0.79, 0.8, 5].map((t) => wordAtTime(words, t)), [-1, 0, 0, 1, 1, 2, 2]);
  const text = 'The cat\nsat.';
  assert.deepEqual(wordsOf(text), [{ start: 0, end: 3, text: 'The' }, { start: 4, end: 7, text: 'cat' }, { start: 8, end: 12, text: 'sat.' }]);
  assert.deepEqual([0, 3, 4, 8, 11, 12].map((i) => wordAt(wordsOf(text), i)), [0, 1, 1, 2, 2, -1]);
});
