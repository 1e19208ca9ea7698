// Node: passage links' addresses (page-memory.js) and the text they carry (text-layer.js passageText):
// what a link writes, a book reads back; malformed addresses are no passage.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hashPassage, passageUrl } from '../../web/src/document/passage-address.js';
import { passageText } from '../../web/src/layers/text-layer.js';

test('node: a passage link round-trips through its address: page from 1 in the link, from 0 when read; any text, & and # included', () => {
  const location = { origin: 'https://example.org', pathname: '/books/manual.html', search: '?v=2' };
  for (const [page, text] of [[0, 'plain words'], [41, 'café & crème #1 100% "quoted"'], [7, 'line one line two']]) {
    const url = passageUrl(page, text, location);
    assert.ok(url.startsWith(`https://example.org/books/manual.html?v=2#page=${page + 1}&text=`), url);
    assert.deepEqual(hashPassage(new URL(url).hash), { page, text });
  }
});

test('node: addresses that are no passage: a bare #page=N, no text, an empty or malformed one', () => {
  for (const hash of ['', '#page=3', '#page=3&text=', '#page=3&text=%E0%A4%A', '#page=x&text=a', '#text=a', '#page=3&text=a&b=c']) {
    assert.equal(hashPassage(hash), null, hash);
  }
});

test('node: a passage carries its selection with white space folded and at most 300 characters, cut at a word', () => {
  assert.equal(passageText('  alpha\n bravo\t\tcharlie  '), 'alpha bravo charlie');
  const long = Array.from({ length: 100 }, (_, i) => `word${i}`).join(' ');
  const carried = passageText(long);
  assert.ok(carried.length <= 300 && long.startsWith(carried) && long[carried.length] === ' ', carried);
});
