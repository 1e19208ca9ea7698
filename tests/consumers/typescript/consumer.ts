// A TypeScript consumer of the packed package: it must typecheck under --strict, with the types
// found through the package's `exports` (tests/node/package.test.mjs runs tsc on it).
import {
  Flipbook, StaticBook, PageLoadError, BookView, loadEngine,
  type FlipbookOptions, type FlipbookCreateError, type ConeCurlEngine,
} from 'conecurl';
import { ConeFlipbookElement } from 'conecurl/element';
import { loadEngine as loadEngineDirectly } from 'conecurl/engine';
import { attachControls, CONTROL_PARTS, DEFAULT_LABELS, type Controls } from 'conecurl/viewer';

export async function openBook(container: HTMLElement): Promise<number> {
  const options: FlipbookOptions = {
    pages: ['cover.jpg', { src: 'p1.jpg', alt: 'Page one', hard: false }],
    display: 'auto', direction: 'rtl', startPage: 0, duration: 800, lighting: false,
  };
  const book: Flipbook = await Flipbook.create(container, options);
  book.addEventListener('turned', (event) => console.log(event.detail.page.toFixed(0)));
  book.setOptions({ shadows: false });
  const turned: boolean = await book.next();
  await book.flip(1, { animate: false });
  book.addEventListener('pageschange', (event) => console.log(event.detail.change, event.detail.page.toFixed(0)));
  const inserted = await book.insertPages(1, ['new.jpg', { src: 'p2.jpg', alt: 'Page two' }]);
  await book.removePages(inserted.at, inserted.count);
  await book.replacePage(0, 'cover-2.jpg');
  // @ts-expect-error: pages go in as an array
  await book.insertPages(0, 'one.jpg');
  book.destroy();
  // @ts-expect-error: 'triple' is not a display mode
  await Flipbook.create(container, { pages: ['a.jpg'], display: 'triple' });
  // @ts-expect-error: only the effects change on a live book
  book.setOptions({ duration: 10 });
  return turned ? book.page : book.pageCount;
}

// Without WebGL2 create() rejects; the error's fallback is a StaticBook with the same members.
export async function openWithFallback(container: HTMLElement): Promise<number> {
  try {
    const book = await Flipbook.create(container, { pages: ['a.jpg', 'b.jpg'], fallback: true });
    book.addEventListener('pageerror', (event) => {
      if (event.detail.reason === 'http' && event.detail.error instanceof PageLoadError) console.warn(event.detail.error.status);
    });
    return book.page;
  } catch (error) {
    const fallback: StaticBook | undefined = (error as FlipbookCreateError).fallback;
    if (!fallback) throw error;
    await fallback.next();
    // @ts-expect-error: 'sideways' is no reason a page fails
    const reason: import('conecurl').PageErrorReason = 'sideways';
    return reason ? fallback.page : (await StaticBook.create(container, { pages: ['a.jpg'] })).pageCount;
  }
}

export async function useElement(): Promise<string | null> {
  const element = document.querySelector('cone-flipbook');  // typed through HTMLElementTagNameMap
  if (!element) return null;
  const same: ConeFlipbookElement = element;
  same.addEventListener('turnstart', (event) => console.log(event.detail.direction, event.detail.page, event.detail.riffle === true));
  same.addEventListener('error', (event) => console.error(event.detail.error.message));
  same.addEventListener('progress', (event) => console.log(event.detail.loaded / event.detail.total));
  const created = document.createElement('cone-flipbook');
  created.setAttribute('pages', 'a.jpg b.jpg');
  document.body.append(created);
  const book: Flipbook = await created.whenReady();
  await created.next();
  await created.flip(1);
  // @ts-expect-error: page is read-only
  created.page = 3;
  created.pages = ['a.jpg', { src: 'b.jpg', alt: 'B' }];  // options as properties (Svelte, Angular)
  created.display = 'auto';
  created.lighting = false;
  created.startPage = 1;
  created.autoplay = { interval: 3000 };  // kept as given: it reads back the same object
  const interval: number | undefined = typeof created.autoplay === 'object' ? created.autoplay.interval : undefined;
  created.label = 'Atlas of clouds';
  created.turnArea = interval ? 'edges' : 'page';
  created.fallback = false;
  // @ts-expect-error: turnArea is one of four
  created.turnArea = 'anywhere';
  // @ts-expect-error: direction is one of three
  created.direction = 'diagonal';
  created.destroy();
  return book.pageCount > 0 ? element.display : null;
}

export async function useEngine(canvas: HTMLCanvasElement): Promise<number> {
  const engine: ConeCurlEngine = await loadEngine({ wasmUrl: '/assets/conecurl-engine.wasm' });
  const same: ConeCurlEngine = await loadEngineDirectly();
  const view = await BookView.create(canvas, { engine, pageCount: 4, display: 'single' });
  view.destroy();
  return engine.curlAt(0.3).theta + same.curlAt(0.1).rho;
}

// conecurl/viewer: the toolbar on a book you made, its parts and labels typed.
export async function withControls(container: HTMLElement): Promise<number> {
  const book = await Flipbook.create(container, { pages: ['a.jpg', 'b.jpg'], controls: { search: false }, labels: { next: 'Suivant' } });
  const controls: Controls = attachControls(book, { controls: { print: false }, labels: { pageOf: '{n} / {total}' }, pdf: false });
  const toolbar: HTMLElement = controls.toolbar;
  controls.remove();
  // @ts-expect-error: 'share' is no part of the toolbar
  attachControls(book, { controls: { share: false } });
  // @ts-expect-error: labels are strings
  attachControls(book, { labels: { next: 3 } });
  return toolbar.childElementCount + CONTROL_PARTS.length + DEFAULT_LABELS.next.length;
}
