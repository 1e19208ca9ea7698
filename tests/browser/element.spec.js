// Browser: the <cone-flipbook> element: attributes as options, child <img> pages, events re-dispatched
// from the element, live and rebuilding attribute changes, errors that name the attribute, and the
// book's lifetime following the element's place in the document.
import { test, expect } from '@playwright/test';
import { openReady, withoutWebGL2 } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/element-fixture.html';

test('browser: <cone-flipbook> attributes become Flipbook options (display, direction, start-page, duration, hard-covers, load-window, lighting)', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 10 }, (_, i) => window.pageUrl(i)).join(' ');
    const element = window.makeElement({
      pages, display: 'double', direction: 'rtl', 'start-page': '3', duration: '250', 'hard-covers': 'true',
      'load-window': '1', lighting: 'false',
    });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    await book.whenIdle();  // the first view's neighbours load after it is drawn
    return {
      same: book === element.book,
      display: element.display,
      page: element.page,
      pageCount: element.pageCount,
      // Right to left: the spread's first page (3) lies right of the spine, the second (4) left of it.
      leftRight: window.pagesAt(element, [[150, 300], [490, 300]]),
      resident: book.surface.renderer.residentPageImages(),
      settings: (({ duration, hardCovers, lighting, loadWindow }) => ({ duration, hardCovers, lighting, loadWindow }))(book.options),
    };
  });
  expect(result.same).toBe(true);
  expect(result.display).toBe('double');
  expect(result.page).toBe(3);
  expect(result.pageCount).toBe(10);
  expect(result.leftRight).toEqual([4, 3]);
  // load-window 1: pages 2..5 around the spread (3, 4), not all ten.
  expect(result.resident).toBe(4);
  expect(result.settings).toEqual({ duration: 250, hardCovers: true, lighting: false, loadWindow: 1 });
  expect(problems).toEqual([]);
});

test('browser: child <img> elements are the pages in order with their alt text, hidden while the book shows; a new child rebuilds at the same page', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const images = [0, 1, 2].map((i) => [window.pageUrl(i), `Page ${i} of the test book`]);
    const element = window.makeElement({ display: 'single' }, images);
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const first = {
      pageCount: element.pageCount,
      alts: book.options.pages.map((p) => p.alt),
      centre: window.pagesAt(element, [[320, 300]])[0],
      childWidths: [...element.querySelectorAll('img')].map((img) => img.getBoundingClientRect().width),
      canvasWidth: element.shadowRoot.querySelector('canvas').getBoundingClientRect().width,
    };
    await element.flip(1, { animate: false });
    const rebuilt = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    element.append(Object.assign(document.createElement('img'), { src: window.pageUrl(3), alt: 'Page 3' }));
    await rebuilt;
    return { first, rebuilt: { pageCount: element.pageCount, page: element.page, same: element.book === book, centre: window.pagesAt(element, [[320, 300]])[0] } };
  });
  expect(result.first.pageCount).toBe(3);
  expect(result.first.alts).toEqual(['Page 0 of the test book', 'Page 1 of the test book', 'Page 2 of the test book']);
  expect(result.first.centre).toBe(0);
  expect(result.first.childWidths).toEqual([0, 0, 0]);  // not rendered: no slot while the book shows
  expect(result.first.canvasWidth).toBe(640);
  expect(result.rebuilt).toEqual({ pageCount: 4, page: 1, same: false, centre: 1 });
  expect(problems).toEqual([]);
});

