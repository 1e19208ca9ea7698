// What the React and Vue components share: which props are book options, which of those change on the
// live book and which need a new one, the handler of each book event, pages compared by content, and
// the pages a component's children make. Read from options.js and book-events.js, never copied.
import { BOOK_EVENTS } from '../book/book-events.js';
import { CREATE_OPTIONS, LIVE_OPTIONS } from '../book/options.js';

/** Options a component passes through as props: startPage comes from page/defaultPage, `on` from the handlers. */
export const OPTION_PROPS = CREATE_OPTIONS.filter((name) => name !== 'startPage' && name !== 'on');
/** Props of both components beside the options and the event handlers: the page shown, controlled or not. */
export const PAGE_PROPS = ['page', 'defaultPage'];
/**
 * Props a change of which builds a new book at the page shown; LIVE_OPTIONS go to the running book
 * (setOptions), and `pages` too, as the changes pageChanges() finds.
 */
export const FIXED_PROPS = OPTION_PROPS.filter((name) => !LIVE_OPTIONS.includes(name) && name !== 'pages');

const HANDLER_WORDS = {
  pageerror: 'PageError', turnstart: 'TurnStart', turncancel: 'TurnCancel', pageschange: 'PagesChange',
  searchchange: 'SearchChange', fullscreenchange: 'FullscreenChange', passagelink: 'PassageLink',
  displaychange: 'DisplayChange', middletap: 'MiddleTap', readaloudstart: 'ReadAloudStart', readaloudpage: 'ReadAloudPage',
  readaloudword: 'ReadAloudWord', readaloudsentence: 'ReadAloudSentence', readaloudvoices: 'ReadAloudVoices', readaloudpause: 'ReadAloudPause', readaloudresume: 'ReadAloudResume', readaloudend: 'ReadAloudEnd',
};
/** 'turned' -> 'onTurned', 'pageerror' -> 'onPageError', ... for every book event. */
export const EVENT_HANDLERS = Object.fromEntries(BOOK_EVENTS.map((type) => [
  type, `on${HANDLER_WORDS[type] ?? type[0].toUpperCase() + type.slice(1)}`,
]));

const plainObject = (value) => value !== null && typeof value === 'object' && Object.getPrototypeOf(value) === Object.prototype;

// Two page entries are the same page when they are the same value, or plain objects ({ src, alt, ... })
// whose fields are: an array written inline in a render is not a new book.
function samePage(a, b) {
  if (Object.is(a, b)) return true;
  if (!plainObject(a) || !plainObject(b)) return false;
  const keys = Object.keys(a);
  return keys.length === Object.keys(b).length && keys.every((key) => key !== 'links' ? Object.is(a[key], b[key])
    : JSON.stringify(a.links) === JSON.stringify(b.links));
}

/** Whether two `pages` arrays (or undefined) list the same pages. */
export function samePages(a, b) {
  if (a === b) return true;
  if (!Array.isArray(a) || !Array.isArray(b) || a.length !== b.length) return false;
  return a.every((page, i) => samePage(page, b[i]));
}

// Two option values are the same when they are the same value, or plain objects of the same values
// (`controls={{ search: false }}`, `labels`, an autoplay object written inline are not a new book).
function sameOption(a, b) {
  if (Object.is(a, b)) return true;
  if (!plainObject(a) || !plainObject(b)) return false;
  const keys = Object.keys(a);
  return keys.length === Object.keys(b).length && keys.every((key) => Object.is(a[key], b[key]));
}

/** Whether the options that need a new book differ between two sets of props (`pages` changes live). */
export function fixedOptionsDiffer(a, b) {
  return FIXED_PROPS.some((name) => !sameOption(a[name], b[name]));
}

/**
 * The live book calls that turn page list `a` into `b`, as [method, ...arguments]: the pages both
 * start and end with stay; between them, pages replaced one by one where the count stays, else the
 * new ones inserted after the old ones, then the old ones removed (so the book never runs out of pages).
 */
export function pageChanges(a, b) {
  let start = 0;
  while (start < a.length && start < b.length && samePage(a[start], b[start])) start++;
  let end = 0;
  while (end < a.length - start && end < b.length - start && samePage(a[a.length - 1 - end], b[b.length - 1 - end])) end++;
  const gone = a.length - start - end;
  const come = b.length - start - end;
  if (gone === come) {
    return b.slice(start, start + come).flatMap((page, i) => (samePage(a[start + i], page) ? [] : [['replacePage', start + i, page]]));
  }
  return [...(come > 0 ? [['insertPages', start + gone, b.slice(start, start + come)]] : []),
    ...(gone > 0 ? [['removePages', start, gone]] : [])];
}

/** The book options in a component's props (those given), `pages` included. */
export function optionsOf(props) {
  const options = {};
  for (const name of OPTION_PROPS) if (props[name] !== undefined) options[name] = props[name];
  return options;
}

/** Page `index` clamped into a book of `count` pages. */
export const clampPage = (index, count) => Math.max(0, Math.min(Number.isInteger(index) ? index : 0, Math.max(0, count - 1)));

/**
 * The box an HTML page child renders into (a React portal's or Vue Teleport's target), one per child
 * key in `hosts`, made once and kept while the key is; `keep(keys)` lets go of the others.
 */
export function pageBoxes() {
  const hosts = new Map();
  return {
    box(key) {
      let host = hosts.get(key);
      if (!host) {
        host = document.createElement('div');
        host.style.height = '100%';
        hosts.set(key, host);
      }
      return host;
    },
    keep(keys) {
      for (const key of hosts.keys()) if (!keys.has(key)) hosts.delete(key);
    },
  };
}
