// The app: a controlled <Flipbook> with controls elsewhere (useFlipbook), a book whose children are its
// pages (an <img> and an HTML section), all under StrictMode; window.app lets the test drive it.
import { StrictMode, createElement as h, useState } from 'react';
import { createRoot } from 'react-dom/client';
import { Flipbook, useFlipbook } from 'conecurl/react';

const pages = Array.from({ length: 6 }, (_, i) => `pages/page-${i}.svg`);
const events = [];
window.events = events;

function App() {
  const [display, setDisplay] = useState('double');
  const [page, setPage] = useState(2);
  const [lighting, setLighting] = useState(true);
  const [bookPages, setPages] = useState(pages);
  const flipbook = useFlipbook();
  window.app = { setDisplay, setPage, setLighting, setPages, pages, flipbook, page, display };
  return h('div', null,
    h('div', { id: 'controls' },
      h('button', { id: 'prev', onClick: () => flipbook.prev() }, 'Previous'),
      h('output', { id: 'page' }, flipbook.ready ? `page ${flipbook.page + 1} of ${flipbook.pageCount}` : 'loading'),
      h('button', { id: 'next', onClick: () => flipbook.next() }, 'Next')),
    h(Flipbook, {
      ref: flipbook.ref, id: 'book', pages: bookPages, display, lighting, page, style: { width: 640, height: 400, aspectRatio: 'auto' },
      onPageChange: setPage,
      onReady: (event) => { events.push(['ready', event.detail]); document.body.dataset.ready = 'true'; },
      onTurned: (event) => events.push(['turned', event.detail]),
      onPagesChange: (event) => events.push(['pageschange', event.detail]),
      onError: (event) => { document.body.dataset.error = event.detail.error.message; },
    }),
    h(Flipbook, {
      id: 'bad-book', pages, duration: -5, style: { width: 200, height: 125, aspectRatio: 'auto' },
      onError: (event) => { window.badBookError = event.detail.error.message; },
    }),
    h(Flipbook, { id: 'children-book', display: 'double', style: { width: 640, height: 400, aspectRatio: 'auto' } },
      h('img', { src: 'pages/page-0.svg', alt: 'Cover' }),
      h('section', { id: 'html-page', style: { background: 'rgb(30, 160, 90)', height: '100%' } }, h('h2', null, 'An HTML page')),
      h('img', { src: 'pages/page-2.svg', alt: 'Two' })));
}

const root = createRoot(document.getElementById('root'));
root.render(h(StrictMode, null, h(App)));

// Mounts and unmounts a StrictMode book `count` times in a box of its own (the leak test).
window.cycle = async (count) => {
  const box = document.body.appendChild(document.createElement('div'));
  for (let i = 0; i < count; i++) {
    const cycleRoot = createRoot(box);
    await new Promise((resolve) => {
      cycleRoot.render(h(StrictMode, null, h(Flipbook, { pages: pages.slice(0, 2), style: { width: 200, height: 125 }, onReady: resolve })));
    });
    cycleRoot.unmount();
  }
  box.remove();
};