test('browser: <cone-flipbook> re-dispatches ready, progress, pageerror, turnstart and turned with the Flipbook\'s own detail; next() before ready waits for the book', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = [window.pageUrl(0), '/no/such/page.png', window.pageUrl(2), window.pageUrl(3)].join(' ');
    const element = window.makeElement({ pages, display: 'double', duration: '200' });
    const events = [];
    for (const type of ['ready', 'progress', 'pageerror', 'turnstart', 'turned']) {
      element.addEventListener(type, (event) => events.push(event));
    }
    document.getElementById('stage').append(element);
    const turned = await element.next();  // asked before the book exists
    const fromBook = [];
    element.book.addEventListener('turned', (event) => fromBook.push(event));
    await element.prev();
    const last = events.filter((e) => e.type === 'turned').at(-1);
    await element.book.whenIdle();  // the neighbours load after the first view (the failing page 1 among them)
    return {
      turned,
      types: events.map((event) => event.type),
      isCustom: events.every((event) => event instanceof CustomEvent && event.target === element),
      details: events.filter((e) => e.type !== 'progress').map((e) => [e.type, e.detail.error ? e.detail.error.message : e.detail]),
      lastProgress: events.filter((e) => e.type === 'progress').at(-1).detail,
      sameDetail: fromBook.length === 1 && last.type === 'turned' && last.detail === fromBook[0].detail,
    };
  });
  expect(result.turned).toBe(true);
  expect(result.isCustom).toBe(true);
  expect(result.types.filter((type) => type === 'progress').length).toBeGreaterThanOrEqual(4);
  expect(result.lastProgress).toEqual({ loaded: 4, total: 4, pending: 0 });
  // Page 1 is a neighbour of the first view (the cover alone): it loads, and fails, once the first view is drawn.
  const pageerrors = result.details.filter(([type]) => type === 'pageerror');
  expect(pageerrors.length).toBe(1);
  expect(pageerrors[0][1]).toContain('/no/such/page.png');
  expect(result.details.filter(([type]) => type !== 'pageerror')).toEqual([
    ['ready', { page: 0 }],
    ['turnstart', { direction: 'forward', page: 1 }],
    ['turned', { page: 1 }],
    ['turnstart', { direction: 'backward', page: 0 }],
    ['turned', { page: 0 }],
  ]);
  expect(result.sameDetail).toBe(true);  // the element passes on the Flipbook's detail object itself
});

test('browser: lighting, shadows, gutter and display attributes change the same live book; other attributes rebuild it at the current page', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 8 }, (_, i) => window.pageUrl(i)).join(' ');
    const element = window.makeElement({ pages, display: 'double', 'start-page': '1' });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const frameAt = () => { book.surface.showTurn('forward', 0.3); return Uint8Array.from(book.surface.readPixels().data); };
    const lit = frameAt();
    element.setAttribute('lighting', 'false');
    element.setAttribute('shadows', 'false');
    element.setAttribute('gutter', 'false');
    const flat = frameAt();
    element.removeAttribute('lighting');  // absent means the default, on
    element.removeAttribute('shadows');
    element.removeAttribute('gutter');
    const litAgain = frameAt();
    const changed = (a, b) => { let n = 0; for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 12) n++; return n / (a.length / 4); };
    element.setAttribute('display', 'single');
    const single = element.display;
    const live = { same: element.book === book, effectsOff: changed(lit, flat), effectsBack: changed(lit, litAgain), single };

    await element.flip(5, { animate: false });
    const rebuilt = new Promise((resolve) => element.addEventListener('ready', (e) => resolve(e.detail), { once: true }));
    element.setAttribute('direction', 'rtl');
    const detail = await rebuilt;
    return {
      live,
      rebuild: { detail, page: element.page, display: element.display, direction: element.book.options.direction, newBook: element.book !== book, oldDestroyed: book.surface === null, canvases: element.shadowRoot.querySelectorAll('canvas').length },
    };
  });
  expect(result.live.same).toBe(true);
  expect(result.live.effectsOff).toBeGreaterThan(0.05);  // shading and shadow touch well over 5% of the frame
  expect(result.live.effectsBack).toBe(0);
  expect(result.live.single).toBe('single');
  expect(result.rebuild).toEqual({ detail: { page: 5 }, page: 5, display: 'single', direction: 'rtl', newBook: true, oldDestroyed: true, canvases: 1 });
  expect(problems).toEqual([]);
});

