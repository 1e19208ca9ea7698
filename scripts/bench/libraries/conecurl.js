// Benchmark adapter for conecurl: mounts a Flipbook through its public API and turns with next().
// Bundled (minified) by scripts/bench/bundle.mjs; the wasm is served next to the bundle.
import { Flipbook } from '../../../web/src/book/flipbook.js';
import { loadEngine } from '../../../web/src/engine.js';

export async function mount(container, { urls, display, duration, extra = {} }) {
  const book = await Flipbook.create(container, { pages: urls, display, duration, ...extra });
  const engine = await loadEngine();  // the module every book on the page shares: its memory
  const memory = Object.values(engine.asm).find((value) => value instanceof WebAssembly.Memory);
  return {
    /** The BookView drawing the book (its public `surface`), for scripts/bench/profile-gpu.mjs. */
    view: () => book.surface,
    async turn() {
      if (!(await book.next())) throw new Error(`conecurl: could not turn forward from page ${book.page}`);
    },
    /** Device px per CSS px the frames with a moving leaf are drawn at now (`resolution: 'auto'` adapts it). */
    movingRatio: () => (book.surface?.movingScale ?? 1) * window.devicePixelRatio,
    stats() {
      return { wasmHeapBytes: memory.buffer.byteLength, pageTextures: book.residentPages.length, page: book.page };
    },
  };
}
