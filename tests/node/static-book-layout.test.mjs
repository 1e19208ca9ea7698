// Node tests of the static fallback's page layout (web/src/static-book.js): the positions and open
// pages it computes in plain JS (so it works without the wasm engine) equal the engine Book's, for
// every page count from 1 to 9 in both displays, at every position.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { firstVisiblePage, lastPosition, positionOfPage, spreadAt } from '../../web/src/static-book.js';
import { loadEngineForNode } from './load-engine.mjs';

let engine;
before(async () => { engine = await loadEngineForNode(); });

test('node: StaticBook positions and open pages equal the engine Book\'s for 1 to 9 pages, single and double (needs the wasm built)', () => {
  let checked = 0;
  for (const display of ['single', 'double']) {
    for (let pageCount = 1; pageCount <= 9; pageCount++) {
      const book = engine.Book.create({ pageCount, display });
      try {
        const where = `${pageCount} pages, ${display}`;
        assert.equal(lastPosition(pageCount, display), book.lastPosition(), where);
        for (let page = 0; page < pageCount; page++) {
          assert.equal(positionOfPage(page, pageCount, display), book.positionOfPage(page), `${where}, page ${page}`);
        }
        for (let position = 0; position <= book.lastPosition(); position++) {
          book.jumpTo(position);
          assert.equal(firstVisiblePage(position, pageCount, display), book.firstVisiblePage(), `${where}, position ${position}`);
          // The engine's resting leaves: a turned one shows its back, an unturned one its front.
          const engineSpread = {};
          for (const leaf of book.frame()) {
            if (leaf.curl.rho > Math.PI / 2) engineSpread.turned = leaf.backPage;
            else engineSpread.unturned = leaf.frontPage;
          }
          assert.deepEqual(spreadAt(position, pageCount, display), engineSpread, `${where}, position ${position}`);
          checked++;
        }
      } finally {
        book.delete();
      }
    }
  }
  // Every position of every book was compared: single 1 + ... + 9 = 45, double (ceil(n / 2) + 1 each) 34.
  assert.equal(checked, 45 + 34);
});