test('browser: a bad attribute fires an error event with a TypeError naming the attribute, logs it, shows it, and the book builds once it is fixed', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const three = [0, 1, 2].map((i) => window.pageUrl(i)).join(' ');
    const cases = [
      [{ pages: three, duration: 'fast' }, ['duration', '300']],
      [{ pages: three, display: 'triple' }, ['display', 'auto']],
      [{ pages: three, 'start-page': '7' }, ['start-page', '2']],
      [{ pages: three, lighting: 'yes' }, ['lighting', 'false']],
      [{ pages: three, 'load-window': '0.5' }, ['load-window', '2']],
      [{ pages: three, direction: 'upwards' }, ['direction', 'vertical']],
      [{}, ['pages', three]],
    ];
    const out = [];
    for (const [attributes, [name, goodValue]] of cases) {
      const element = window.makeElement(attributes);
      const events = [];
      element.addEventListener('error', (event) => events.push(event.detail.error));
      document.getElementById('stage').append(element);
      const rejection = await element.whenReady().then(() => null, (error) => error);
      const panel = element.shadowRoot.querySelector('[part=error]');
      const shown = { visible: !panel.hidden && panel.getBoundingClientRect().height > 0, text: panel.textContent };
      element.setAttribute(name, goodValue);
      const fixed = await element.whenReady().then((book) => book === element.book, (error) => error.message);
      out.push({
        name,
        events: events.map((e) => `${e.name}: ${e.message}`),
        sameError: rejection === events[0],
        shown,
        fixed,
        panelHiddenAfterFix: panel.hidden,
      });
      element.remove();
    }
    // A bad value for a live attribute is reported and the book keeps its setting and keeps working.
    const element = window.makeElement({ pages: three });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const errors = [];
    element.addEventListener('error', (event) => errors.push(event.detail.error.message));
    element.setAttribute('shadows', 'maybe');
    const turned = await element.next();
    return { out, live: { errors, same: element.book === book, turned, shadows: book.options.shadows } };
  });
  for (const { name, events, sameError, shown, fixed, panelHiddenAfterFix } of result.out) {
    expect(events, `attribute ${name}`).toHaveLength(1);
    expect(events[0]).toMatch(/^TypeError: conecurl: <cone-flipbook> /);
    expect(events[0]).toContain(name === 'pages' ? "'pages' attribute" : `attribute '${name}'`);
    expect(sameError, `whenReady() rejects with the reported error (${name})`).toBe(true);
    expect(shown.visible).toBe(true);
    expect(shown.text).toContain(events[0].replace(/^TypeError: /, ''));
    expect(fixed, `fixing ${name} builds the book`).toBe(true);
    expect(panelHiddenAfterFix).toBe(true);
  }
  expect(result.live.errors).toHaveLength(1);
  expect(result.live.errors[0]).toContain("attribute 'shadows'");
  expect(result.live).toMatchObject({ same: true, turned: true, shadows: true });
  // Each error also went to the console.
  const logged = problems.filter((text) => text.includes('conecurl: <cone-flipbook>'));
  expect(logged).toHaveLength(result.out.length + 1);
});

test('browser: removing <cone-flipbook> destroys its book and releases its canvas; a move keeps the book; destroy() empties it; putting it back rebuilds', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const before = window.liveCanvases();
    const pages = Array.from({ length: 6 }, (_, i) => window.pageUrl(i)).join(' ');
    const element = window.makeElement({ pages, display: 'double' });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    await element.flip(3, { animate: false });
    const whileShown = window.liveCanvases();

    document.getElementById('elsewhere').append(element);  // a move: removed and inserted in one task
    // The element decides in a microtask after disconnectedCallback whether it was moved or removed:
    // a task later it has, on any machine.
    await new Promise((resolve) => setTimeout(resolve));
    const moved = { same: element.book === book, alive: book.surface !== null };

    element.remove();
    await new Promise((resolve) => setTimeout(resolve));  // as above: the removal is decided in a microtask
    const removed = {
      book: element.book,
      destroyed: book.surface === null,
      canvases: element.shadowRoot.querySelectorAll('canvas').length,
      live: window.liveCanvases(),
      next: await element.next().then(() => 'resolved', (error) => error.message),
    };

    document.getElementById('stage').append(element);
    const again = await element.whenReady();
    const back = { newBook: again !== book, page: element.page, live: window.liveCanvases() };

    element.destroy();
    const destroyed = {
      book: element.book,
      canvases: element.shadowRoot.querySelectorAll('canvas').length,
      live: window.liveCanvases(),
      next: await element.next().then(() => 'resolved', (error) => error.message),
    };

    // Removed while its book is still being built: the build stops (robustness.spec.js: no renderer is made).
    const early = window.makeElement({ pages });
    document.getElementById('stage').append(early);
    const waiting = early.whenReady().then(() => 'resolved', (error) => error.message);
    early.remove();
    const earlyResult = await waiting;
    return { before, whileShown, moved, removed, back, destroyed, earlyResult };
  });
  expect(result.whileShown).toBe(result.before + 1);
  expect(result.moved).toEqual({ same: true, alive: true });
  expect(result.removed.book).toBeNull();
  expect(result.removed.destroyed).toBe(true);
  expect(result.removed.canvases).toBe(0);
  expect(result.removed.live).toBe(result.before);
  expect(result.removed.next).toContain('in the document');
  expect(result.back).toEqual({ newBook: true, page: 3, live: result.before + 1 });
  expect(result.destroyed.book).toBeNull();
  expect(result.destroyed.canvases).toBe(0);
  expect(result.destroyed.live).toBe(result.before);
  expect(result.destroyed.next).toContain('destroyed');
  expect(result.earlyResult).toContain('removed from the document');
  await expect.poll(() => page.evaluate(() => window.liveCanvases())).toBe(result.before);
  expect(problems).toEqual([]);
});

