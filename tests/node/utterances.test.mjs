// Node: how read-aloud cuts a page's text into utterances (sentences, a long one at a clause) and how long
// the watchdog lets an utterance go without an event (web/src/read-aloud/speech-engine.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MAX_UTTERANCE_CHARS, sentencesOf, stallLimitMs, utterancesOf } from '../../web/src/read-aloud/speech-engine.js';

const pieces = (text) => utterancesOf(text, 'en').map(({ start, end }) => text.slice(start, end));

test('node: utterances are the sentences, each with its spaces, where none is longer than the limit', () => {
  const text = 'The cat sat. It was warm!  Was it? Yes.';
  assert.deepEqual(pieces(text), ['The cat sat. ', 'It was warm!  ', 'Was it? ', 'Yes.']);
  assert.deepEqual(utterancesOf(text, 'en'), sentencesOf(text, 'en'));
});

test('node: a sentence longer than 200 characters is cut at its last clause end that fits, the pieces joined give it back', () => {
  const long = 'This sentence goes on and on, with many clauses and commas in it; it runs past the limit of two hundred characters, '
    + 'because some writers write like this: long, winding, and full of turns, which a voice says in one breath until it stops.';
  const text = `Short. ${long} Next.`;
  const said = pieces(text);
  assert.equal(said.join(''), text);
  assert.ok(said.every((piece) => piece.length <= MAX_UTTERANCE_CHARS), said.map((p) => p.length).join(', '));
  assert.equal(said[0], 'Short. ');
  assert.equal(said[said.length - 1], 'Next.');
  // Each cut falls after a clause's punctuation and its space.
  for (const piece of said.slice(1, -2)) assert.match(piece, /[,;:] $/u);
});

test('node: a long sentence without clauses is cut at a space; a run of letters longer than the limit where it must', () => {
  const words = Array.from({ length: 80 }, (_, i) => `word${i}`).join(' ');
  const said = pieces(`${words}.`);
  assert.equal(said.join(''), `${words}.`);
  assert.ok(said.every((p) => p.length <= MAX_UTTERANCE_CHARS));
  assert.ok(said.slice(0, -1).every((p) => p.endsWith(' ')));
  assert.deepEqual(pieces('x'.repeat(450)).map((p) => p.length), [200, 200, 50]);
});

test('node: the watchdog waits longer for longer texts and slower rates, and always some seconds for a voice to start', () => {
  assert.ok(stallLimitMs(12, 1) > 5000);
  assert.ok(stallLimitMs(200, 1) > stallLimitMs(12, 1));
  assert.ok(stallLimitMs(200, 0.5) > stallLimitMs(200, 1));
  // A 200-character sentence at rate 1 takes a slow voice (8 characters a second) 25 s: more than that.
  assert.ok(stallLimitMs(200, 1) > 25_000);
  assert.ok(stallLimitMs(200, 10) < 15_000);
});
