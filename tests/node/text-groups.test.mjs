// Node tests of the published format's text groups (web/src/document/format.js): the groups a document
// of any length gets, their file's round trip, and the clear errors of a bad group file or manifest entry.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  TEXT_GROUP_PAGES, checkManifest, checkTextGroup, decodePageText, encodePageText, encodeTextGroup, makeManifest, planTextGroups,
} from '../../web/src/document/format.js';

const record = (text) => ({
  text, width: 420, height: 560,
  items: [{ start: 0, end: text.length, str: text, tx: [12, 0, 0, 12, 40, 80], width: 90, family: 'sans-serif', ascent: 0.8, descent: -0.2 }],
});
const page = { width: 420, height: 560, src: 'pages/0001.webp' };

test('node: text groups cover every page once, in order, TEXT_GROUP_PAGES a group and the last one the rest; file names give the pages from 1 (needs nothing)', () => {
  assert.deepEqual(planTextGroups(1), [{ first: 0, count: 1, src: 'text/pages-0001-0001.json' }]);
  assert.deepEqual(planTextGroups(TEXT_GROUP_PAGES).map(({ first, count }) => [first, count]), [[0, TEXT_GROUP_PAGES]]);
  const groups = planTextGroups(2 * TEXT_GROUP_PAGES + 3);
  assert.deepEqual(groups.map(({ first, count }) => [first, count]), [[0, TEXT_GROUP_PAGES], [TEXT_GROUP_PAGES, TEXT_GROUP_PAGES], [2 * TEXT_GROUP_PAGES, 3]]);
  assert.equal(groups[2].src, `text/pages-${String(2 * TEXT_GROUP_PAGES + 1).padStart(4, '0')}-${String(2 * TEXT_GROUP_PAGES + 3).padStart(4, '0')}.json`);
  assert.deepEqual(planTextGroups(0), []);
});

test('node: a text group\'s file holds each page\'s text file, decoded to the record its own file gives, null for a page without one (needs nothing)', () => {
  const files = [JSON.stringify(encodePageText(record('Zebra'))), null, `${JSON.stringify(encodePageText(record('Café')))}\n`];
  const json = JSON.parse(encodeTextGroup(40, files));
  const records = checkTextGroup(json, 'g.json', { first: 40, count: 3 }).map((page) => page && decodePageText(page, 'g.json'));
  assert.equal(records[0].text, 'Zebra');
  assert.equal(records[1], null);
  assert.deepEqual(records[2].items.map((item) => [item.str, item.tx, item.family]), [['Café', [12, 0, 0, 12, 40, 80], 'sans-serif']]);
});

test('node: a bad text group file or textGroups entry is refused with an error naming the file and what is wrong (needs nothing)', () => {
  const json = JSON.parse(encodeTextGroup(0, [JSON.stringify(encodePageText(record('a')))]));
  assert.throws(() => checkTextGroup({ pages: [] }, 'g.json', { first: 0, count: 0 }), /the text group g\.json is not a conecurl text group/);
  assert.throws(() => checkTextGroup(json, 'g.json', { first: 0, count: 2 }), /g\.json holds pages 0 \+ 1, not the 0 \+ 2 book\.json names/);
  assert.throws(() => checkTextGroup({ ...json, version: 99 }, 'g.json', { first: 0, count: 1 }), /format version 99.*update conecurl/);
  const manifest = (textGroups) => makeManifest({ pages: [page, page, page], textGroups });
  assert.doesNotThrow(() => checkManifest(manifest([{ first: 0, count: 2, src: 'a.json' }, { first: 2, count: 1, src: 'b.json' }]), 'book.json'));
  assert.equal(checkManifest(makeManifest({ pages: [page] }), 'book.json').textGroups, undefined, 'optional: a document without groups reads each page\'s own file');
  for (const [groups, what] of [
    [{}, /'textGroups' is not an array/],
    [[{ first: 0, count: 2 }], /'textGroups\[0\]' needs a src/],
    [[{ first: 0, count: 2, src: 'a.json' }, { first: 1, count: 2, src: 'b.json' }], /'textGroups\[1\]' needs a src and pages \(first, count\) after the group before it and below 3/],
    [[{ first: 2, count: 2, src: 'a.json' }], /'textGroups\[0\]'/],
    [[{ first: 0, count: 0, src: 'a.json' }], /'textGroups\[0\]'/],
  ]) {
    assert.throws(() => checkManifest({ ...manifest(), textGroups: groups }, 'book.json'), what);
  }
});
