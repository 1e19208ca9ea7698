// Node tests of `conecurl publish --narration` (issue 37): a folder of page-N audio and word-times files is
// checked, copied into the site and named in book.json's pages; each kind of bad narration is refused in
// one line that names the file and what is wrong (exit 1, nothing written); audio lengths read from headers.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { audioSeconds } from '../../cli/publish/audio-duration.mjs';
import { narrationFolder, silentWav, timed, wordTimesVtt } from '../fixtures/narration-files.mjs';
import { assertOneLine, publish, readJson, tempDir, writeTestPdf } from './publish-run.mjs';

const SMALL = ['--height', '120', '--zoom', '0', '--jobs', '1', '--no-download'];


test('node: conecurl publish --narration copies each page\'s audio and word times into book/narration/ and names them in book.json; a re-publish with --pages renumbers them and removes its stale ones (needs pdfjs-dist, @napi-rs/canvas)', async (t) => {
  const dir = tempDir(t);
  const pdf = await writeTestPdf(dir);
  const out = path.join(dir, 'site');
  const words1 = timed(['A', 'book', 'about', 'animals']);
  const words2 = timed(['The', 'zebra', 'has', 'stripes.']);
  const files = {
    'page-1.wav': silentWav(1), 'page-1.vtt': wordTimesVtt(words1),
    'page-02.WAV': silentWav(1.2), 'page-02.json': JSON.stringify({ words: words2 }),
    'notes.txt': 'the narrator\'s script\n',
  };
  const folder = narrationFolder(dir, 'voice', files);
  const run = await publish([pdf, '--out', out, ...SMALL, '--narration', folder]);
  assert.equal(run.code, 0, run.stderr);
  assert.match(run.stdout, /Checking the narration of 2 pages in .*voice/);
  assert.match(run.stdout, /passed over notes\.txt/);
  assert.match(run.stdout, /narration [\d.]+ KB/);
  const manifest = readJson(path.join(out, 'book/book.json'));
  assert.deepEqual(manifest.pages.map((page) => page.narration ?? null), [
    { src: 'narration/0001.wav', words: 'narration/0001.vtt' },
    { src: 'narration/0002.wav', words: 'narration/0002.json' },
    null, null, null, null, null, null,
  ]);
  const same = (site, given) => assert.deepEqual(fs.readFileSync(path.join(out, 'book', site)), fs.readFileSync(path.join(folder, given)), site);
  same('narration/0001.wav', 'page-1.wav');
  same('narration/0001.vtt', 'page-1.vtt');
  same('narration/0002.wav', 'page-02.WAV');
  same('narration/0002.json', 'page-02.json');
  const ledger = readJson(path.join(out, '.conecurl-publish.json')).files;
  for (const file of ['0001.wav', '0001.vtt', '0002.wav', '0002.json']) assert.ok(ledger.includes(`book/narration/${file}`), file);

  // Pages 2 and 3 only: page 2's narration is now the site's first page's; page 1's is left out with its page.
  const again = await publish([pdf, '--out', out, ...SMALL, '--pages', '2-3', '--narration', folder]);
  assert.equal(again.code, 0, again.stderr);
  assert.match(again.stdout, /Narration of page 1 left out with the page \(--pages\)/);
  const renumbered = readJson(path.join(out, 'book/book.json'));
  assert.deepEqual(renumbered.pages.map((page) => page.narration ?? null), [{ src: 'narration/0001.wav', words: 'narration/0001.json' }, null]);
  same('narration/0001.wav', 'page-02.WAV');
  assert.deepEqual(fs.readdirSync(path.join(out, 'book/narration')).sort(), ['0001.json', '0001.wav']);
  // Without --narration: the site's narration goes, the folder given is untouched.
  assert.equal((await publish([pdf, '--out', out, ...SMALL])).code, 0);
  assert.ok(!fs.existsSync(path.join(out, 'book/narration')));
  assert.deepEqual(fs.readdirSync(folder).sort(), Object.keys(files).sort());
});

