// Browser: what a book loads and when. A plain book of images fetches none of the optional parts (page
// sound, autoplay, page memory, live pages, HTML pages, PDF, the 2D fallback, the document API, the edge
// marks, the text layer and passage links, the viewer): each is
// fetched only once an option or a call asks for it (counted by the module URLs the page requests); and
// page images reach the GPU outside the turn's frames or in bands (bytes counted per frame).
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

// The optional modules, each loaded by a dynamic import() only when asked for.
const OPTIONAL = {
  sound: '/web/src/book/page-sound.js',
  autoplay: '/web/src/book/autoplay.js',
  memory: '/web/src/book/page-memory.js',
  live: '/web/src/book/live-pages.js',
  html: '/web/src/layers/html-pages.js',
  pdf: '/web/src/document/pdf-pages.js',
  fallback: '/web/src/book/static-book.js',
  canvas: '/web/src/surfaces/canvas-surface.js',
  // The document API, each part on first use.
  outline: '/web/src/document/book-outline.js',
  search: '/web/src/document/book-search.js',
  textIndex: '/web/src/document/text-index.js',
  thumbnails: '/web/src/document/page-thumbnails.js',
  document: '/web/src/document/book-document.js',
  // Issue 23's other parts: the edge marks (edgeMarks, on with controls), a PDF's text layer and its
  // passage link, the viewer (controls).
  edgeMarks: '/web/src/document/edge-marks.js',
  edgeTabs: '/web/src/layers/edge-tabs.js',
  textLayer: '/web/src/layers/text-layer.js',
  passageLink: '/web/src/document/passage-link.js',
  viewer: '/web/src/viewer/attach-controls.js',
  viewerOptions: '/web/src/viewer/viewer-options.js',
};

// Every module path under /web/src/ the page requests, from now on.
function recordModules(page) {
  const modules = new Set();
  page.on('request', (request) => {
    const { pathname } = new URL(request.url());
    if (pathname.startsWith('/web/src/')) modules.add(pathname);
  });
  return modules;
}

test('browser: a plain book of images loads none of the optional modules (sound, autoplay, page memory, live pages, HTML, PDF, 2D fallback) (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 6 }));
  expect(modules.has('/web/src/book/flipbook.js')).toBe(true);  // the recording sees the entry's modules
  expect(modules.has('/web/src/surfaces/book-view.js')).toBe(true);
  expect([...modules].filter((path) => Object.values(OPTIONAL).includes(path))).toEqual([]);
  // The sound, off, still answers what it is doing; setOptions({ sound: true }) brings its module.
  expect(await page.evaluate(() => window.book.sound.state)).toBe('off');
  await page.evaluate(() => window.book.setOptions({ sound: true }));
  await expect.poll(() => modules.has(OPTIONAL.sound)).toBe(true);
  await expect.poll(() => page.evaluate(() => window.book.sound.state)).toBe('waiting');
  expect(problems).toEqual([]);
});

test('browser: the optional modules load when their option or call asks for them: sound, autoplay, hash, insertPages (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 6, sound: true, autoplay: { interval: 60_000 }, hash: true }));
  for (const name of ['sound', 'autoplay', 'memory']) expect(modules.has(OPTIONAL[name]), name).toBe(true);
  expect(modules.has(OPTIONAL.live)).toBe(false);
  expect(await page.evaluate(() => window.book.sound.state)).toBe('waiting');  // page-sound.js's own answer
  const count = await page.evaluate(async () => {
    await window.book.insertPages(6, [window.makeNumberedPage(6)]);
    return window.book.pageCount;
  });
  expect(count).toBe(7);
  expect(modules.has(OPTIONAL.live)).toBe(true);
  expect(problems).toEqual([]);
});

test('browser: edgeMarks: true loads the edge marks and their buttons, and only then (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => window.openBook({ pages: 6 }));
  expect(modules.has(OPTIONAL.edgeMarks)).toBe(false);
  await page.evaluate(() => window.openBook({ pages: 6, edgeMarks: true, outline: [{ title: 'Two', page: 2 }] }));
  expect(modules.has(OPTIONAL.edgeMarks)).toBe(true);
  expect(modules.has(OPTIONAL.edgeTabs)).toBe(true);
  expect(modules.has(OPTIONAL.viewer)).toBe(false);  // the marks come without the toolbar
  expect(problems).toEqual([]);
});

