// Node: every entry of the package imports on a server, and the React and Vue components render there,
// touching no window, document, customElements or WebAssembly (each is a getter that throws, in a
// child process of its own); the framework components' prop tables come from the book's options and events.
import test from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { BOOK_EVENTS } from '../../web/src/book/book-events.js';
import { DEFAULTS, LIVE_OPTIONS, OPTION_NAMES } from '../../web/src/book/options.js';
import { EVENT_HANDLERS, FIXED_PROPS, OPTION_PROPS, fixedOptionsDiffer, pageChanges, samePages } from '../../web/src/components/framework-props.js';

const root = fileURLToPath(new URL('../../', import.meta.url));

// Runs `body` (an ES module's text) in a fresh Node where the DOM and WebAssembly globals are absent
// (undefined) and every read of one is recorded with its stack; prints { out, reads } where `reads`
// lists the globals read from the package's own files (a framework's own `typeof window` does not count).
function onServer(body) {
  const traps = `
    const reads = [];
    for (const name of ['window', 'document', 'customElements', 'WebAssembly', 'HTMLElement', 'navigator']) {
      Object.defineProperty(globalThis, name, { configurable: true, get() {
        const caller = new Error().stack.split('\\n').slice(2).find((line) => !line.includes('node:internal')) ?? '';
        if (caller.includes('/web/src/')) reads.push(name + ' at ' + caller.trim());
        return undefined;
      } });
    }
    globalThis.__reads = reads;
  `;
  const printed = execFileSync(process.execPath, ['--input-type=module', '-e', `${traps}\n${body}\nconsole.log(JSON.stringify(globalThis.__reads));`],
    { cwd: root, encoding: 'utf8' }).trim().split('\n');
  return { out: JSON.parse(printed[0]), reads: JSON.parse(printed[printed.length - 1]) };
}

test('node: every entry of the package imports with no DOM and no WebAssembly; /react and /vue read none of them', () => {
  for (const [entry, file] of [['.', 'index'], ['./element', 'element'], ['./engine', 'engine'], ['./react', 'react'], ['./vue', 'vue']]) {
    const { out, reads } = onServer(`console.log(JSON.stringify(Object.keys(await import('./web/src/${file}.js')).sort()));`);
    if (entry === './react') assert.deepEqual(out, ['Flipbook', 'useFlipbook']);
    if (entry === './vue') assert.deepEqual(out, ['Flipbook', 'default']);
    if (entry === '.') assert.ok(out.includes('Flipbook'));
    if (entry === './element') assert.deepEqual(out, ['ConeFlipbookElement']);
    // The element module only looks whether HTMLElement and customElements exist, to define nothing on a server.
    const allowed = entry === './element' ? /^(HTMLElement|customElements) at .*element\.js/ : /^$/;
    assert.deepEqual(reads.filter((read) => !allowed.test(read)), [], `${entry} read a browser global`);
  }
});

test('node: the React and Vue components render on a server as a sized empty box, reading no browser global', () => {
  const { out, reads } = onServer(`
    import { createElement } from 'react';
    import { renderToString } from 'react-dom/server';
    import { createSSRApp, h } from 'vue';
    import { renderToString as renderVue } from 'vue/server-renderer';
    import { Flipbook } from './web/src/react.js';
    import { Flipbook as VueFlipbook } from './web/src/vue.js';
    const react = renderToString(createElement(Flipbook, { pages: ['a.png', 'b.png'], className: 'book', style: { height: 300 } },
      createElement('section', null, 'HTML page')));
    const vue = await renderVue(createSSRApp({ render: () => h(VueFlipbook, { pages: ['a.png'], class: 'book' }) }));
    console.log(JSON.stringify({ react, vue }));
  `);
  assert.equal(out.react, '<div class="book" style="display:block;position:relative;width:100%;aspect-ratio:16 / 10;height:300px"></div>');
  assert.match(out.vue, /^<div style="display:block;position:relative;width:100%;aspect-ratio:16 \/ 10;" class="book"><\/div>$/);
  assert.deepEqual(reads, []);
});

