// Runs inside the benchmark page: loads one library's bundle, mounts the book with the generated
// pages, and exposes window.bench for the runner (first frame, turns with rAF sampling, stats).
// Query: ?lib=conecurl|page-flip|turnjs|floor-webgl|floor-2d|conecurl-baseline&pages=N&display=single|double&duration=ms&bundles=URL&images=URL
// [&options=JSON] [&instrument=startup] (startup-instrument.js run before the library loads: startup.mjs in Firefox and WebKit)
const params = new URLSearchParams(location.search);
const required = (name) => {
  const value = params.get(name);
  if (!value) throw new Error(`bench harness: query parameter '${name}' is missing`);
  return value;
};
const lib = required('lib');
const pageCount = Number(required('pages'));
const display = required('display');
const duration = Number(required('duration'));
const bundles = required('bundles');
const images = required('images');
// Extra options for the library under test (JSON), for profiling runs: e.g. {"shadows":false}.
const extra = JSON.parse(params.get('options') || '{}');

// The runner waits for image loading to settle by counting resource entries; the default buffer
// (250 entries) would stop counting long before a 1000-page book has loaded.
performance.setResourceTimingBufferSize(100000);

const nextFrame = () => new Promise((resolve) => requestAnimationFrame(resolve));
const urls = Array.from({ length: pageCount }, (_, i) => `${images}/page-${String(i + 1).padStart(4, '0')}.png`);

// rAF timestamps while sampling; the runner stops the sampler before it measures idle CPU.
let sampling = false;
let stamps = [];
function sample(now) {
  if (!sampling) return;
  stamps.push(now);
  requestAnimationFrame(sample);
}

async function main() {
  if (!['single', 'double'].includes(display)) throw new Error(`bench harness: display must be single or double, got ${display}`);
  if (params.get('instrument') === 'startup') await import('./startup-instrument.js');
  const { mount } = await import(`${bundles}/${lib}.js`);
  const book = await mount(document.getElementById('book'), { urls, display, duration, extra });
  const readyMs = performance.now();
  await nextFrame();  // the library draws the shown pages in this frame (all three draw on rAF)
  await nextFrame();  // ...and this one has them on screen
  const firstFrameMs = performance.now();
  return {
    book,
    readyMs,
    firstFrameMs,
  };
}

const started = main();
window.bench = {
  /** { readyMs, firstFrameMs } since navigation start, or throws what went wrong. */
  async ready() {
    const { readyMs, firstFrameMs } = await started;
    return { readyMs, firstFrameMs };
  },
  /**
   * Turns `count` times forward, one after another, sampling every animation frame. Returns the rAF
   * timestamps, when each turn started and landed (ms since navigation start), and stats() after each.
   */
  async turns(count, timeoutMs) {
    const { book } = await started;
    stamps = [];
    sampling = true;
    requestAnimationFrame(sample);
    const turns = [];
    const turnStats = [];  // library figures after each turn (conecurl: resident page textures)
    try {
      for (let i = 0; i < count; i++) {
        const start = performance.now();
        let timer;
        const timeout = new Promise((_, reject) => {
          timer = setTimeout(() => reject(new Error(`${lib}: turn ${i + 1} did not land within ${timeoutMs} ms`)), timeoutMs);
        });
        await Promise.race([book.turn(), timeout]).finally(() => clearTimeout(timer));
        turns.push({ start, end: performance.now() });
        if (book.stats) turnStats.push(book.stats());
      }
      await nextFrame();
    } finally {
      sampling = false;
    }
    return { stamps, turns, turnStats };
  },
  /** The mounted adapter ({ turn, stats, view? }), for profiling scripts that evaluate in the page. */
  async mounted() {
    return (await started).book;
  },
  /**
   * What the page draws into: the device pixel ratio and every canvas on screen with its drawing buffer
   * (px) and CSS size, so the report can say which library draws at the device's ratio (none: a DOM book);
   * for conecurl, the device px per CSS px its frames with a moving leaf were drawn at last (movingRatio).
   */
  async drawing() {
    const canvases = [...document.querySelectorAll('canvas')].filter((canvas) => canvas.clientWidth > 0 && canvas.clientHeight > 0)
      .map((canvas) => ({ width: canvas.width, height: canvas.height, cssWidth: canvas.clientWidth, cssHeight: canvas.clientHeight }));
    const { book } = await started;
    return { devicePixelRatio: window.devicePixelRatio, canvases, movingRatio: book.movingRatio?.() };
  },
  /** Library-specific figures (conecurl: wasm heap, resident page textures). */
  async stats() {
    const { book } = await started;
    return book.stats ? book.stats() : {};
  },
};
