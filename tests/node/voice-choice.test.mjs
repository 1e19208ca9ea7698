// Node tests of read-aloud's voice choice (web/src/engine/voice-choice.js, issue 37): the order of the
// voices over fake lists (navigator.languages given), the default voice, eSpeak last, a 13,362-voice
// list as Firefox's with espeak-ng, and the memory of voice and speed per language over a fake
// localStorage, one that throws too. No DOM, no speech synthesis.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { defaultVoice, isLowQuality, keepChoice, orderVoices, regionOfTag, voiceMemory } from '../../web/src/engine/voice-choice.js';

const voice = (name, lang, more = {}) => ({ name, lang, local: true, default: false, ...more });
const names = (list) => list.map((v) => v.name);

test('node: the page\'s language first, in the reader\'s own region (navigator.languages), then the page\'s region, then the others A to Z; other languages after by tag', () => {
  const voices = [voice('Amélie', 'fr-FR'), voice('Alex', 'en-US'), voice('Hans', 'de-DE', { local: false }),
    voice('Daniel', 'en-GB'), voice('Karen', 'en-AU'), voice('Thomas', 'fr-CA', { local: false }), voice('Plain', 'en')];
  assert.deepEqual(names(orderVoices(voices, 'en', ['en-GB', 'en'])), ['Daniel', 'Alex', 'Plain', 'Karen', 'Hans', 'Thomas', 'Amélie']);
  assert.deepEqual(names(orderVoices(voices, 'en-AU', ['en-US'])), ['Alex', 'Karen', 'Plain', 'Daniel', 'Hans', 'Thomas', 'Amélie']);
  assert.deepEqual(names(orderVoices(voices, 'en', [])), ['Alex', 'Plain', 'Karen', 'Daniel', 'Hans', 'Thomas', 'Amélie']);  // the main region, US; the others A to Z
  assert.deepEqual(names(orderVoices(voices, 'fr-FR', ['fr-CA', 'en-US'])), ['Thomas', 'Amélie', 'Hans', 'Plain', 'Karen', 'Daniel', 'Alex']);
  // No page language: the reader's first.
  assert.deepEqual(names(orderVoices(voices, '', ['de_DE'])).slice(0, 1), ['Hans']);
  // Tags as browsers write them: 'en_GB' (Android), upper case, a script subtag.
  assert.deepEqual(names(orderVoices([voice('a', 'EN_us'), voice('b', 'en_GB')], 'en', ['en-gb'])), ['b', 'a']);
  assert.equal(regionOfTag('zh-Hans-CN'), 'CN');
  assert.equal(regionOfTag('es-419'), '419');
  assert.equal(regionOfTag('en'), '');
});

test('node: within a region local voices before network ones, the browser\'s default first, eSpeak last; the default voice is the first not eSpeak\'s', () => {
  const voices = [voice('Google US English', 'en-US', { local: false }), voice('eSpeak English', 'en-US'),
    voice('Samantha', 'en-US'), voice('Fred', 'en-US', { default: true }), voice('espeak-ng en-GB', 'en-GB')];
  assert.deepEqual(names(orderVoices(voices, 'en', ['en-US'])), ['Fred', 'Samantha', 'Google US English', 'eSpeak English', 'espeak-ng en-GB']);
  // A reader in Britain: eSpeak's British voice is not taken over the American ones...
  assert.equal(defaultVoice(voices, 'en', ['en-GB']).name, 'Fred');
  // ...unless eSpeak is all there is.
  assert.equal(defaultVoice([voice('eSpeak a', 'en-US'), voice('eSpeak b', 'en-GB')], 'en', ['en-GB']).name, 'eSpeak b');
  assert.equal(defaultVoice(voices, 'ja', ['en-US']), null);
  assert.ok(isLowQuality({ name: 'English (America)+Max', voiceURI: 'urn:moz-tts:speechd:English%20(America)+Max?en-US' }));
  assert.ok(!isLowQuality({ name: 'Microsoft Aria Online (Natural)', voiceURI: 'Microsoft Aria Online (Natural) - English (United States)' }));
  // SpeechSynthesisVoice's own field (localService) counts as `local`.
  assert.deepEqual(names(orderVoices([{ name: 'net', lang: 'en-US', localService: false }, { name: 'dev', lang: 'en-US', localService: true }], 'en', [])), ['dev', 'net']);
});

