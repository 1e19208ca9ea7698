// Node tests of what makes a published site embeddable and cacheable (issue 38): the <iframe> snippet in
// `conecurl publish`'s summary and the _headers file (Netlify, Cloudflare Pages) written into the site.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { embedSrc, headersFile, iframeSnippet } from '../../cli/publish/embed.mjs';
import { makeLinkPdf } from '../fixtures/publish-pdfs.mjs';
import { publish, readJson, root, tempDir } from './publish-run.mjs';

/** _headers as [{ path, headers: [] }]: a rule is a line at the start, its headers the indented lines below it. */
function parseHeaders(text) {
  const rules = [];
  for (const line of text.split('\n')) {
    if (line.trim() === '' || line.startsWith('#')) continue;
    if (/^\s/.test(line)) rules.at(-1).headers.push(line.trim());
    else rules.push({ path: line.trim(), headers: [] });
  }
  return rules;
}

/** Whether a _headers path (a trailing * matches the rest) matches a site path like /book/pages/0001.webp. */
const matches = (rule, file) => (rule.endsWith('*') ? file.startsWith(rule.slice(0, -1)) : file === rule);

test('node: conecurl publish prints an <iframe> snippet of the site (its relative path, the book\'s title, fullscreen allowed) and writes _headers where index.html, book.json, sw.js and manifest.webmanifest revalidate, the reader\'s hashed files are immutable and each file has one cache rule (needs pdfjs-dist, @napi-rs/canvas)', async (t) => {
  const dir = tempDir(t);
  const pdf = path.join(dir, 'links.pdf');
  fs.writeFileSync(pdf, await makeLinkPdf());
  const out = path.join(dir, 'my site');
  const run = await publish([pdf, '--out', out, '--height', '200', '--title', 'Links & "quotes"']);
  assert.equal(run.code, 0, run.stderr);
  const line = run.stdout.split('\n').find((l) => l.includes('<iframe'));
  assert.ok(line, run.stdout);
  const iframe = line.slice(line.indexOf('<iframe'));
  const src = `${path.relative(root, out).split(path.sep).join('/')}/`;  // the test runs the command in the repository root
  assert.equal(new RegExp(' src="([^"]*)"').exec(iframe)[1], src);
  assert.match(iframe, / title="Links &amp; &quot;quotes&quot;"/);
  assert.match(iframe, / allow="fullscreen"/);
  assert.match(iframe, /<\/iframe>$/);

  const rules = parseHeaders(fs.readFileSync(path.join(out, '_headers'), 'utf8'));
  const cache = (file) => {
    const hits = rules.filter((rule) => matches(rule.path, file));
    assert.equal(hits.length, 1, `${file} is matched by one rule: ${hits.map((h) => h.path)}`);
    assert.equal(hits[0].headers.length, 1);
    return hits[0].headers[0];
  };
  // The service worker and the web app manifest name the publish's version: they revalidate too.
  const revalidated = ['index.html', 'book/book.json', 'sw.js', 'manifest.webmanifest'];
  for (const file of ['/', ...revalidated.map((f) => `/${f}`)]) assert.equal(cache(file), 'Cache-Control: no-cache', file);
  // Every file the site holds but its own ledger (which the host may serve or not): the reader's, named by
  // their content's hash, immutable; the numbered page files cached for a while, then revalidated.
  const files = readJson(path.join(out, '.conecurl-publish.json')).files;
  assert.ok(files.includes('_headers'), 'the ledger lists _headers: a new publish replaces it');
  assert.ok(files.includes('sw.js') && files.includes('manifest.webmanifest') && files.includes('book/icon-512.png'), 'the web app\'s files are written');
  for (const file of files.filter((f) => ![...revalidated, '_headers'].includes(f))) {
    if (file.startsWith('conecurl/')) {
      assert.match(file, /-[\w-]{8}\.(js|css|wasm)$/, 'a hashed name');
      assert.equal(cache(`/${file}`), 'Cache-Control: public, max-age=31536000, immutable', file);
    } else {
      assert.match(cache(`/${file}`), /^Cache-Control: public, max-age=\d+$/, file);
    }
  }
  assert.ok(files.some((f) => f.startsWith('book/zoom/')) && files.includes('book/links.pdf') && files.some((f) => f.startsWith('conecurl/')));
});

test('node: the embed src is --url where given, else the site relative to the current folder; the snippet escapes its title (needs nothing)', () => {
  assert.equal(embedSrc({ out: '/srv/sites/book', url: 'https://example.com/book/' }), 'https://example.com/book/');
  assert.equal(embedSrc({ out: '/srv/sites/book', cwd: '/srv' }), 'sites/book/');
  assert.equal(embedSrc({ out: '/srv', cwd: '/srv' }), './');
  assert.equal(iframeSnippet({ src: 'a/', title: '<b>' }), '<iframe src="a/" title="&lt;b>" width="100%" height="600" style="border:0" allow="fullscreen" allowfullscreen loading="lazy"></iframe>');
  assert.ok(!headersFile({ download: null }).includes('.pdf'), 'no PDF rule with --no-download');
});