test('browser: every option is a property too, as Svelte and Angular set them: pages as an array (over children), scalars written to their attributes, display live, a bad pages value named', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const element = document.createElement('cone-flipbook');
    element.append(Object.assign(document.createElement('img'), { src: window.pageUrl(5), alt: 'ignored: the pages property wins' }));
    element.pages = [window.pageUrl(0), { src: window.pageUrl(1), alt: 'One' }, window.pageUrl(2), window.pageUrl(3)];
    element.startPage = 2;
    element.display = 'double';  // a spread (640x400 is too narrow for 'auto' to choose one): page 2 opens pages 1-2
    element.lighting = false;
    element.duration = 300;
    element.setAttribute('autoplay', '60000');  // parsed as { interval }
    const attributes = ['start-page', 'lighting', 'duration'].map((name) => element.getAttribute(name));
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const built = { pageCount: book.pageCount, page: element.page, lighting: book.options.lighting, duration: book.options.duration,
      autoplay: book.options.autoplay,
      startPage: element.startPage, pages: element.pages.length };
    element.display = 'single';
    const live = { same: element.book === book, display: element.display, attribute: element.getAttribute('display') };
    const rebuilt = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    element.pages = [window.pageUrl(0), window.pageUrl(1)];
    await rebuilt;
    const after = { pageCount: element.book.pageCount, newBook: element.book !== book };
    const errors = [];
    element.addEventListener('error', (event) => errors.push(event.detail.error.message));
    element.pages = 42;
    return { attributes, built, live, after, errors };
  });
  expect(result.attributes).toEqual(['2', 'false', '300']);
  expect(result.built).toEqual({ pageCount: 4, page: 1, lighting: false, duration: 300, autoplay: { interval: 60000 }, startPage: 2, pages: 4 });
  expect(result.live).toEqual({ same: true, display: 'single', attribute: 'single' });
  expect(result.after).toEqual({ pageCount: 2, newBook: true });
  expect(result.errors).toHaveLength(1);
  expect(result.errors[0]).toMatch(/property 'pages' must be an array of pages or a string of URLs, got number/);
  expect(problems.filter((p) => !/property 'pages'/.test(p))).toEqual([]);
});

