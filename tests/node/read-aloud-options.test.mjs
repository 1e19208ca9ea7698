// Node: readAloud()'s options and a reading's update() are checked before anything is read
// (web/src/read-aloud/book-reader.js): defaults filled in, and a bad one named with what is allowed.
import test from 'node:test';
import assert from 'node:assert/strict';
import { checkReadOptions, checkUpdate } from '../../web/src/read-aloud/book-reader.js';

test('node: readAloud() options get their defaults, and each bad option is named with what it allows', () => {
  const engine = { speak() {} };
  assert.deepEqual(checkReadOptions(), { engine: null, voice: undefined, voiceObject: null, rate: 1, pitch: 1, lang: undefined, follow: false });
  assert.deepEqual(checkReadOptions({ engine, voice: 'Anna', rate: 0.5, pitch: 2, lang: 'de-DE', follow: true }),
    { engine, voice: 'Anna', voiceObject: null, rate: 0.5, pitch: 2, lang: 'de-DE', follow: true });
  const refuses = (options, message) => assert.throws(() => checkReadOptions(options), (e) => e.message === `conecurl: ${message}`);
  refuses({ speed: 2 }, "readAloud() has no option 'speed' (allowed: engine, voice, rate, pitch, lang, follow)");
  refuses({ rate: NaN }, "readAloud() 'rate' must be a number from 0.1 to 10, got NaN");
  refuses({ pitch: -1 }, "readAloud() 'pitch' must be a number from 0 to 2, got -1");
  refuses({ lang: '' }, "readAloud() 'lang' must be a language tag such as 'en-GB', got \"\"");
  refuses({ follow: 'yes' }, "readAloud() 'follow' must be true or false, got \"yes\"");
  assert.throws(() => checkReadOptions({ engine: {} }), /'engine' must have speak\(text, \{ lang, rate, pitch, voice, onWord, onEnd \}\)/);
  assert.throws(() => checkReadOptions({ voice: 3 }), /'voice' must be a voice's name \(readAloudVoices\(\) lists them\)/);
  assert.throws(() => checkReadOptions('fast'), /readAloud\(\) takes an options object/);
});

test('node: update() takes voice, rate and pitch only; a voice given as undefined is the default again', () => {
  assert.deepEqual(checkUpdate({ rate: 1.5 }), { rate: 1.5 });
  assert.deepEqual(checkUpdate({ voice: undefined }), { voice: undefined });
  assert.throws(() => checkUpdate({ rate: 0 }), /conecurl: update\(\) 'rate' must be a number from 0\.1 to 10, got 0/);
  assert.throws(() => checkUpdate({ lang: 'fr' }), /update\(\) has no option 'lang' \(allowed: voice, rate, pitch\)/);
});
