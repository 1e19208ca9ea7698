// The toolbar's elements: its buttons (each named by its label, an icon beside or instead of the text)
// and the page field ("3 of 12"; a page number typed and Enter opens it), in one role="toolbar" row
// with roving focus; the controls its width cannot hold move into the More menu (more-menu.js),
// measured, least used first. What the buttons do is the caller's (attach-controls.js): `actions` by part.
// A part may be made but absent (Read aloud, until the book says it can read aloud): hidden, and fitted
// as if it were not there.
import { icon } from './viewer-icons.js';
import { fill } from './viewer-labels.js';
import { rovingFocus } from './roving-focus.js';
import { createMoreMenu } from './more-menu.js';

// part -> [label key, icon, text shown beside the icon on a wide book]; in toolbar order, groups by null.
const LAYOUT = [
  ['previous', 'previous', false], ['page'], ['next', 'next', false], null,
  ['zoom'], ['readAloud'], null,
  ['thumbnails', 'thumbnails', true], ['contents', 'contents', true], ['search', 'search', true], null,
  ['download', 'download', false], ['print', 'print', false], ['fullscreen', 'fullscreen', false],
];
// The toggles whose state is shown by aria-pressed or aria-expanded.
const PANELS = ['thumbnails', 'contents', 'search'];
/**
 * The parts that move into the More menu when the toolbar's width cannot hold them, least used first
 * (each moves only once those before it did). Previous, Next and the page field always stay. Read
 * aloud moves after Zoom: zoom has gestures besides its buttons (pinch, double-tap, the wheel), while
 * a book reading itself is paused with its button alone, which should then be one press away.
 */
