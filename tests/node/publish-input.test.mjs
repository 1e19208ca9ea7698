// Node tests of `conecurl publish` on bad input and on its out folder: each failure is one line naming the
// file and what to do, with its exit code (1 input, 2 usage, 3 failed pages); --out never loses a file
// conecurl did not write, and a re-publish replaces its own files and removes its own stale ones.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ENCRYPTED_PASSWORD, makeBrokenPagePdf } from '../fixtures/publish-pdfs.mjs';
import { assertOneLine, publish, readJson, root, tempDir, writeTestPdf } from './publish-run.mjs';

const ENCRYPTED = path.join(root, 'tests/fixtures/encrypted.pdf');
const SMALL = ['--height', '120', '--zoom', '0', '--jobs', '1'];

test('node: conecurl publish refuses a missing file, a non-PDF, a truncated PDF and a bad --pages in one line each (exit 1 or 2)', async (t) => {
  const dir = tempDir(t);
  const out = path.join(dir, 'site');
  const missing = path.join(dir, 'nope.pdf');
  assertOneLine(await publish([missing, '--out', out]), 1, missing, /does not exist/);
  const text = path.join(dir, 'notes.pdf');
  fs.writeFileSync(text, 'just some text, not a PDF\n');
  assertOneLine(await publish([text, '--out', out]), 1, text, /is not a PDF/);
  const pdf = await writeTestPdf(dir);
  const truncated = path.join(dir, 'cut.pdf');
  fs.writeFileSync(truncated, fs.readFileSync(pdf).subarray(0, 600));
  assertOneLine(await publish([truncated, '--out', out]), 1, truncated, /damaged.*repair/);
  assertOneLine(await publish([pdf, '--out', out, '--pages', '3-x']), 2, null, /--pages "3-x"/);
  assertOneLine(await publish([pdf, '--out', out, '--pages', '2,40']), 2, pdf, /has 8 pages, so there is no page 40/);
  assertOneLine(await publish([pdf]), 2, null, /--out/);
  assertOneLine(await publish([pdf, '--out', out, '--format', 'gif']), 2, null, /--format "gif"/);
  assert.ok(!fs.existsSync(out), 'nothing was written');
});

test('node: conecurl publish asks for the password of an encrypted PDF, refuses a wrong one, and publishes with the right one', async (t) => {
  const dir = tempDir(t);
  const out = path.join(dir, 'site');
  assertOneLine(await publish([ENCRYPTED, '--out', out, ...SMALL]), 1, ENCRYPTED, /encrypted: give its password with --password/);
  assertOneLine(await publish([ENCRYPTED, '--out', out, '--password', 'wrong', ...SMALL]), 1, ENCRYPTED, /password is wrong/);
  const run = await publish([ENCRYPTED, '--out', out, '--password', ENCRYPTED_PASSWORD, ...SMALL]);
  assert.equal(run.code, 0, run.stderr);
  assert.equal(readJson(path.join(out, 'book/book.json')).pageCount, 2);
});

test('node: conecurl publish reports a page that cannot be rendered by number, publishes the others and exits 3', async (t) => {
  const dir = tempDir(t);
  const pdf = path.join(dir, 'broken.pdf');
  fs.writeFileSync(pdf, await makeBrokenPagePdf(7));  // the last: pdf.js counts the pages before a bad entry only
  const run = await publish([pdf, '--out', path.join(dir, 'site'), ...SMALL]);
  assertOneLine(run, 3, pdf, /^conecurl publish: page 8 of .* could not be rendered/);
  const manifest = readJson(path.join(dir, 'site/book/book.json'));
  assert.equal(manifest.pageCount, 8);
  assert.equal(typeof manifest.pages[7].failed, 'string');
  assert.ok(manifest.pages[7].width > 0 && manifest.pages[7].height > 0);
  for (const i of [0, 1, 2, 6]) assert.ok(fs.existsSync(path.join(dir, 'site/book', manifest.pages[i].src)), `page ${i + 1}`);
  assert.ok(!fs.existsSync(path.join(dir, 'site/book/pages/0008.webp')));
});

test('node: conecurl publish never writes into a folder it did not publish, nor over a file it did not write, and a re-publish removes only its own stale files', async (t) => {
  const dir = tempDir(t);
  const pdf = await writeTestPdf(dir);
  const foreign = path.join(dir, 'mine');
  fs.mkdirSync(foreign);
  fs.writeFileSync(path.join(foreign, 'notes.txt'), 'keep me');
  assertOneLine(await publish([pdf, '--out', foreign, ...SMALL]), 1, foreign, /not empty and was not written by conecurl/);
  assert.deepEqual(fs.readdirSync(foreign), ['notes.txt']);

  const out = path.join(dir, 'site');
  assert.equal((await publish([pdf, '--out', out, ...SMALL, '--zoom', '2'])).code, 0);
  fs.writeFileSync(path.join(out, 'book/extra.txt'), 'the host\'s own file');
  fs.writeFileSync(path.join(out, 'README.txt'), 'also mine');
  const again = await publish([pdf, '--out', out, ...SMALL, '--pages', '1-3', '--no-download']);
  assert.equal(again.code, 0, again.stderr);
  assert.equal(fs.readFileSync(path.join(out, 'book/extra.txt'), 'utf8'), 'the host\'s own file');
  assert.ok(fs.existsSync(path.join(out, 'README.txt')));
  assert.deepEqual(fs.readdirSync(path.join(out, 'book/pages')).sort(), ['0001.webp', '0002.webp', '0003.webp']);
  assert.ok(!fs.existsSync(path.join(out, 'book/zoom')), 'the zoom images of the first run are gone');
  assert.ok(!fs.existsSync(path.join(out, 'book/book.pdf')), 'the PDF of the first run is gone');
  assert.equal(readJson(path.join(out, 'book/book.json')).pageCount, 3);

  // A file in the way of one conecurl would write, which it did not write: refused, nothing changed.
  fs.rmSync(path.join(out, 'book/pages/0001.webp'));
  fs.writeFileSync(path.join(out, 'book/pages/0004.webp'), 'a file of the host');
  const ledger = readJson(path.join(out, '.conecurl-publish.json'));
  assertOneLine(await publish([pdf, '--out', out, ...SMALL]), 1, 'book/pages/0004.webp', /conecurl did not write/);
  assert.equal(fs.readFileSync(path.join(out, 'book/pages/0004.webp'), 'utf8'), 'a file of the host');
  assert.deepEqual(readJson(path.join(out, '.conecurl-publish.json')), ledger);
});
