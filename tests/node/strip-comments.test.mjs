// Node: the published site's modules lose their comments and nothing else (cli/publish/strip-comments.mjs):
// every module of the package still parses once stripped, keeps its code, and the lexer leaves strings,
// template literals and regular expressions that look like comments alone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { stripComments } from '../../cli/publish/strip-comments.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

test('node: stripComments leaves strings, template literals and regular expressions that look like comments, and takes the comments', () => {
  const source = [
    "const a = 'http://x/*y*/'; // gone",
    'const b = "//not a comment";',
    'const c = `line // kept ${ { v: 1 }.v } /* kept */ ${`${"nested // kept"}`}`;',
    'const d = x.replace(/\\/\\*[^]*?\\*\\//g, "") / 2; /* gone */',
    'const e = /[/]\\/\\//.test(s); // gone',
    'function f() { return /a\\/b/.source; }',
    '/**',
    ' * gone',
    ' */',
    'export { a, b, c, d, e, f };',
  ].join('\n');
  const out = stripComments(source);
  for (const kept of ["'http://x/*y*/'", '"//not a comment"', '`line // kept ${ { v: 1 }.v } /* kept */ ${`${"nested // kept"}`}`',
    '/\\/\\*[^]*?\\*\\//g', '/ 2;', '/[/]\\/\\//.test(s);', 'return /a\\/b/.source;', 'export { a, b, c, d, e, f };']) {
    assert.ok(out.includes(kept), `kept: ${kept}\n${out}`);
  }
  assert.ok(!/gone/.test(out), out);
  assert.equal(stripComments(out), out, 'stripping twice changes nothing');
});

test('node: every module a published site carries still parses once stripped, and each of its lines starts as a line of the source, in order', () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-strip-'));
  try {
    const files = ['web/src', 'web/reader'].flatMap((folder) => fs.readdirSync(path.join(root, folder), { recursive: true })
      .filter((name) => name.endsWith('.js')).map((name) => path.join(folder, name)));
    assert.ok(files.length > 60, `${files.length} modules`);
    for (const file of files) {
      const source = fs.readFileSync(path.join(root, file), 'utf8');
      const out = stripComments(source);
      assert.ok(out.length < source.length, `${file} lost its comments`);
      const copy = path.join(dir, 'module.mjs');
      fs.writeFileSync(copy, out);
      execFileSync(process.execPath, ['--check', copy], { stdio: 'pipe' });  // throws, naming the error, if it no longer parses
      // Every line of code of the stripped module is a line (or the start of one) of the source, in order.
      let at = 0;
      for (const line of out.split('\n').map((l) => l.trim()).filter(Boolean)) {
        const found = source.indexOf(line.split(/\s+/)[0], at);
        assert.ok(found >= 0, `${file}: "${line}" is not in the source after offset ${at}`);
        at = found;
      }
    }
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