test('browser: turn-area, label and fallback are attributes too; every option property reads back what it was given (an autoplay object kept, not "[object Object]") and the book gets it', async ({ page }) => {
  const problems = await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const { PROPERTY_OPTIONS, propertyOf } = await import('/web/src/components/element-attributes.js');
    const pages = [0, 1, 2, 3].map((i) => window.pageUrl(i));
    const autoplay = { interval: 60000, loop: true };
    // A value for every option property (display reads the display shown: the live-attribute test has it).
    const values = {
      pages, minPageWidth: 150, direction: 'rtl', startPage: 2, duration: 300, schedule: 'smooth', center: false, hardCovers: true,
      lighting: false, shadows: false, gutter: false, showThrough: 0.25, thickness: 0.01, loadWindow: 2, hash: false, autoplay, sound: false,
      muted: true, rememberPage: 'element-spec', wasmUrl: '/dist/x.wasm', antialias: 'auto', resolution: 1.5, turnArea: 'corners',
      label: 'Atlas of clouds', fallback: false, pdf: new Uint8Array([37, 80, 68, 70]), pdfWorkerSrc: '/no/worker.mjs', document: '/files/atlas/book.json',
      outline: [{ title: 'Clouds', page: 1 }], download: '/files/atlas.pdf',
      edgeMarks: true,
      // viewer (issue 23): objects kept as given
      controls: { search: false }, labels: { next: 'Suivant' },
      textLayer: false,
      readAloudMemory: 'element-spec-voices',
    };
    const unsampled = PROPERTY_OPTIONS.filter((option) => option !== 'display' && !(option in values));
    const loose = document.createElement('cone-flipbook');  // not in the document: nothing is built
    // Each by its property's name (the `document` option is the `src` property: `document` would shadow the global).
    for (const [option, value] of Object.entries(values)) loose[propertyOf(option)] = value;
    const changed = Object.entries(values).filter(([option, value]) => !Object.is(loose[propertyOf(option)], value)).map(([option]) => option);
    const written = ['autoplay', 'turn-area', 'label', 'fallback', 'pages', 'pdf'].map((name) => loose.getAttribute(name));

    // The three new attributes reach the book.
    const byAttribute = window.makeElement({ pages: pages.join(' '), 'turn-area': 'edges', label: 'Atlas of rain', fallback: 'false' });
    document.getElementById('stage').append(byAttribute);
    const first = await byAttribute.whenReady();
    const fromAttributes = {
      turnArea: first.options.turnArea, label: first.options.label, fallback: first.options.fallback,
      name: first.element.getAttribute('aria-label'), read: [byAttribute.turnArea, byAttribute.label, byAttribute.fallback],
    };
    byAttribute.remove();

    // Properties, as a framework sets them: the autoplay object is the book's option as given.
    const element = document.createElement('cone-flipbook');
    Object.assign(element, { pages, autoplay, label: 'Atlas of clouds', turnArea: 'corners', fallback: false });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const fromProperties = {
      autoplay: book.options.autoplay, sameObject: element.autoplay === autoplay, attribute: element.getAttribute('autoplay'),
      turnArea: book.options.turnArea, label: book.options.label, name: book.element.getAttribute('aria-label'), fallback: book.options.fallback,
    };
    // A value an attribute holds replaces the one kept, and builds a new book with it; null removes it.
    const rebuilt = new Promise((resolve) => element.addEventListener('ready', resolve, { once: true }));
    element.autoplay = true;
    await rebuilt;
    const replaced = { attribute: element.getAttribute('autoplay'), read: element.autoplay, book: element.book.options.autoplay, newBook: element.book !== book };
    element.autoplay = null;
    const removed = { attribute: element.getAttribute('autoplay'), read: element.autoplay };
    // A value no attribute holds is named, not written as "[object Object]".
    const errors = [];
    element.addEventListener('error', (event) => errors.push(event.detail.error.message));
    element.duration = { ms: 300 };
    return { unsampled, changed, written, fromAttributes, fromProperties, replaced, removed, errors, durationAttribute: element.getAttribute('duration') };
  });
  expect(result.unsampled).toEqual([]);
  expect(result.changed).toEqual([]);
  expect(result.written).toEqual([null, 'corners', 'Atlas of clouds', 'false', null, null]);
  expect(result.fromAttributes).toEqual({ turnArea: 'edges', label: 'Atlas of rain', fallback: false, name: 'Atlas of rain', read: ['edges', 'Atlas of rain', false] });
  expect(result.fromProperties).toEqual({
    autoplay: { interval: 60000, loop: true }, sameObject: true, attribute: null,
    turnArea: 'corners', label: 'Atlas of clouds', name: 'Atlas of clouds', fallback: false,
  });
  expect(result.replaced).toEqual({ attribute: 'true', read: true, book: true, newBook: true });
  expect(result.removed).toEqual({ attribute: null, read: undefined });
  expect(result.errors).toHaveLength(1);
  expect(result.errors[0]).toMatch(/property 'duration' must be a string, number or boolean .*got an object/);
  expect(result.durationAttribute).toBeNull();
  expect(problems.filter((p) => !/property 'duration'/.test(p))).toEqual([]);
});

test('browser: fallback="false" without WebGL2: the element reports the failure and shows no still pages (by default it does)', async ({ page }) => {
  await withoutWebGL2(page);
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const pages = [0, 1, 2].map((i) => window.pageUrl(i)).join(' ');
    const out = {};
    for (const fallback of ['true', 'false']) {
      const element = window.makeElement({ pages, fallback });
      document.getElementById('stage').append(element);
      const outcome = await element.whenReady().then((book) => book.surface.kind, (error) => error.code);
      out[fallback] = { outcome, book: element.book ? element.book.constructor.name : null };
      element.remove();
    }
    return out;
  });
  expect(result).toEqual({ true: { outcome: 'canvas', book: 'StaticBook' }, false: { outcome: 'webgl2-unavailable', book: null } });
});

