// Cross-engine journeys with documents: live HTML pages, the PDF viewer (toolbar, search with marks on
// the page, selectable text) and a site made by `conecurl publish` (opens, searches, turns).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { makeDocumentPdf } from '../fixtures/document-pdf.mjs';
import { READER_ENTRY, publish, root } from '../node/publish-run.mjs';

const HTML = '/tests/browser/fixtures/html-fixture.html';
const PDF = '/tests/browser/fixtures/pdf-fixture.html';
/** Where a journey publishes its site: under build/ (git-ignored), served by the suite's server; one folder per engine. */
const SITES = 'build/engines-site';

// --- in-page helpers (run inside the page: they see only their arguments and the page) ---

/** A double book of 6 pages in the HTML fixture whose page 2 (right of the spread [1, 2]) is the live HTML page. */
async function openHtmlBook(options) {
  const html = window.makeHtmlPage();
  window.htmlHome = document.createElement('div');
  window.htmlHome.append(html);
  document.body.append(window.htmlHome);
  const pages = Array.from({ length: 6 }, (_, i) => (i === 2 ? html : window.makeNumberedPage(i)));
  window.book = await window.Flipbook.create(window.container, { pages, display: 'double', startPage: 1, ...options });
  window.events = [];
  for (const type of ['turnstart', 'turned', 'pageschange']) window.book.addEventListener(type, (e) => window.events.push({ type, ...e.detail }));
  // Told when a wait times out (scripts/engines.mjs): where the book stands.
  window.__explain = () => `events ${window.events.map((e) => e.type).join(' ')}; page ${window.book.page}, animating ${window.book.animating}, `
    + `queued ${window.book.surface.queuedTurns}, frames drawn ${window.book.surface.framesDrawn}, context lost ${window.book.surface.canvas.getContext('webgl2')?.isContextLost()}`;
  await window.book.whenIdle();
  return window.book.surface.kind;
}

/** The HTML page's parts: viewport rectangles, whether its sheet shows live, what it holds, and where page `index` lies open (viewport px). */
function htmlParts(index) {
  const root = document.getElementById('form');
  const rect = (el) => { const { x, y, width, height } = el.getBoundingClientRect(); return { x, y, width, height }; };
  const sheet = root.closest('.conecurl-html-page');
  const canvas = window.book.surface.canvas.getBoundingClientRect();
  return {
    input: rect(root.querySelector('.name')), button: rect(root.querySelector('.count')), link: rect(root.querySelector('.link')),
    block: rect(root.querySelector('.block')), sheet: rect(sheet), live: !sheet.inert,
    count: root.querySelector('.count').textContent, typed: root.querySelector('.name').value,
    place: window.book.openPagePlaces().filter((p) => p.page === index).map((p) => ({ x: canvas.x + p.x, width: p.width }))[0] ?? null,
  };
}

/** The WebGL book drawn now, read back: RGB at viewport points, and the dark pixels in a viewport rectangle. */
function readBack(points, box) {
  const book = window.book;
  const canvas = book.surface.canvas.getBoundingClientRect();
  book.surface.drawNow();
  const pixels = book.surface.readPixels();
  const ratio = pixels.width / book.surface.canvas.clientWidth;
  const at = (x, y) => {
    const i = (Math.round((y - canvas.top) * ratio) * pixels.width + Math.round((x - canvas.left) * ratio)) * 4;
    return Array.from(pixels.data.slice(i, i + 3));
  };
  let dark = 0;
  if (box) {
    for (let y = Math.ceil(box.y); y < box.y + box.height; y++) {
      for (let x = Math.ceil(box.x); x < box.x + box.width; x++) if (Math.max(...at(x, y)) < 110) dark++;
    }
  }
  return { colours: points.map(([x, y]) => at(x, y)), dark };
}

/** Resolves once no turn moves or waits and no page loads (as the Chromium tests' settle()). */
async function settleBook() {
  const busy = () => window.book.animating || window.book.surface.queuedTurns > 0;
  const frame = () => new Promise((resolve) => requestAnimationFrame(resolve));
  for (;;) {
    if (busy()) { await frame(); continue; }
    await window.book.whenIdle();
    await frame();
    if (!busy()) return;
  }
}

