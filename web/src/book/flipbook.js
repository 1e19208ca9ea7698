// The public entry point: a flipbook in a container element. Flipbook is the book controller
// (book-controller.js) over the WebGL surface, BookView on the wasm engine, sharing the page's WebGL
// contexts with other books; without WebGL2 or the engine, create() leaves a StaticBook in its place.
import { idleAfterFirstFrame, whenIdle, whenIdleAfter } from '../surfaces/after-first-frame.js';
import { loadEngine } from '../engine/load-engine.js';
import { BookView } from '../surfaces/book-view.js';
import { leafThicknessOf } from '../engine/layout.js';
import { BookController } from './book-controller.js';
import { DOCUMENT_OPTIONS, describeValue, hardPageIndices, validateOptions } from './options.js';
import { contextBudget } from '../surfaces/context-budget.js';
import { knownSoftwareWebGL, probeWebGL } from '../surfaces/software-gl.js';

// Failures after which a book can still be shown, as still pages: Flipbook.create falls back on these.
const FALLBACK_CODES = ['webgl2-unavailable', 'engine-unavailable'];
const PREPARE_RETRY_MS = 250;  // how soon prepareTurn() is asked again while a leaf moves

// The book's document in place of `pages`: `pdf` (a URL, ArrayBuffer or Uint8Array; pdf.js is imported
// only then) or `document` (a published document's book.json URL: conecurl publish wrote it).
async function openDocumentOption(options) {
  if (options === null || typeof options !== 'object') return null;
  if ('document' in options) {
    const { document: url } = options;
    if (!(typeof url === 'string' && url.trim() !== '') && !(url instanceof URL)) {
      throw new TypeError(`conecurl: option 'document' must be the URL of a published document's book.json, got ${describeValue(url)}`);
    }
    for (const other of ['pages', 'pdf', 'pdfWorkerSrc']) {
      if (other in options) throw new TypeError(`conecurl: option '${other}' cannot be given with 'document' (the document's pages are the book)`);
    }
    const { openPublished } = await import('../document/published-document.js');
    return openPublished(String(url));
  }
  if (!('pdf' in options)) return null;
  const { pdf, pdfWorkerSrc } = options;
  if (!(typeof pdf === 'string' || pdf instanceof ArrayBuffer || pdf instanceof Uint8Array)) {
    throw new TypeError(`conecurl: option 'pdf' must be a URL string, an ArrayBuffer or a Uint8Array, got ${describeValue(pdf)}`);
  }
  if ('pages' in options) throw new TypeError("conecurl: option 'pages' cannot be given with 'pdf' (the PDF's pages are the book)");
  if (pdfWorkerSrc !== undefined && typeof pdfWorkerSrc !== 'string') {
    throw new TypeError(`conecurl: option 'pdfWorkerSrc' must be a URL string, got ${describeValue(pdfWorkerSrc)}`);
  }
  const { openPdf } = await import('../document/pdf-pages.js');
  return openPdf(pdf, { workerSrc: pdfWorkerSrc });
}

// The options of a book over a document: its pages in place of the option that named it; its title is
// the book's label unless one was given.
function documentOptions(options, doc) {
  const rest = { ...options, pages: doc.pages };
  for (const name of DOCUMENT_OPTIONS) delete rest[name];
  if (doc.title && rest.label === undefined) rest.label = doc.title;
  return rest;
}

export class Flipbook extends BookController {
  /** @param {HTMLElement} container @param {object} options  See flipbook.d.ts. */
  static async create(container, options) {
    if (!(container instanceof HTMLElement)) throw new TypeError('conecurl: container must be an HTMLElement');
    // The engine (the page's one, unless the book names its own .wasm) loads while a document opens.
    if (!options?.wasmUrl) loadEngine().catch(() => {});  // a failure is met where _open awaits it
    const doc = await openDocumentOption(options);
    let settings;
    try {
      settings = validateOptions(doc ? documentOptions(options, doc) : options, { document: Boolean(doc) });
    } catch (error) {
      doc?.destroy();
      throw error;
    }
    if (doc) settings.pageAspect = doc.aspect;  // page shape from the document's first page
    return new this(container, settings, doc)._open();  // `this`: subclasses get their own instances
  }