test('browser: with controls, the first spread shows before the toolbar, the input modules and the edge marks are asked for; the book keeps the toolbar\'s room from the start (request times, heights)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const seen = await page.evaluate(async () => {
    // When each page's picture first went to the surface, and the book's height at the first.
    const { BookView } = await import('/web/src/surfaces/book-view.js');
    const setPageImage = BookView.prototype.setPageImage;
    const uploaded = {};
    let height = null;
    BookView.prototype.setPageImage = function (index, ...rest) {
      uploaded[index] ??= performance.now();
      height ??= this.canvas.getBoundingClientRect().height;
      return setPageImage.call(this, index, ...rest);
    };
    try {
      await window.openBook({ pages: 6, display: 'double', controls: true });
    } finally {
      BookView.prototype.setPageImage = setPageImage;
    }
    const started = Object.fromEntries(performance.getEntriesByType('resource')
      .map((entry) => [new URL(entry.name).pathname, entry.startTime]));
    const shownAt = Math.max(...window.book.openPages.map((index) => uploaded[index]));
    return { shownAt, height, started, after: window.book.element.querySelector('canvas').getBoundingClientRect().height };
  });
  const late = ['/web/src/viewer/attach-controls.js', '/web/src/viewer/toolbar.js', '/web/src/input/book-input.js',
    '/web/src/input/pointer-drag.js', '/web/src/document/edge-marks.js'];
  for (const path of late) {
    expect(seen.started[path], `${path} was fetched`).toBeGreaterThan(seen.shownAt);
  }
  expect(seen.started['/web/src/viewer/toolbar-room.js']).toBeLessThan(seen.shownAt);  // the room, before
  expect(seen.after).toBe(seen.height);  // the toolbar came into the room kept for it: nothing moved
  expect(problems).toEqual([]);
});

test('browser: a first page showing its placeholder while its image loads gets the toolbar and input then, not once the image lands (an image held back)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(() => {
    let release;
    const held = new Promise((resolve) => { release = resolve; });
    window.release = release;
    const pages = Array.from({ length: 6 }, (_, i) => window.makeNumberedPage(i));
    pages[0] = { src: () => held.then(() => window.makeNumberedPage(0)), placeholder: window.makeNumberedPage(0, 32, 40) };
    window.opening = window.openBook({ pages, display: 'single', controls: true });
  });
  // Without them until its image lands, this waits until the test's time runs out.
  await page.waitForFunction(() => document.querySelector('[role="toolbar"]') !== null);
  expect(await page.evaluate(() => performance.getEntriesByType('resource').some((entry) => entry.name.endsWith('/web/src/input/book-input.js')))).toBe(true);
  const state = await page.evaluate(async () => {
    window.release();
    await window.opening;
    return window.book.pageState(0).state;
  });
  expect(state).toBe('loaded');
  expect(problems).toEqual([]);
});

test('browser: hash: the first view opens at #page=N with page memory loaded only for it (module count)', async ({ page }) => {
  const modules = recordModules(page);
  const problems = await openReady(page, `${FIXTURE}#page=5`);
  expect(await page.evaluate(() => window.openBook({ pages: 8, display: 'single' }))).toEqual({ page: 0, display: 'single' });
  expect(modules.has(OPTIONAL.memory)).toBe(false);  // no hash option: the address is not read
  expect(await page.evaluate(() => window.openBook({ pages: 8, display: 'single', hash: true }))).toEqual({ page: 4, display: 'single' });
  expect(modules.has(OPTIONAL.memory)).toBe(true);
  expect(problems).toEqual([]);
});

// In the page, before the book makes its context: every texImage2D / texSubImage2D is counted in bytes
// of pixels (width x height x 4; an allocation without pixels counts 0) in the bucket of the animation
// frame it falls in (uploads between two frames count in the later one's), when a leaf moves then.
function countUploadsPerFrame(page) {
  return page.addInitScript(() => {
    const sizeOf = (source) => [source.naturalWidth || source.videoWidth || source.width, source.naturalHeight || source.videoHeight || source.height];
    const bytesOf = (name, args) => {
      const last = args[args.length - 1];
      if (last === null || last === undefined) return 0;
      // texImage2D(target, level, internal, format, type, source) and texSubImage2D(target, level, x, y, format, type, source): the whole source.
      if ((name === 'texImage2D' && args.length === 6) || (name === 'texSubImage2D' && args.length === 7)) {
        const [width, height] = sizeOf(last);
        return width * height * 4;
      }
      const [width, height] = name === 'texImage2D' ? [args[3], args[4]] : [args[4], args[5]];
      return width * height * 4;
    };
    window.uploadFrames = [];  // { bytes, calls } per animation frame in which a leaf moved
    let open = { bytes: 0, calls: 0 };
    for (const name of ['texImage2D', 'texSubImage2D']) {
      const original = WebGL2RenderingContext.prototype[name];
      WebGL2RenderingContext.prototype[name] = function (...args) {
        if (window.book?.animating) {
          open.bytes += bytesOf(name, args);
          open.calls++;
        }
        return original.apply(this, args);
      };
    }
    // Every frame callback (the book's, the test's) runs wrapped: the first of a frame closes the bucket.
    let frameTime = -1;
    const requestFrame = window.requestAnimationFrame;
    window.requestAnimationFrame = (callback) => requestFrame((now) => {
      if (now !== frameTime) {
        frameTime = now;
        if (open.calls > 0) window.uploadFrames.push(open);
        open = { bytes: 0, calls: 0 };
      }
      callback(now);
    });
    window.flushUploadFrames = () => {
      if (open.calls > 0) window.uploadFrames.push(open);
      open = { bytes: 0, calls: 0 };
      return window.uploadFrames.splice(0);
    };
  });
}

