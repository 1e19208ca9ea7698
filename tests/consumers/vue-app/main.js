// The app: <Flipbook> with v-model:page and a display prop, its exposed next() behind a button, and a
// book whose default slot holds its pages (an <img> and an HTML section); window.app drives it.
import { createApp, h, ref } from 'vue';
import { Flipbook } from 'conecurl/vue';

const pages = Array.from({ length: 6 }, (_, i) => `pages/page-${i}.svg`);
const events = [];
window.events = events;

const App = {
  setup() {
    const page = ref(2);
    const display = ref('double');
    const book = ref(null);
    const bookPages = ref(pages);
    window.app = { page, display, book, pages: bookPages };
    return () => h('div', null, [
      h('div', { id: 'controls' }, [
        h('button', { id: 'next', onClick: () => book.value.next() }, 'Next'),
        h('output', { id: 'page' }, `page ${page.value + 1}`),
      ]),
      h(Flipbook, {
        ref: book, id: 'book', pages: bookPages.value, display: display.value, page: page.value, style: { width: '640px', height: '400px', aspectRatio: 'auto' },
        'onUpdate:page': (value) => { page.value = value; },
        onReady: (event) => { events.push(['ready', event.detail]); document.body.dataset.ready = 'true'; },
        onTurned: (event) => events.push(['turned', event.detail]),
        onPageschange: (event) => events.push(['pageschange', event.detail]),
        onError: (event) => { document.body.dataset.error = event.detail.error.message; },
      }),
      h(Flipbook, { id: 'children-book', display: 'double', style: { width: '640px', height: '400px', aspectRatio: 'auto' } }, {
        default: () => [
          h('img', { src: 'pages/page-0.svg', alt: 'Cover' }),
          h('section', { id: 'html-page', style: { background: 'rgb(30, 160, 90)', height: '100%' } }, [h('h2', 'An HTML page')]),
          h('img', { src: 'pages/page-2.svg', alt: 'Two' }),
        ],
      }),
    ]);
  },
};
createApp(App).mount('#root');