  // Loads the engine and builds the first view (BookController's _build and _events, reached through
  // `this`, as a subclass does); resolves with the book once its first view is drawn. The engine
  // loads while the first view's pages are asked for and its context is made: _makeSurface waits for it.
  async _open() {
    try {
      this._engine = loadEngine(this._settings.wasmUrl ? { wasmUrl: this._settings.wasmUrl } : {});
      this._engine.catch(() => {});  // a failure is thrown where it is awaited
      await this._build();
    } catch (error) {
      this._stopIfDestroyed();  // destroyed while it was built: an AbortError, no fallback put in its place
      throw await this._fail(error);
    }
    this._events.releaseSoon();  // what happened while loading the first view is heard from now on
    // The first view is shown with the programs it draws (BookRenderer links each on first use): the
    // ones a turn draws are linked when the page is next idle once the first frame is on screen, so neither
    // the first page nor the first turn waits.
    // While a leaf moves it is asked again a little later (the renderer's page-wide checks wait for rest),
    // not at each idle moment between the turn's frames.
    const prepare = () => {
      if (this._surface?.prepareTurn?.() !== false) return;
      this._defer(this._surface.moving ? (task) => whenIdleAfter(PREPARE_RETRY_MS, task) : whenIdle, prepare);
    };
    this._defer(idleAfterFirstFrame, prepare);
    return this;
  }

  constructor(container, settings, doc = null) {
    super(container, settings, doc);
    this._contextLease = contextBudget().lease(this._canvas);  // many books on a page share the WebGL contexts
  }

  destroy() {
    if (this._destroyed) return;
    if (!this._surface) this._probed?.getExtension('WEBGL_lose_context')?.loseContext();  // no renderer came to take it
    super.destroy();
    this._contextLease.dispose();
  }

  // create() failed. Without WebGL2 or the engine the pages can still be shown: unless the option
  // `fallback` is false, a StaticBook takes the book's place in the container (error.fallback).
  // Then `error` is dispatched (subclasses such as <cone-flipbook> hear it) and create rejects.
  async _fail(error) {
    const canFallBack = this._settings.fallback && FALLBACK_CODES.includes(error && error.code);
    const doc = canFallBack ? this._document : null;
    if (canFallBack) this._document = null;  // the fallback shows the same document
    this.destroy();
    if (canFallBack) {
      try {
        // Loaded only now: books that have WebGL2 never download the fallback.
        const { openStaticBook } = await import('./static-book.js');
        error.fallback = await openStaticBook(this._container, this._settings, doc);
      } catch (fallbackError) {
        doc?.destroy();
        error.fallbackError = fallbackError;
      }
    }
    this.dispatchEvent(new CustomEvent('error', { detail: { error } }));
    return error;
  }

  // Room in the page's context budget, then the canvas's context. antialias 'auto' (smooth edges unless WebGL
  // runs in software, where multisampling costs ~30% a frame) is found out by the page's first book, on its own
  // canvas with the context it keeps on a GPU (software-gl.js); in software that context is multisampled, so
  // the book takes a fresh canvas, whose context the renderer makes, and loses the probe's first. At once:
  // nothing is queued on it yet, so that takes a few ms, where losing it later waits on all the GPU process
  // has queued by then (100 ms to over a second in software, docs/benchmark.md). A known verdict (or true,
  // false) needs no probe.
  _prepareCanvas() {
    this._contextLease.admit();
    if (this._settings.antialias !== 'auto' || knownSoftwareWebGL() !== null) return;
    this._probed = probeWebGL(this._canvas);  // on a GPU, the renderer's context to be
    if (!knownSoftwareWebGL()) return;
    this._probed.getExtension('WEBGL_lose_context')?.loseContext();
    this._probed = null;
    this._contextLease.dispose();
    this._replaceCanvas();
    this._contextLease = contextBudget().lease(this._canvas);
    this._contextLease.admit();
  }

  // The engine draws the stacks' edge bands, and centres a closed book on its page and its band (layout.js centerShift).
  _stackShape() {
    return { leafThickness: leafThicknessOf(this._settings.thickness), hardPages: hardPageIndices(this._pages, this._settings.hardCovers) };
  }

  async _makeSurface(display) {
    const engine = await this._engine;
    this._stopIfDestroyed();  // destroyed while the engine loaded: no renderer, no context
    const settings = this._settings;
    const hardPages = hardPageIndices(this._pages, settings.hardCovers);
    const view = new BookView(engine, this._canvas, {
      pageCount: this.pageCount,
      // A PDF's pages keep their shape; image books use the engine's default page.
      ...(settings.pageAspect ? { pageWidth: settings.pageAspect, pageHeight: 1 } : {}),
      display,
      direction: settings.direction,
      hardPages,
      turnSeconds: settings.duration / 1000,
      schedule: settings.schedule,
      center: settings.center,
      antialias: settings.antialias === 'auto' ? !knownSoftwareWebGL() : settings.antialias,  // see _prepareCanvas
      lighting: settings.lighting,
      shadows: settings.shadows,
      gutter: settings.gutter,
      showThrough: settings.showThrough,
      thickness: settings.thickness,
      resolution: settings.resolution,
    });
    this._contextLease.attach(view);
    return view;
  }
}
