// Benchmark adapter for conecurl: mounts a Flipbook through its public API and turns with next().
// Bundled (minified) by scripts/bench/bundle.mjs; the wasm is served next to the bundle.
import { Flipbook } from '../../../web/src/flipbook.js';

export async function mount(container, { urls, display, duration, extra = {} }) {
  const book = await Flipbook.create(container, { pages: urls, display, duration, ...extra });
  return {
    /** The BookView underneath (internal), for scripts/bench/profile-gpu.mjs. */
    view: () => book._view,
    async turn() {
      if (!(await book.next())) throw new Error(`conecurl: could not turn forward from page ${book.page}`);
    },
    stats() {
      // Internals read for the benchmark only (no public accessor yet): BookView's renderer and the
      // Emscripten module's memory.
      const view = book._view;
      return {
        wasmHeapBytes: view.engine.HEAP8.length,
        pageTextures: view.renderer.residentPageImages(),
        page: book.page,
      };
    },
  };
}