// Firefox with speech-dispatcher and espeak-ng: each eSpeak language with each of its variants.
function firefoxVoices() {
  const tags = [];
  for (let i = 0; i < 130; i++) tags.push(i === 0 ? 'en-US' : i === 1 ? 'en-GB' : i === 2 ? 'fr-FR' : `x${String.fromCharCode(97 + (i % 26))}${String.fromCharCode(97 + Math.floor(i / 26))}-${i % 3 === 0 ? 'AA' : 'BB'}`);
  const list = [];
  for (let n = 0; list.length < 13362; n++) {
    const tag = tags[n % tags.length];
    const name = `${tag} voice+variant${Math.floor(n / tags.length)}`;
    list.push({ name, lang: tag, localService: true, default: n === 0, voiceURI: `urn:moz-tts:speechd:${encodeURIComponent(name)}?${tag}` });
  }
  return list;
}

test('node: a 13,362-voice list as Firefox\'s with espeak-ng is ordered (the page\'s language first, grouped by region) and its default found', () => {
  const voices = firefoxVoices();
  assert.equal(voices.length, 13362);
  const ordered = orderVoices(voices, 'en', ['en-GB', 'en']);
  assert.equal(ordered.length, 13362);
  assert.equal(new Set(ordered).size, 13362);
  const english = ordered.filter((v) => v.lang.startsWith('en'));
  assert.deepEqual(ordered.slice(0, english.length), english);  // the page's language first
  const firstUS = english.findIndex((v) => v.lang === 'en-US');
  assert.ok(english.slice(0, firstUS).every((v) => v.lang === 'en-GB') && english.slice(firstUS).every((v) => v.lang === 'en-US'), 'grouped by region, GB first');
  assert.equal(defaultVoice(voices, 'en', ['en-GB']).lang, 'en-GB');  // all eSpeak: the first of the reader's region
  // The other languages, each region together, by tag.
  const rest = ordered.slice(english.length).map((v) => v.lang.toLowerCase());
  assert.deepEqual(rest, [...rest].sort());
});

// A localStorage as the browser's, or one that throws as a private window's or a sandboxed frame's.
function fakeStorage({ throws = false } = {}) {
  const items = new Map();
  return {
    items,
    getItem: (key) => { if (throws) throw new Error('SecurityError'); return items.has(key) ? items.get(key) : null; },
    setItem: (key, value) => { if (throws) throw new Error('QuotaExceededError'); items.set(key, String(value)); },
  };
}

test('node: the voice and speed are kept per language under the key given (default conecurl-read-aloud), false keeps nothing, a throwing storage reads as empty', (t) => {
  const storage = fakeStorage();
  const before = globalThis.localStorage;
  t.after(() => { if (before === undefined) delete globalThis.localStorage; else globalThis.localStorage = before; });
  globalThis.localStorage = storage;
  const memory = voiceMemory();
  memory.remember('en-GB', { voice: 'Daniel', rate: 1.25 });
  memory.remember('fr', { voice: 'Amélie' });
  assert.deepEqual(memory.recall('en-US'), { voice: 'Daniel', rate: 1.25 });  // per language, whatever the region
  assert.deepEqual(memory.recall('fr-CA'), { voice: 'Amélie' });
  assert.deepEqual(JSON.parse(storage.items.get('conecurl-read-aloud')), { en: { voice: 'Daniel', rate: 1.25 }, fr: { voice: 'Amélie' } });
  voiceMemory('my-key').remember('en', { rate: 2 });
  assert.deepEqual(JSON.parse(storage.items.get('my-key')), { en: { rate: 2 } });
  // readAloud(): a rate not given is the one kept; a voice and rate given are kept. update(): a voice given as undefined is forgotten.
  const settings = { voice: undefined, rate: 1 };
  keepChoice(memory, 'en', {}, settings);
  assert.equal(settings.rate, 1.25);
  keepChoice(memory, 'en', { voice: 'Alex' }, { voice: 'Alex', rate: 1.25 });
  assert.equal(memory.recall('en').voice, 'Alex');
  keepChoice(memory, 'en', { voice: undefined });
  assert.deepEqual(memory.recall('en'), { rate: 1.25 });
  // false: nothing read, nothing written.
  const count = storage.items.size;
  voiceMemory(false).remember('en', { voice: 'X', rate: 3 });
  assert.equal(storage.items.size, count);
  assert.deepEqual(voiceMemory(false).recall('en'), {});
  // Junk kept under the key reads as nothing.
  storage.items.set('junk', '[1,2]');
  assert.deepEqual(voiceMemory('junk').recall('en'), {});
  storage.items.set('junk', '{"en":{"voice":3,"rate":99}}');
  assert.deepEqual(voiceMemory('junk').recall('en'), {});
  // A storage that throws: nothing kept, nothing thrown.
  globalThis.localStorage = fakeStorage({ throws: true });
  assert.doesNotThrow(() => voiceMemory().remember('en', { voice: 'Daniel' }));
  assert.deepEqual(voiceMemory().recall('en'), {});
});
