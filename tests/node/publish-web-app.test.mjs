// Node tests of the files that make a published site an offline, installable web app (cli/publish/
// web-app.mjs): manifest.webmanifest's fields and icons, sw.js's version and file list taken from what
// publish wrote (sizes as on disk), the version kept by an unchanged re-publish and changed by a changed
// one, and the clear errors of a broken service worker source.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { loadCanvas } from '../../cli/publish/pdfjs-node.mjs';
import { serviceWorker, webManifest } from '../../cli/publish/web-app.mjs';
import { runtimeFiles } from '../../cli/publish/runtime-files.mjs';
import { publish, readJson, root, tempDir, writeTestPdf } from './publish-run.mjs';

/** The SITE sw.js was given: { version, shell, files }. */
const siteOf = (out) => JSON.parse(/^const SITE = (\{.*\});$/m.exec(fs.readFileSync(path.join(out, 'sw.js'), 'utf8'))[1]);

test('node: the web app manifest takes its name from the title (short_name cut to 12 characters), start_url and scope ./, standalone, colours and icons (needs nothing)', () => {
  const manifest = JSON.parse(webManifest({ title: 'A catalogue of spring flowers', lang: 'en', icons: [{ src: 'book/icon-192.png', side: 192 }] }));
  assert.deepEqual(manifest, {
    name: 'A catalogue of spring flowers', short_name: 'A catalogue\u2026', lang: 'en', start_url: './', scope: './', display: 'standalone',
    background_color: '#d9d4cc', theme_color: '#d9d4cc',
    icons: [{ src: 'book/icon-192.png', sizes: '192x192', type: 'image/png', purpose: 'any' }],
  });
  assert.equal(JSON.parse(webManifest({ title: 'Short', lang: '', icons: [] })).short_name, 'Short');
});

test('node: a service worker source without its SITE line, or a shell naming a file the site lacks, is refused with a clear error (needs nothing)', () => {
  assert.throws(() => serviceWorker('const x = 1;', { version: 'v', shell: [], files: [] }), /has no line "const SITE = null;/);
  const template = 'const SITE = null;  // replaced by conecurl publish\n';
  assert.throws(() => serviceWorker(template, { version: 'v', shell: ['index.html'], files: [] }), /shell names files the site does not have: index\.html/);
  assert.equal(serviceWorker(template, { version: 'v', shell: ['a'], files: [['a', 1]] }), 'const SITE = {"version":"v","shell":["a"],"files":[["a",1]]};\n');
});

test('node: conecurl publish writes manifest.webmanifest with square icons from page 1, and sw.js whose file list is what it wrote, with sizes, and whose version changes only with the files and is written into index.html for the reader (needs pdfjs-dist, @napi-rs/canvas, dist/)', async (t) => {
  const dir = tempDir(t);
  const pdf = await writeTestPdf(dir);
  const out = path.join(dir, 'site');
  const run = (title) => publish([pdf, '--out', out, '--height', '200', '--zoom', '0', '--title', title]);
  assert.equal((await run('Animals and drinks')).code, 0);

  const manifest = readJson(path.join(out, 'manifest.webmanifest'));
  assert.equal(manifest.name, 'Animals and drinks');
  assert.equal(manifest.start_url, './');
  assert.equal(manifest.display, 'standalone');
  const { loadImage } = loadCanvas();
  for (const icon of manifest.icons) {
    const image = await loadImage(fs.readFileSync(path.join(out, icon.src)));
    assert.equal(`${image.width}x${image.height}`, icon.sizes, icon.src);
  }
  const html = fs.readFileSync(path.join(out, 'index.html'), 'utf8');
  assert.match(html, /<link rel="manifest" href="manifest\.webmanifest">/);
  assert.match(html, /<meta name="theme-color" content="#d9d4cc">/);

  const site = siteOf(out);
  const reader = runtimeFiles(root);
  const ledger = readJson(path.join(out, '.conecurl-publish.json')).files;
  // Every file written but _headers and sw.js itself, each with its size on disk.
  assert.deepEqual(site.files.map(([file]) => file), ledger.filter((file) => !['_headers', 'sw.js'].includes(file)));
  for (const [file, bytes] of site.files) assert.equal(bytes, fs.statSync(path.join(out, file)).size, file);
  for (const file of ['index.html', 'book/book.json', 'manifest.webmanifest', 'book/icon-512.png', 'book/text/pages-0001-0008.json', `conecurl/${reader.entry}`, `conecurl/${reader.wasm}`]) {
    assert.ok(site.shell.includes(file), `${file} is precached`);
  }
  // A page's own text file is read by its text layer (offline, the reader takes the page's text from its group).
  for (const file of ['book/pages/0001.webp', 'book/thumbs/0001.webp', 'book/cover.jpg', 'book/text/0001.json']) assert.ok(!site.shell.includes(file), `${file} is kept as read`);
  assert.match(site.version, /^[0-9a-f]{16}$/);
  // The page's own version, which the reader compares with its worker's (a new publish's worker reloads it).
  assert.match(fs.readFileSync(path.join(out, 'index.html'), 'utf8'), new RegExp(`<meta name="conecurl-site-version" content="${site.version}">`));

  assert.equal((await run('Animals and drinks')).code, 0);
  assert.equal(siteOf(out).version, site.version, 'the same input: the same version');
  assert.equal((await run('Animals, drinks and more')).code, 0);
  assert.notEqual(siteOf(out).version, site.version, 'a new title: a new version');
});