test('node: the components take every book option as a prop and name a handler for every book event', () => {
  for (const name of OPTION_NAMES.filter((n) => n !== 'startPage' && n !== 'on')) assert.ok(OPTION_PROPS.includes(name), name);
  assert.deepEqual(Object.keys(EVENT_HANDLERS), BOOK_EVENTS);
  assert.equal(EVENT_HANDLERS.pageerror, 'onPageError');
  assert.equal(EVENT_HANDLERS.turnstart, 'onTurnStart');
  for (const live of LIVE_OPTIONS) assert.ok(!FIXED_PROPS.includes(live), live);
  assert.ok(FIXED_PROPS.includes('direction'));
  assert.ok('display' in DEFAULTS);
});

test('node: pages written inline in each render are the same pages; a fixed option is a new book, changed pages are not', () => {
  assert.ok(samePages(['a.png', { src: 'b.png', alt: 'B' }], ['a.png', { src: 'b.png', alt: 'B' }]));
  assert.ok(!samePages(['a.png', { src: 'b.png', alt: 'B' }], ['a.png', { src: 'b.png', alt: 'C' }]));
  assert.ok(!samePages(['a.png'], ['a.png', 'b.png']));
  const element = new (class FakeElement {})();  // an HTML page or Blob: the same page only when the same object
  assert.ok(samePages([element], [element]));
  assert.ok(!samePages([element], [new (class FakeElement {})()]));
  assert.ok(!fixedOptionsDiffer({ pages: ['a'], lighting: true }, { pages: ['a'], lighting: false }));
  assert.ok(fixedOptionsDiffer({ pages: ['a'], direction: 'ltr' }, { pages: ['a'], direction: 'rtl' }));
  assert.ok(!fixedOptionsDiffer({ pages: ['a'] }, { pages: ['b'] }));  // pageChanges() applies them live
  // An object written inline in each render is the same option while its values are.
  assert.ok(!fixedOptionsDiffer({ controls: { search: false }, labels: { next: 'Suivant' } }, { controls: { search: false }, labels: { next: 'Suivant' } }));
  assert.ok(fixedOptionsDiffer({ controls: { search: false } }, { controls: { search: true } }));
  assert.ok(fixedOptionsDiffer({ controls: { search: false } }, { controls: true }));
  assert.ok(fixedOptionsDiffer({ labels: { next: 'Suivant' } }, { labels: { next: 'Suivant', previous: 'Précédent' } }));
});

test('node: pageChanges turns one pages prop into the next with the fewest live calls, inserting before removing', () => {
  const inline = (alt) => ({ src: 'b.png', alt });
  assert.deepEqual(pageChanges(['a', inline('B'), 'c'], ['a', inline('B'), 'c']), []);
  assert.deepEqual(pageChanges(['a', 'b', 'c'], ['a', 'x', 'b', 'y', 'c']), [['insertPages', 2, ['x', 'b', 'y']], ['removePages', 1, 1]]);
  assert.deepEqual(pageChanges(['a', 'b', 'c'], ['a', 'b', 'c', 'd', 'e']), [['insertPages', 3, ['d', 'e']]]);
  assert.deepEqual(pageChanges(['a', 'b', 'c', 'd'], ['a', 'd']), [['removePages', 1, 2]]);
  assert.deepEqual(pageChanges(['a', inline('B'), 'c'], ['a', inline('C'), 'c']), [['replacePage', 1, inline('C')]]);
  assert.deepEqual(pageChanges(['a', 'b', 'c', 'd'], ['x', 'b', 'c', 'y']), [['replacePage', 0, 'x'], ['replacePage', 3, 'y']]);
  assert.deepEqual(pageChanges(['a', 'b'], ['x']), [['insertPages', 2, ['x']], ['removePages', 0, 2]]);  // never empty between
  assert.deepEqual(pageChanges(['a', 'b'], []), [['removePages', 0, 2]]);  // refused by the book: it keeps a page
  // Applied in order to a list, the calls give the new list.
  const apply = (list, changes) => changes.reduce((pages, [method, at, arg]) => {
    const next = [...pages];
    if (method === 'insertPages') next.splice(at, 0, ...arg);
    if (method === 'removePages') next.splice(at, arg);
    if (method === 'replacePage') next[at] = arg;
    return next;
  }, list);
  for (const [a, b] of [[['a', 'b', 'c'], ['c', 'b', 'a']], [['a'], ['b', 'a', 'b']], [['a', 'a', 'a'], ['a', 'a']], [['p', 'q'], ['q', 'p', 'q', 'r']]]) {
    assert.deepEqual(apply(a, pageChanges(a, b)), b, `${a} -> ${b}`);
  }
});
