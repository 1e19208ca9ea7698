// A TypeScript consumer of conecurl/react and conecurl/vue from the packed package: it must typecheck
// under --strict (tests/node/package.test.mjs runs tsc on it, with React's and Vue's types).
import { createElement, useRef } from 'react';
import { Flipbook, useFlipbook, type FlipbookHandle, type FlipbookProps } from 'conecurl/react';
import { h } from 'vue';
import VueFlipbook, { type FlipbookHandle as VueHandle } from 'conecurl/vue';

export function ReactBook() {
  const flipbook = useFlipbook();
  const handle = useRef<FlipbookHandle>(null);
  const props: FlipbookProps = {
    pages: ['a.jpg', { src: 'b.jpg', alt: 'B' }], display: 'double', lighting: false, page: flipbook.page,
    onPageChange: (page: number) => console.log(page.toFixed(0)),
    onTurned: (event) => console.log(event.detail.page.toFixed(0)),
    onPagesChange: (event) => console.log(event.detail.change, event.detail.pageCount.toFixed(0)),
    onPageError: (event) => console.log(event.detail.reason),
  };
  void handle.current?.next().then((turned: boolean) => turned);
  const ready: boolean = flipbook.ready;
  return createElement('div', null, createElement(Flipbook, { ...props, ref: flipbook.ref }),
    createElement('button', { onClick: () => void flipbook.next(), disabled: !ready }, 'Next'));
}

export function vueBook(onTurned: (page: number) => void) {
  const exposed: VueHandle | null = null;
  void exposed;
  return h(VueFlipbook, { pages: ['a.jpg'], display: 'single', page: 0, onTurned: (event: CustomEvent<{ page: number }>) => onTurned(event.detail.page) });
}
