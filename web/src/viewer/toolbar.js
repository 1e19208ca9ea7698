// The toolbar's elements: its buttons (each named by its label, an icon beside or instead of the text)
// and the page field ("3 of 12"; a page number typed and Enter opens it), in one role="toolbar" row
// with roving focus. What the buttons do is the caller's (attach-controls.js): `actions` by part.
import { icon } from './viewer-icons.js';
import { fill } from './viewer-labels.js';
import { rovingFocus } from './roving-focus.js';

// part -> [label key, icon, text shown beside the icon on a wide book]; in toolbar order, groups by null.
const LAYOUT = [
  ['previous', 'previous', false], ['page'], ['next', 'next', false], null,
  ['zoom'], null,
  ['thumbnails', 'thumbnails', true], ['contents', 'contents', true], ['search', 'search', true], null,
  ['download', 'download', false], ['print', 'print', false], ['fullscreen', 'fullscreen', false],
];
// The toggles whose state is shown by aria-pressed or aria-expanded.
const PANELS = ['thumbnails', 'contents', 'search'];

function makeButton(labels, key, iconName, textShown) {
  const button = document.createElement('button');
  button.type = 'button';
  button.dataset.control = key;
  const text = document.createElement('span');
  text.className = textShown ? 'conecurl-text' : 'conecurl-hidden-text';
  text.textContent = labels[key];
  if (!textShown) button.title = labels[key];
  button.append(icon(iconName), text);
  return button;
}

/**
 * The toolbar for `parts` (viewer-options.js shownParts), texts from `labels`. `actions[part](button)`
 * runs on a press; `actions.page(n)` gets the page number typed (from 1).
 * @returns {{ element: HTMLElement, buttons: Record<string, HTMLButtonElement>, pageField: HTMLInputElement|null,
 *   show: (state: object) => void, remove: () => void }}
 */
export function createToolbar(labels, parts, actions) {
  const element = document.createElement('div');
  element.className = 'conecurl-toolbar';
  element.setAttribute('role', 'toolbar');
  element.setAttribute('aria-label', labels.toolbar);
  const buttons = {};
  let pageField = null;
  let showPage = null;
  let lastGroupEmpty = true;
  for (const entry of LAYOUT) {
    if (entry === null) {
      if (!lastGroupEmpty) element.append(Object.assign(document.createElement('span'), { className: 'conecurl-gap' }));
      lastGroupEmpty = true;
      continue;
    }
    const [part] = entry;
    if (!parts[part]) continue;
    lastGroupEmpty = false;
    if (part === 'page') {
      ({ field: pageField, display: showPage } = makePageField(labels, actions.page));
      element.append(pageField);
    } else if (part === 'zoom') {
      buttons.zoomOut = makeButton(labels, 'zoomOut', 'zoomOut', false);
      buttons.zoomIn = makeButton(labels, 'zoomIn', 'zoomIn', false);
      element.append(buttons.zoomOut, buttons.zoomIn);
    } else {
      buttons[part] = makeButton(labels, entry[0], entry[1], entry[2]);
      element.append(buttons[part]);
    }
  }
  element.lastElementChild?.classList.contains('conecurl-gap') && element.lastElementChild.remove();
  for (const [name, button] of Object.entries(buttons)) {
    if (PANELS.includes(name)) button.setAttribute('aria-expanded', 'false');
    if (name === 'fullscreen') button.setAttribute('aria-pressed', 'false');
    button.addEventListener('click', () => {
      if (button.getAttribute('aria-disabled') !== 'true') actions[name](button);
    });
  }
  const focus = rovingFocus(element, () => [...element.querySelectorAll('button, input')]);

  return {
    element,
    buttons,
    pageField,
    /**
     * Shows the book's state: { pages (the open pages' numbers from 1: "6" or "6–7"), pageCount, atStart,
     * atEnd, zoom, maxZoom, fullscreen }.
     */
    show(state) {
      const disable = (button, off) => button?.setAttribute('aria-disabled', String(off));
      disable(buttons.previous, state.atStart);
      disable(buttons.next, state.atEnd);
      disable(buttons.zoomOut, state.zoom <= 1);
      disable(buttons.zoomIn, state.zoom >= state.maxZoom);
      buttons.fullscreen?.setAttribute('aria-pressed', String(state.fullscreen));
      showPage?.(fill(labels.pageOf, { n: state.pages, total: state.pageCount }), state.pageCount);
      focus.refresh();
    },
    remove() {
      focus.stop();
      element.remove();
    },
  };
}

// The page field: a text field named "Page" showing "N of M"; focused, it holds the number alone to
// type over; Enter opens the page typed (a number outside the book or not a number: nothing happens).
function makePageField(labels, open) {
  const field = document.createElement('input');
  const focused = () => field === field.getRootNode().activeElement;
  let count = 0;
  field.type = 'text';
  field.className = 'conecurl-page-field';
  field.inputMode = 'numeric';
  field.autocomplete = 'off';
  field.setAttribute('aria-label', labels.page);
  let shown = '';
  let typed = false;  // the reader typed since the number was last shown
  const number = () => /\d+/.exec(shown)?.[0] ?? '';
  field.addEventListener('input', () => { typed = true; });
  field.addEventListener('focus', () => {
    typed = false;
    field.value = number();
    field.select();
  });
  field.addEventListener('blur', () => {
    if (shown) field.value = shown;
  });
  field.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && field.value !== number()) {
      event.stopPropagation();
      typed = false;
      field.value = number();
      field.select();
      return;
    }
    if (event.key !== 'Enter') return;
    event.preventDefault();
    const n = Number(field.value.trim());
    if (Number.isInteger(n) && n >= 1 && n <= count) {
      typed = false;
      open(n);
      field.select();
    } else {
      field.setAttribute('aria-invalid', 'true');
      field.addEventListener('input', () => field.removeAttribute('aria-invalid'), { once: true });
    }
  });
  return {
    field,
    /** Shows `text` ("3 of 12"), now or once the field is left; `pageCount` bounds the numbers typed. */
    display(text, pageCount) {
      count = pageCount;
      shown = text;
      if (!focused()) field.value = text;
      else if (!typed) field.value = number();
    },
  };
}