test('node: conecurl publish --narration refuses each kind of bad narration in one line naming the file, the page and what is wrong (exit 1, nothing written; needs pdfjs-dist)', async (t) => {
  const dir = tempDir(t);
  const pdf = await writeTestPdf(dir);
  const out = path.join(dir, 'site');
  const wav = silentWav(1);
  const good = wordTimesVtt(timed(['A', 'book']));
  let n = 0;
  /** Publishes with a narration folder of `files`; expects one line naming `name` (a file in it, or null) and matching `what`. */
  const refused = async (files, name, what, code = 1) => {
    const folder = narrationFolder(dir, `case-${n++}`, files);
    const run = await publish([pdf, '--out', out, ...SMALL, '--narration', folder]);
    assertOneLine(run, code, name && path.join(folder, name), what);
    assert.ok(!fs.existsSync(out), `nothing was written (${name})`);
  };
  // Times not increasing: a WebVTT cue before the one above it; a JSON word before the one before it.
  await refused({ 'page-1.wav': wav, 'page-1.vtt': 'WEBVTT\n\n00:00.000 --> 00:00.200\nA\n\n00:00.400 --> 00:00.500\nbook\n\n00:00.300 --> 00:00.350\nabout\n' },
    'page-1.vtt', /\(page 1\) word 3 "about" at 00:00\.300 starts before the word before it.*: fix the file/);
  await refused({ 'page-2.wav': wav, 'page-2.json': JSON.stringify([{ start: 0.5, end: 0.6, text: 'The' }, { start: 0.1, end: 0.2, text: 'zebra' }]) },
    'page-2.json', /\(page 2\) word 2 "zebra" at 00:00\.100 starts before the word before it/);
  await refused({ 'page-1.wav': wav, 'page-1.json': JSON.stringify([{ start: 0.5, end: 0.2, text: 'A' }]) },
    'page-1.json', /word 1 "A" at 00:00\.500 must have start and end in seconds, 0 <= start <= end/);
  // A cue whose end comes before its start, or a time that is not mm:ss.ttt: the line is named.
  await refused({ 'page-1.wav': wav, 'page-1.vtt': 'WEBVTT\n\n00:00.000 --> 00:00.200\nA\n\n00:00.500 --> 00:00.300\nbook\n' },
    'page-1.vtt', /\(page 1\) line 6: a cue's times must be mm:ss\.ttt --> mm:ss\.ttt, start before end/);
  await refused({ 'page-1.wav': wav, 'page-1.vtt': 'WEBVTT\n\n00:00.000 --> 00:00.200\n{"text": "A",}\n' },
    'page-1.vtt', /\(page 1\) line 4: a cue's JSON text cannot be read/);
  // A word past the audio's end (a 1 s WAV).
  await refused({ 'page-1.wav': wav, 'page-1.vtt': wordTimesVtt([{ start: 0, end: 0.4, text: 'A' }, { start: 0.5, end: 2.5, text: 'book' }]) },
    'page-1.vtt', /\(page 1\) word 2 "book" ends at 2\.5 s, past the end of page-1\.wav \(1 s long\)/);
  // Unparsable files.
  await refused({ 'page-1.wav': wav, 'page-1.vtt': '00:00.000 --> 00:00.200\nA\n' }, 'page-1.vtt', /is not WebVTT \(its first line must be WEBVTT\)/);
  await refused({ 'page-1.wav': wav, 'page-1.json': '[{ "start": 0, "end": 0.2, "text": "A" },' }, 'page-1.json', /\(page 1\) is not JSON \(/);
  await refused({ 'page-1.wav': wav, 'page-1.json': '{ "times": [] }' }, 'page-1.json', /must be an array of \{ start, end, text, rect \}/);
  await refused({ 'page-1.wav': wav, 'page-1.vtt': 'WEBVTT\n' }, 'page-1.vtt', /holds no words/);
  await refused({ 'page-1.mp3': 'this is not audio', 'page-1.vtt': good }, 'page-1.mp3', /\(page 1\) is not an MP3 file/);
  // A word-times file without audio, audio without word times, two of one kind for a page.
  await refused({ 'page-3.vtt': good }, 'page-3.vtt', /has no audio: add page-3\.mp3/);
  await refused({ 'page-1.wav': wav, 'page-1.vtt': good, 'page-4.ogg': wav }, 'page-4.ogg', /has no word times: add page-4\.vtt or page-4\.json/);
  await refused({ 'page-1.wav': wav, 'page-1.mp3': wav, 'page-1.vtt': good }, 'page-1.mp3', /and page-1\.wav are both page 1's audio: keep one/);
  // A page number outside the PDF (8 pages, from 1), and a name that is meant as narration but breaks the rule.
  await refused({ 'page-9.wav': wav, 'page-9.vtt': good }, 'page-9.vtt', /is for page 9, but .*book\.pdf has 8 pages \(numbered from 1\)/);
  await refused({ 'page-0.wav': wav, 'page-0.vtt': good }, 'page-0.vtt', /is for page 0/);
  await refused({ 'page1.wav': wav, 'page-1.vtt': good }, 'page1.wav', /is not named page-N\.<ext>: name it like page-1\.mp3/);
  // The folder: empty, missing; the option without a value (usage, exit 2).
  await refused({ 'readme.txt': 'nothing here' }, null, /holds no narration: name each page's audio page-N\.mp3/);
  const missing = path.join(dir, 'no-such-folder');
  assertOneLine(await publish([pdf, '--out', out, '--narration', missing]), 1, missing, /does not exist/);
  assertOneLine(await publish([pdf, '--out', out, '--narration']), 2, null, /--narration needs a value/);
  assert.ok(!fs.existsSync(out));
});

test('node: the narration checks read an audio file\'s length from its own header: WAV, MP3 frames after an ID3 tag, Ogg Opus, M4A; null where it cannot be known', () => {
  assert.equal(audioSeconds(silentWav(1.5), 'wav'), 1.5);
  // MPEG-1 Layer III, 128 kbit/s, 44.1 kHz: 417-byte frames of 1152 samples, after a 20-byte ID3v2 tag.
  const frame = Buffer.alloc(417);
  frame.set([0xff, 0xfb, 0x90, 0x00]);
  const id3 = Buffer.from([0x49, 0x44, 0x33, 4, 0, 0, 0, 0, 0, 10, ...Array(10).fill(0)]);
  const mp3 = Buffer.concat([id3, ...Array(100).fill(frame)]);
  assert.ok(Math.abs(audioSeconds(mp3, 'mp3') - (100 * 1152) / 44100) < 1e-9);
  // Ogg Opus: the OpusHead packet (pre-skip 312) on the first page, granule 1.5 s + pre-skip on the last.
  const page = (granule, packet) => {
    const head = Buffer.alloc(27);
    head.write('OggS', 0, 'latin1');
    head.writeBigInt64LE(BigInt(granule), 6);
    head[26] = packet.length ? 1 : 0;
    return Buffer.concat([head, packet.length ? Buffer.from([packet.length]) : Buffer.alloc(0), packet]);
  };
  const opusHead = Buffer.alloc(19);
  opusHead.write('OpusHead', 0, 'latin1');
  opusHead[8] = 1;
  opusHead[9] = 1;
  opusHead.writeUInt16LE(312, 10);
  opusHead.writeUInt32LE(48000, 12);
  assert.equal(audioSeconds(Buffer.concat([page(0, opusHead), page(72000 + 312, Buffer.alloc(0))]), 'opus'), 1.5);
  // M4A: ftyp, then moov holding mvhd (version 0: timescale 1000, duration 3250).
  const box = (type, body) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(8 + body.length, 0);
    head.write(type, 4, 'latin1');
    return Buffer.concat([head, body]);
  };
  const mvhd = Buffer.alloc(100);
  mvhd.writeUInt32BE(1000, 12);
  mvhd.writeUInt32BE(3250, 16);
  assert.equal(audioSeconds(Buffer.concat([box('ftyp', Buffer.from('M4A \0\0\0\0', 'latin1')), box('moov', box('mvhd', mvhd))]), 'm4a'), 3.25);
  assert.equal(audioSeconds(box('ftyp', Buffer.from('M4A \0\0\0\0', 'latin1')), 'm4a'), null);  // no moov: not known
  assert.throws(() => audioSeconds(Buffer.from('not a wav file at all'), 'wav'), /is not a WAV file/);
  assert.throws(() => audioSeconds(Buffer.alloc(0), 'mp3'), /is empty/);
});