test.describe('at 2x pixel ratio (pages of over 1 MB)', () => {
  test.use({ deviceScaleFactor: 2 });

  test('browser: the pages a turn uncovers are decoded and uploaded while the book rests (default load window): none is loading when the turn starts, and no turning frame uploads more than UPLOAD_BAND_BYTES (bytes counted per frame)', async ({ page }) => {
    await countUploadsPerFrame(page);
    const problems = await openReady(page, FIXTURE);
    const budget = await page.evaluate(async () => {
      const { UPLOAD_BAND_BYTES } = await import('/web/src/surfaces/page-textures.js');
      const pages = Array.from({ length: 12 }, (_, i) => ({ src: () => window.makeNumberedPage(i, 1000, 1250) }));  // over 1 MB each as uploaded
      await window.openBook({ pages, display: 'double', startPage: 1, duration: 1500 });
      return UPLOAD_BAND_BYTES;
    });
    for (let turn = 0; turn < 3; turn++) {
      // The spread a forward turn uncovers: the turning leaf's back and the page under it.
      const before = await page.evaluate(() => {
        const uncovered = window.book.openPages.map((p) => p + 2).filter((p) => p < window.book.pageCount);
        return uncovered.map((p) => window.book.pageState(p).state);
      });
      expect(before, `turn ${turn}`).toEqual(['loaded', 'loaded']);
      await page.evaluate(() => window.flushUploadFrames());
      await page.evaluate(() => window.book.next());
      const frames = await page.evaluate(() => window.flushUploadFrames());
      console.log(`turn ${turn}: uploads in turning frames (bytes): ${frames.map((f) => f.bytes).join(' ') || 'none'}`);
      for (const frame of frames) expect(frame.bytes).toBeLessThanOrEqual(budget);
      await page.evaluate(() => window.settle());
    }
    expect(problems).toEqual([]);
  });

  test('browser: a page that arrives while a leaf moves is uploaded in bands: no frame of the turn uploads more than UPLOAD_BAND_BYTES, and the page shows its image after the turn (bytes counted per frame, pixels read back)', async ({ page }) => {
    await countUploadsPerFrame(page);
    const problems = await openReady(page, FIXTURE);
    const { budget, pageBytes } = await page.evaluate(async () => {
      const { UPLOAD_BAND_BYTES } = await import('/web/src/surfaces/page-textures.js');
      // Pages bigger than the screen needs; once `holding`, a page asked for waits for release().
      let release;
      const gate = new Promise((resolve) => { release = resolve; });
      window.release = release;
      window.holding = false;
      const big = (i) => window.makeNumberedPage(i, 1000, 1250);
      const pages = Array.from({ length: 8 }, (_, i) => ({ src: () => (window.holding ? gate.then(() => big(i)) : big(i)) }));
      await window.openBook({ pages, display: 'double', startPage: 1, loadWindow: 1, duration: 4000 });
      window.holding = true;
      const size = window.book.surface.pageImageSize(1);
      return { budget: UPLOAD_BAND_BYTES, pageBytes: size.width * size.height * 4 };
    });
    expect(pageBytes).toBeGreaterThan(2 * budget);  // a whole page would be over budget: it must go in bands
    expect(await page.evaluate(() => window.book.pageState(4).state)).toBe('idle');  // not loaded before the turn
    await page.evaluate(() => window.flushUploadFrames());
    await page.evaluate(async () => {
      const turned = window.book.next();
      window.release();  // page 4, under the turning leaf, arrives now, while it moves
      await turned;
    });
    const frames = await page.evaluate(() => window.flushUploadFrames());
    console.log(`uploads in turning frames (bytes): ${frames.map((f) => f.bytes).join(' ')}; band budget ${budget}, a page ${pageBytes}`);
    expect(frames.length).toBeGreaterThanOrEqual(3);  // the page arrived mid-turn and went up in several frames
    for (const frame of frames) expect(frame.bytes).toBeLessThanOrEqual(budget);
    // Pages 3 and 4 show their own images (the colour read back low in the middle of each place).
    await page.evaluate(() => window.settle());
    const shown = await page.evaluate(() => {
      const view = window.book.surface;
      view.drawNow();
      const pixels = view.readPixels();
      const ratio = pixels.width / view.canvas.clientWidth;
      return view.openPagePlaces().map(({ page: index, x, y, width, height }) => {
        const px = Math.round((x + width / 2) * ratio);
        const py = Math.round((y + height * 0.85) * ratio);  // below the page number
        const i = (py * pixels.width + px) * 4;
        return [index, window.pageAtColor([pixels.data[i], pixels.data[i + 1], pixels.data[i + 2]], 8)];
      });
    });
    expect(shown).toEqual([[3, 3], [4, 4]]);
    expect(problems).toEqual([]);
  });
});