export const OVERFLOW_ORDER = ['print', 'download', 'fullscreen', 'contents', 'thumbnails', 'zoom', 'readAloud', 'search'];
/** The parts only ever in the More menu (no toolbar button): made absent, shown by setPresent. */
export const MENU_ONLY = ['keepOffline'];
// The buttons a part is made of.
const BUTTONS_OF = { zoom: ['zoomOut', 'zoomIn'], readAloud: ['readAloud', 'readAloudSettings'] };
const buttonsOf = (part) => BUTTONS_OF[part] ?? [part];

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
export function createToolbar(labels, parts, actions, { fullscreenKey = 'fullscreen' } = {}) {
  const element = document.createElement('div');
  element.className = 'conecurl-toolbar';
  element.setAttribute('role', 'toolbar');
  element.setAttribute('aria-label', labels.toolbar);
  const buttons = {};
  let pageField = null;
  let showPage = null;
  let group = [];  // the parts since the last gap
  const gaps = [];  // { gap, group }: a gap and the parts before it
  for (const entry of LAYOUT) {
    if (entry === null) {
      if (group.length > 0) {
        gaps.push({ gap: Object.assign(document.createElement('span'), { className: 'conecurl-gap' }), group });
        element.append(gaps.at(-1).gap);
      }
      group = [];
      continue;
    }
    const [part] = entry;
    if (!parts[part]) continue;
    group.push(part);
    if (part === 'page') {
      ({ field: pageField, display: showPage } = makePageField(labels, actions.page));
      element.append(pageField);
    } else if (part === 'zoom') {
      buttons.zoomOut = makeButton(labels, 'zoomOut', 'zoomOut', false);
      buttons.zoomIn = makeButton(labels, 'zoomIn', 'zoomIn', false);
      element.append(buttons.zoomOut, buttons.zoomIn);
    } else if (part === 'readAloud') {
      buttons.readAloud = makeButton(labels, 'readAloud', 'readAloud', false);
      buttons.readAloudSettings = makeButton(labels, 'readAloudSettings', 'readAloudSettings', false);
      buttons.readAloudSettings.setAttribute('aria-haspopup', 'dialog');
      buttons.readAloudSettings.setAttribute('aria-expanded', 'false');
      element.append(buttons.readAloud, buttons.readAloudSettings);
    } else if (part === 'fullscreen') {
      buttons.fullscreen = makeButton(labels, fullscreenKey, fullscreenKey === 'read' ? 'read' : 'fullscreen', false);
      element.append(buttons.fullscreen);
    } else {
      buttons[part] = makeButton(labels, entry[0], entry[1], entry[2]);
      element.append(buttons[part]);
    }
  }
  element.lastElementChild?.classList.contains('conecurl-gap') && element.lastElementChild.remove();
  // Reading mode's Exit (shown only while reading) and the More button end the row; neither moves.
  buttons.exit = makeButton(labels, 'exitReading', 'exit', false);
  buttons.exit.hidden = true;
  const menuItems = [];
  for (const [name, button] of Object.entries(buttons)) {
    const part = Object.keys(BUTTONS_OF).find((key) => BUTTONS_OF[key].includes(name)) ?? name;
    if (!OVERFLOW_ORDER.includes(part)) continue;
    const key = name === 'fullscreen' ? fullscreenKey : name;
    menuItems.push({ part: name, label: labels[key], iconName: name === 'fullscreen' && fullscreenKey === 'read' ? 'read' : name });
  }
  const menuOnly = MENU_ONLY.filter((part) => parts[part]);
  for (const part of menuOnly) menuItems.push({ part, label: labels[part], iconName: part });
  const menu = createMoreMenu(labels, menuItems, (name) => {
    const control = buttons[name] ?? menu.items[name];
    if (control.getAttribute('aria-disabled') !== 'true') actions[name](control);
  });
  element.append(buttons.exit, menu.button);
  for (const [name, button] of Object.entries(buttons)) {
    if (PANELS.includes(name)) button.setAttribute('aria-expanded', 'false');
    if (name === 'fullscreen') button.setAttribute('aria-pressed', 'false');
    button.addEventListener('click', () => {
      if (button.getAttribute('aria-disabled') !== 'true') actions[name](button);
    });
  }
  const focus = rovingFocus(element, () => [...element.querySelectorAll('button, input')].filter((control) => !control.hidden));

  // The width's fit: every part shown; while the row is wider than the toolbar, the next part of
  // OVERFLOW_ORDER moves into the menu. Measured on the real widths (labels, fonts, a coarse pointer's
  // 44 px targets), again whenever the toolbar's width changes.
  let reading = false;
  const absent = new Set([...(buttons.readAloud ? ['readAloud'] : []), ...menuOnly]);
  const present = (part) => buttonsOf(part).every((name) => buttons[name]) && !absent.has(part)
    && !(reading && part === 'fullscreen');
  const setShown = (part, on) => { for (const name of buttonsOf(part)) if (buttons[name]) buttons[name].hidden = !on; };
  const menuOnlyShown = () => menuOnly.filter((part) => !absent.has(part));
  // A group of absent parts alone (Read aloud, with zoom hidden) takes no gap either.
  const tidyGaps = () => { for (const { gap, group: parts } of gaps) gap.hidden = parts.every((part) => absent.has(part)); };
  for (const part of absent) setShown(part, false);
  tidyGaps();
  const fits = () => element.scrollWidth <= element.clientWidth;
  let moved = [];
  function fit() {
    if (element.clientWidth === 0) return;
    // A control hidden while the row is measured loses focus: it goes back to it once the fit is done
    // (or to More, where the control moved into the menu).
    const focused = [...Object.values(buttons), menu.button].find((control) => control === document.activeElement);
    const movable = OVERFLOW_ORDER.filter(present);
    for (const part of movable) setShown(part, true);
    if (buttons.fullscreen) buttons.fullscreen.hidden = reading;
    menu.show(menuOnlyShown());  // More stays while it holds a menu-only item
    moved = [];
    if (!fits()) {
      menu.button.hidden = false;
      for (const part of movable) {
        if (fits()) break;
        setShown(part, false);
        moved.push(part);
      }
    }
    const names = moved.flatMap(buttonsOf);
    menu.show(Object.keys(menu.items).filter((name) => names.includes(name) || menuOnlyShown().includes(name)));  // in toolbar order
    if (focused && document.activeElement !== focused) (focused.hidden ? menu.button : focused).focus();
    focus.refresh();
  }
  const watch = typeof ResizeObserver === 'function' ? new ResizeObserver(() => fit()) : null;
  watch?.observe(element);
  const mirror = (name) => {  // a menu item says what its button says
    const item = menu.items[name];
    if (!item) return;
    for (const attribute of ['aria-disabled', 'aria-expanded', 'aria-pressed', 'data-on']) {
      const value = buttons[name].getAttribute(attribute);
      const mirrored = attribute === 'aria-disabled' ? attribute : 'data-on';  // a menuitem has no aria-pressed
      if (value !== null) item.setAttribute(mirrored, value);
    }
  };
  const states = new MutationObserver((records) => { for (const record of records) mirror(record.target.dataset.control); });
  for (const button of Object.values(buttons)) states.observe(button, { attributes: true, attributeFilter: ['aria-disabled', 'aria-expanded', 'aria-pressed', 'data-on'] });

  return {
    element,
    buttons,
    pageField,
    /** The More menu: { button, element, open(), close(), isOpen() }; its element goes beside the toolbar. */
    menu,
    /** Fits the controls to the toolbar's width again (after its buttons changed size). */
    fit,
    /** The parts in the More menu now, in the order they moved. */
    moved: () => [...moved],
    /** Where focus goes for a part's button: the button, or the More button while the part is in the menu. */
    focusTarget: (name) => (buttons[name] && !buttons[name].hidden ? buttons[name] : menu.button),
    /** Shows a part made absent (`on`), or takes it away again (hidden, and not in the menu); fits again. */
    setPresent(part, on) {
      if (!(buttons[buttonsOf(part)[0]] ?? menu.items[part]) || absent.has(part) === !on) return;
      if (on) absent.delete(part);
      else {
        absent.add(part);
        setShown(part, false);
      }
      tidyGaps();
      fit();
    },
    /** Names button `name` by label `key` (or `text`, that label filled in) with icon `iconName`, in the toolbar and in the More menu. */
    relabel(name, key, iconName, text = labels[key]) {
      for (const control of [buttons[name], menu.items[name]]) {
        if (!control) continue;
        control.querySelector('span').textContent = text;
        if (control.title) control.title = text;
        control.querySelector('svg').replaceWith(icon(iconName));
      }
    },
    /** Reading mode: Exit shown, Fullscreen (or Read) hidden. */
    setReading(on) {
      reading = on;
      buttons.exit.hidden = !on;
      fit();
    },
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
      watch?.disconnect();
      states.disconnect();
      menu.remove();
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