/** The toolbar's buttons by their names (the hidden text a screen reader reads), visible or in the More menu. */
function toolbarButtons() {
  const bar = document.querySelector('[role="toolbar"]');
  if (!bar) return null;
  return Array.from(bar.querySelectorAll('button'), (b) => {
    const r = b.getBoundingClientRect();
    return { name: (b.getAttribute('aria-label') || b.textContent).trim(), shown: r.width > 0 && r.height > 0 && !b.closest('[hidden]'),
      x: r.x + r.width / 2, y: r.y + r.height / 2 };
  });
}

/** The Search panel's state: its field (focused?), status text, results, marks and their boxes, the text layer's spans. */
function searchState() {
  const panel = Array.from(document.querySelectorAll('[role="dialog"]')).find((d) => d.getAttribute('aria-label') === 'Search'
    || document.getElementById(d.getAttribute('aria-labelledby') || '')?.textContent.trim() === 'Search');
  const field = panel?.querySelector('input[type="search"]');
  const box = (el) => { const { x, y, width, height } = el.getBoundingClientRect(); return { x, y, width, height }; };
  return {
    open: Boolean(panel && !panel.hidden && panel.getBoundingClientRect().width > 0),
    focused: Boolean(field) && document.activeElement === field,
    field: field ? box(field) : null,
    status: panel?.querySelector('[role="status"]')?.textContent ?? null,
    results: Array.from(panel?.querySelectorAll('.conecurl-results button') ?? [], (b) => ({ text: b.textContent, current: b.getAttribute('aria-current') === 'true' })),
    animating: window.book.animating, openPages: window.book.openPages,
    marks: Array.from(document.querySelectorAll('[data-search-hit]'), (m) => ({ page: Number(m.dataset.page), current: m.hasAttribute('data-current'), box: box(m) })),
    spans: Array.from(document.querySelectorAll('[data-text-layer] span'), (s) => ({ page: Number(s.closest('[data-text-layer]').dataset.page), text: s.textContent, box: box(s) })),
  };
}

/** Whether every open page has its text layer with spans, and nothing moves. */
function textLayersLaid() {
  const open = window.book.openPages;
  const layers = Array.from(document.querySelectorAll('[data-text-layer]'));
  return !window.book.animating && layers.length === open.length
    && open.every((p) => layers.some((l) => Number(l.dataset.page) === p && l.querySelector('span')));
}

// --- on this side ---

const centre = (r) => ({ x: r.x + r.width / 2, y: r.y + r.height / 2 });
const isRed = ([r, g, b]) => r > 140 && g < 90 && b < 90;
const inside = (point, r, slack = 0) => point.x >= r.x - slack && point.x <= r.x + r.width + slack && point.y >= r.y - slack && point.y <= r.y + r.height + slack;

/**
 * The bounding box of the dark pixels of a viewport screenshot in `box` grown by `across` px each side
 * and `up` px above and below (as text-layer.spec.js's inkBox; less than half the gap to the next line).
 */
function inkBox(screenshot, box, across, up) {
  const png = PNG.sync.read(screenshot);
  const x0c = Math.max(0, Math.floor(box.x - across)), y0c = Math.max(0, Math.floor(box.y - up));
  const x1c = Math.min(png.width, Math.ceil(box.x + box.width + across)), y1c = Math.min(png.height, Math.ceil(box.y + box.height + up));
  let [x0, y0, x1, y1, count] = [Infinity, Infinity, -Infinity, -Infinity, 0];
  for (let y = y0c; y < y1c; y++) {
    for (let x = x0c; x < x1c; x++) {
      const i = (y * png.width + x) * 4;
      if (png.data[i] + png.data[i + 1] + png.data[i + 2] < 3 * 110) {
        count++;
        [x0, y0, x1, y1] = [Math.min(x0, x), Math.min(y0, y), Math.max(x1, x + 1), Math.max(y1, y + 1)];
      }
    }
  }
  return count === 0 ? null : { x: x0, y: y0, width: x1 - x0, height: y1 - y0, count };
}