test('browser: every event a <cone-flipbook> dispatches has the detail fields book-events.js lists (as flipbook.d.ts types them); a far flip() riffles, one turnstart with riffle: true', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const { EVENT_DETAILS } = await import('/web/src/book/book-events.js');
    const pages = Array.from({ length: 12 }, (_, i) => window.pageUrl(i));
    pages[5] = '/no/such/page.png';  // a pageerror
    const element = window.makeElement({ pages: pages.join(' '), display: 'double', duration: '200' });
    const seen = [];
    for (const type of Object.keys(EVENT_DETAILS)) element.addEventListener(type, (event) => seen.push([type, event.detail]));
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    await element.next();
    const before = seen.length;
    await element.flip(10);  // from the spread of pages 1-2 to that of 9-10: four leaves
    const landedAt = element.page;
    const far = seen.slice(before).filter(([type]) => type === 'turnstart' || type === 'turned')
      .map(([type, detail]) => (type === 'turnstart' ? [type, detail.direction, detail.riffle] : [type, detail.page]));
    book.zoom = 2;
    book.zoom = 1;
    const resized = new Promise((resolve) => element.addEventListener('resize', resolve, { once: true }));
    element.style.width = '600px';
    await resized;
    await element.insertPages(12, [window.pageUrl(0)]);
    element.setAttribute('shadows', 'maybe');  // refused live: an error event
    await book.whenIdle();  // page 5's load has failed by now (it lies within the load window since next())
    // Read aloud, the open page given an alt to say, with an engine that begins its sentence and says its
    // first word at once: start, page, sentence, word, pause, resume, end.
    await element.replacePage(book.openPages[0], { src: window.pageUrl(0), alt: 'Hello there' });
    const engine = { speak: (text, { onSentence, onWord }) => { onSentence(0, text.length); onWord(0, text.length); return { pause() {}, resume() {}, cancel() {} }; } };
    const saying = new Promise((resolve) => element.addEventListener('readaloudword', resolve, { once: true }));
    const reading = await book.readAloud({ engine });
    await saying;
    reading.pause();
    reading.resume();
    reading.stop();
    const fieldsOf = (detail) => Object.keys(detail).filter((key) => detail[key] !== undefined).sort();
    const wrong = seen.filter(([type, detail]) => {
      const listed = EVENT_DETAILS[type];
      const fields = fieldsOf(detail);
      return fields.some((field) => !listed.includes(field) && !listed.includes(`${field}?`))
        || listed.some((field) => !field.endsWith('?') && !fields.includes(field));
    }).map(([type, detail]) => `${type}: ${fieldsOf(detail).join(', ')}`);
    return { types: [...new Set(seen.map(([type]) => type))].sort(), wrong, far, landedAt };
  });
  expect(result.wrong).toEqual([]);
  expect(result.types).toEqual(expect.arrayContaining(['ready', 'progress', 'pageerror', 'turnstart', 'turned', 'zoom', 'resize', 'pageschange', 'error',
    'readaloudstart', 'readaloudpage', 'readaloudsentence', 'readaloudword', 'readaloudpause', 'readaloudresume', 'readaloudend']));
  expect(result.landedAt).toBe(9);  // the spread's first page
  expect(result.far).toEqual([['turnstart', 'forward', true], ['turned', 9]]);
});

test('browser: a published book is the src attribute and property (not document), so an inline handler on the element that reads document.title gets the global document', async ({ page }) => {
  await openReady(page, FIXTURE);
  const result = await page.evaluate(async () => {
    const holder = document.createElement('div');
    holder.innerHTML = '<cone-flipbook src="/no/such/book.json" onclick="document.title = \'set by the handler\'; this.dataset.seen = typeof document.createElement"></cone-flipbook>';
    const element = holder.firstElementChild;
    const upgraded = element instanceof customElements.get('cone-flipbook');
    const before = document.title;
    element.click();  // not in the page: nothing is built, the handler runs
    const seen = { title: document.title, createElement: element.dataset.seen, hasDocument: 'document' in element, src: element.src };
    document.title = before;
    // The src attribute is the book's document option: its build reads that file (and fails on it, naming it).
    document.getElementById('stage').append(element);
    const failure = await element.whenReady().then(() => 'built', (error) => String(error.message));
    element.remove();
    return { upgraded, ...seen, failure };
  });
  expect(result.upgraded).toBe(true);
  expect(result.title).toBe('set by the handler');
  expect(result.createElement).toBe('function');
  expect(result.hasDocument).toBe(false);
  expect(result.src).toBe('/no/such/book.json');
  expect(result.failure).toMatch(/\/no\/such\/book\.json/);
});