/** The ink around a span lies within it (a few px of slack) and fills most of its width. */
function assertInkUnder(ink, box, what, slack = 3) {
  assert.ok(ink, `dark pixels near ${what}`);
  assert.ok(ink.x >= box.x - slack && ink.y >= box.y - slack && ink.x + ink.width <= box.x + box.width + slack
    && ink.y + ink.height <= box.y + box.height + slack, `the ink of ${what} ${JSON.stringify(ink)} lies in its span ${JSON.stringify(box)}`);
  assert.ok(ink.width > 0.85 * box.width, `the ink of ${what} fills its span's width (${ink.width} of ${box.width})`);
}

/** Types `text` with real key input, one key at a time (each engine's driver presses a named key). */
async function typeKeys(browser, text) {
  for (const key of text) await browser.key(key);
}

/** Defines the document journeys on engineSuite's context: { engine, url, open, evaluate, journey, heard, browser }. */
export function documentJourneys(context) {
  const { engine, open, evaluate, journey } = context;
  let pdf;  // the document tests' PDF (tests/fixtures/document-pdf.mjs), made once
  const documentPdf = async () => (pdf ??= await makeDocumentPdf());

  journey('a live HTML page draws in the WebGL book (its red block read back), takes typed keys and clicks without turning, keeps its place when pages are inserted and removed, and turns with its texture', async () => {
    const { browser } = context;
    await open(HTML);
    // A slow turn (4 s): the moving leaf is read back while it lifts, wherever a busy machine has it.
    assert.equal(await evaluate(openHtmlBook, { duration: 4000 }), 'webgl', 'the book drew with WebGL2');
    const before = await evaluate(htmlParts, 2);
    assert.equal(before.live, true, 'the open HTML page lies live over its place');
    assert.ok(before.place, 'page 2 is open');
    assert.ok(Math.abs(before.sheet.x - before.place.x) < 1 && Math.abs(before.sheet.width - before.place.width) < 1,
      `the live page ${JSON.stringify(before.sheet)} lies over its place ${JSON.stringify(before.place)}`);
    const textureBefore = await evaluate(readBack, [[centre(before.block).x, centre(before.block).y]], before.input);
    assert.ok(isRed(textureBefore.colours[0]), `the page's texture shows the red block where the DOM has it: ${textureBefore.colours[0]}`);

    // Real input: a click in the field, keys typed, a caret key the field keeps; the counter and link clicked.
    await browser.click(centre(before.input).x, centre(before.input).y);
    await typeKeys(browser, 'Hello');
    await browser.key('ArrowLeft');
    for (let i = 0; i < 3; i++) await browser.click(centre(before.button).x, centre(before.button).y);
    await browser.click(centre(before.link).x, centre(before.link).y);
    await browser.click(centre(before.block).x, centre(before.block).y);
    await evaluate(settleBook);  // past a click series: a click that reached the book would have turned it
    const after = await evaluate(htmlParts, 2);
    assert.deepEqual([after.typed, after.count], ['Hello', '3'], 'the keys typed into the field and the clicks reached the button');
    assert.deepEqual(await evaluate(() => [window.book.page, window.events.length, location.hash]), [1, 0, '#ordered']);

    // The texture is made again once the content rested: the field shows the typed text (more dark pixels).
    await browser.waitFor(async (box, dark) => {
      await window.book.whenIdle();
      const b = window.book;
      const canvas = b.surface.canvas.getBoundingClientRect();
      b.surface.drawNow();
      const px = b.surface.readPixels();
      const ratio = px.width / b.surface.canvas.clientWidth;
      let n = 0;
      for (let y = Math.ceil(box.y); y < box.y + box.height; y++) {
        for (let x = Math.ceil(box.x); x < box.x + box.width; x++) {
          const i = (Math.round((y - canvas.top) * ratio) * px.width + Math.round((x - canvas.left) * ratio)) * 4;
          if (Math.max(px.data[i], px.data[i + 1], px.data[i + 2]) < 110) n++;
        }
      }
      return n > dark + 20;
    }, after.input, textureBefore.dark);
    assert.ok(isRed((await evaluate(readBack, [[centre(after.block).x, centre(after.block).y]])).colours[0]), 'the block is still red in the new texture');

    // Pages inserted before the open spread, then removed: the reader's pages stay open, the HTML page
    // live over its new place with what was typed; one pageschange each.
    const inserted = await evaluate(async () => {
      const { makeNumberedPage } = await import('/tests/browser/fixtures/test-pages.js');
      const detail = await window.book.insertPages(0, [makeNumberedPage(6), makeNumberedPage(7)]);
      await window.book.whenIdle();
      return { detail, page: window.book.page, openPages: window.book.openPages };
    });
    assert.deepEqual(inserted, { detail: { change: 'insert', at: 0, count: 2, pageCount: 8, page: 3 }, page: 3, openPages: [3, 4] });
    const moved = await evaluate(htmlParts, 4);
    assert.ok(moved.live && moved.place && Math.abs(moved.sheet.x - moved.place.x) < 1 && moved.typed === 'Hello',
      `the HTML page (now page 4) is live over its place: ${JSON.stringify({ live: moved.live, sheet: moved.sheet, place: moved.place, typed: moved.typed })}`);
    const removed = await evaluate(async () => {
      const detail = await window.book.removePages(0, 2);
      await window.book.whenIdle();
      return { detail, page: window.book.page, openPages: window.book.openPages };
    });
    assert.deepEqual(removed, { detail: { change: 'remove', at: 0, count: 2, pageCount: 6, page: 1 }, page: 1, openPages: [1, 2] });
    assert.deepEqual(await evaluate(() => window.events.map((e) => `${e.type} ${e.change ?? ''}`.trim())), ['pageschange insert', 'pageschange remove']);
    const back = await evaluate(htmlParts, 2);
    assert.ok(back.live && Math.abs(back.sheet.x - before.sheet.x) < 1, 'the HTML page is back live over its first place');

    // The turn: once the leaf lifts the live page is hidden and the moving leaf shows its texture, red block and all.
    const red = await evaluate(async () => {
      let ended = false;
      window.turning = window.book.next();
      window.turning.then((landed) => { ended = true; window.turnLanded = landed; });
      const lifted = () => window.book.surface.book.frame().some((leaf) => !leaf.resting && leaf.curl.rho > 0.05);
      while (!lifted() && !ended) await new Promise((resolve) => requestAnimationFrame(resolve));
      if (!lifted()) return { ended, page: window.book.page, animating: window.book.animating };
      window.book.surface.drawNow();
      const pixels = window.book.surface.readPixels();
      let n = 0;
      for (let i = 0; i < pixels.data.length; i += 4) if (pixels.data[i] > 140 && pixels.data[i + 1] < 90 && pixels.data[i + 2] < 90) n++;
      return { n, live: !document.getElementById('form').closest('.conecurl-html-page').inert };
    });
    assert.equal(red.ended, undefined, `the leaf lifted before the turn ended: ${JSON.stringify(red)}`);
    assert.equal(red.live, false, 'the live page is hidden while its leaf moves');
    assert.ok(red.n > 200, `the moving leaf shows the red block (${red.n} red pixels)`);
    // Waited for by polling, so a turn that never lands says where the book stood (its __explain).
    assert.equal(await browser.waitFor(() => window.turnLanded !== undefined && String(window.turnLanded)), 'true', 'the turn landed');
    await evaluate(settleBook);
    assert.deepEqual(await evaluate(() => [window.book.page, window.events.filter((e) => e.type === 'turned').length]), [3, 1]);
  });

  journey('the PDF viewer: the toolbar has its buttons; the Search panel, typed into, finds the hits, says "n of N" and marks them over the words on the page; the text layer lies over the words and a mouse drag selects a line', async () => {
    const { browser } = context;
    const { base64 } = await documentPdf();
    await open(PDF);
    await evaluate(async (base64) => {
      // Taller than the fixture's 640x400: pages near their size in points, lines far enough apart to tell apart in the ink.
      Object.assign(window.container.style, { width: '780px', height: '580px' });
      window.book = await window.Flipbook.create(window.container, {
        pdf: window.bytesFromBase64(base64), display: 'double', duration: 300, controls: true, startPage: 1,
      });
      window.events = [];
      for (const type of ['turnstart', 'turned']) window.book.addEventListener(type, (e) => window.events.push(type));
      await window.book.whenIdle();
    }, base64);
    const buttons = await evaluate(toolbarButtons);
    assert.ok(buttons, 'the book has a toolbar');
    const named = (name) => buttons.find((b) => b.name === name);
    for (const name of ['Previous page', 'Next page', 'Zoom in', 'Zoom out', 'Contents', 'Search', 'Download', 'Print', 'Fullscreen']) {
      assert.ok(named(name), `the toolbar has ${name}: ${buttons.map((b) => b.name).join(', ')}`);
    }
    assert.ok(named('Search').shown, 'Search shows in the toolbar');

    const expected = [1, 1, 4];  // the pages with 'zebra' (tests/fixtures/document-pdf.mjs); book.search() says so below

    // The text layer: its spans lie over the rendered words (dark pixels of a screenshot).
    await browser.waitFor(textLayersLaid);
    let state = await evaluate(searchState);
    const line = state.spans.find((s) => s.page === 1 && s.text === 'The zebra has stripes.');
    assert.ok(line, `page 2's text layer has its line: ${state.spans.filter((s) => s.page === 1).map((s) => s.text).join('|')}`);
    const shot = await browser.screenshot();
    for (const span of state.spans.filter((s) => s.page === 1 && /^(The zebra has stripes\.|Stripes confuse flies, it is said\.)$/.test(s.text))) {
      assertInkUnder(inkBox(shot, span.box, 14, 3), span.box, `'${span.text}'`);
    }

    // A real mouse drag over the line selects it, and does not turn.
    const y = line.box.y + line.box.height / 2;
    await browser.drag(Array.from({ length: 11 }, (_, i) => ({ x: line.box.x + 1 + (line.box.width - 2) * (i / 10), y })));
    const selected = await evaluate(() => {
      const button = document.querySelector('[data-passage-link]');
      return { text: window.getSelection().toString(), page: window.book.page, animating: window.book.animating, events: window.events,
        passage: button && !button.hidden && button.getBoundingClientRect().width > 0 ? button.textContent : null };
    });
    assert.ok(selected.text.includes('zebra has stripes'), `the drag selected '${selected.text}'`);
    assert.deepEqual([selected.page, selected.animating, selected.events], [1, false, []], 'the drag did not turn');
    assert.equal(selected.passage, 'Copy link to this passage', 'the passage button shows by the selection');

    // The Search panel: a click on Search opens it with its field focused; typed keys and Enter search.
    // Where Search is now: the toolbar fits itself again when a part comes (Read aloud, once the voices answer).
    const search = (await evaluate(toolbarButtons)).find((b) => b.name === 'Search');
    await browser.click(search.x, search.y);
    // (The panel's live region named here for the waits below: the book has a live region of its own.)
    await browser.waitFor(() => {
      const field = document.activeElement;
      const panel = field?.type === 'search' && field.getAttribute('aria-label') === 'Search the book' && field.closest('[role="dialog"]');
      if (panel) panel.querySelector('[role="status"]').id = 'searchStatus';
      return Boolean(panel);
    });
    await typeKeys(browser, 'zebra');
    await browser.key('Enter');
    await browser.waitFor((n, page) => {
      const status = document.getElementById('searchStatus');
      return status?.textContent === `1 of ${n}` && !window.book.animating && window.book.openPages.includes(page)
        && document.querySelector('[data-search-hit][data-current]') !== null;
    }, expected.length, expected[0]);
    state = await evaluate(searchState);
    assert.equal(state.status, `1 of ${expected.length}`);
    assert.deepEqual(state.results.map((r) => [r.text.match(/^Page \d+/)?.[0], r.current]),
      expected.map((page, i) => [`Page ${page + 1}`, i === 0]));
    // The marks: one per hit on the open pages, each over a word of its page's text layer that holds it.
    const open1 = state.marks.filter((m) => m.page === 1);
    assert.equal(open1.length, 2, `page 2's two hits are marked: ${JSON.stringify(state.marks)}`);
    for (const mark of open1) {
      const over = state.spans.find((s) => s.page === 1 && /zebra/i.test(s.text) && inside(centre(mark.box), s.box, 1));
      assert.ok(over, `the mark ${JSON.stringify(mark.box)} lies over a 'zebra' of the page: ${JSON.stringify(state.spans.filter((s) => s.page === 1))}`);
      assert.ok(mark.box.width > 5 && mark.box.height > 3, `the mark has a size: ${JSON.stringify(mark.box)}`);
    }
    // Enter again: the next hit.
    await browser.key('Enter');
    await browser.waitFor((n) => document.getElementById('searchStatus').textContent === `2 of ${n}`, expected.length);
    // Escape closes the panel and ends the search: the marks go.
    await browser.key('Escape');
    await browser.waitFor(() => document.querySelectorAll('[data-search-hit]').length === 0);
    assert.deepEqual(await evaluate(async () => (await window.book.search('zebra')).map((hit) => hit.page)), expected, 'the panel showed the book\'s hits');
    await evaluate(() => window.book.clearSearch());
  });

  journey('a site made by `conecurl publish` opens its book, its search finds and marks the hits, and it turns by a click', async () => {
    const { browser } = context;
    // Published afresh on each run (the site carries its own copy of web/src), into the folder the server
    // serves, one per engine (the two engines' suites may run at once).
    const out = path.join(root, SITES, engine);
    fs.mkdirSync(path.dirname(out), { recursive: true });
    const source = path.join(root, SITES, `${engine}.pdf`);
    fs.writeFileSync(source, Buffer.from((await documentPdf()).base64, 'base64'));
    fs.rmSync(out, { recursive: true, force: true });
    const result = await publish([source, '--out', out, '--height', '800', '--title', 'The document test']);
    assert.equal(result.code, 0, `conecurl publish: ${result.stderr}`);
    await browser.goto(context.url(`/${SITES}/${engine}/index.html`));
    const site = await evaluate(async (url) => {
      window.book = await (await import(document.querySelector(url).src)).book;
      if (!window.book) return { problem: document.querySelector('[role="alert"]')?.textContent ?? 'no book' };
      await window.book.whenIdle();
      window.events = [];
      window.book.addEventListener('turned', (e) => window.events.push(e.detail.page));
      return { count: window.book.pageCount, page: window.book.page, surface: window.book.surface.kind, title: document.title,
        toolbar: Boolean(document.querySelector('[role="toolbar"]')), listening: Array.isArray(window.__heard) };
    }, READER_ENTRY);
    // `listening`: the suite's heard.js ran in the site's page (what it throws is heard, so "nothing heard" means something).
    assert.deepEqual(site, { count: 8, page: 0, surface: 'webgl', title: 'The document test', toolbar: true, listening: true });

    const hits = await evaluate(async () => (await window.book.search('zebra')).map((h) => h.page));
    assert.deepEqual(hits, [1, 1, 4]);
    // Shown: the book turns to the hit's page and marks it over the page.
    const shown = await evaluate(async () => {
      const [hit] = await window.book.search('zebra');
      await window.book.showHit(hit);
      await window.book.whenIdle();
      const canvas = window.book.surface.canvas.getBoundingClientRect();
      const places = window.book.openPagePlaces().map((p) => ({ page: p.page, x: canvas.x + p.x, y: canvas.y + p.y, width: p.width, height: p.height }));
      const marks = Array.from(document.querySelectorAll('[data-search-hit]'), (m) => {
        const { x, y, width, height } = m.getBoundingClientRect();
        return { page: Number(m.dataset.page), box: { x, y, width, height } };
      });
      return { openPages: window.book.openPages, places, marks };
    });
    assert.ok(shown.openPages.includes(1), `the hit's page is open: ${shown.openPages}`);
    assert.equal(shown.marks.filter((m) => m.page === 1).length, 2, `both hits on the page are marked: ${JSON.stringify(shown.marks)}`);
    for (const mark of shown.marks) {
      const place = shown.places.find((p) => p.page === mark.page);
      assert.ok(place && inside(centre(mark.box), place) && mark.box.width > 5, `the mark ${JSON.stringify(mark)} lies on its page ${JSON.stringify(place)}`);
    }
    await evaluate(() => window.book.clearSearch());

    // A click on the right-hand page's free edge (the turn area beside a text layer) turns forward.
    const from = await evaluate(() => { window.events.length = 0; return window.book.page; });
    const right = shown.places.reduce((a, b) => (b.x > a.x ? b : a));
    await browser.click(right.x + right.width * 0.95, right.y + right.height * 0.5);
    await browser.waitFor(() => window.events.length > 0);
    await evaluate(settleBook);
    const turned = await evaluate(() => [window.book.page, window.events]);
    assert.ok(turned[0] > from, `the click turned forward from page ${from}: ${JSON.stringify(turned)}`);
  });
}
