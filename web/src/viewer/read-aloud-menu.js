// The Read aloud part's "Voice and speed" popup: the reader's voice and speed, kept between readings,
// in two native selects over the toolbar; what a choice does (readAloud(), update()) is the caller's.
import { placeByAnchor, popupElement } from './more-menu.js';

/** The speeds offered, as `rate` (1: the voice's own). */
export const SPEEDS = [0.5, 0.75, 1, 1.25, 1.5, 2];
const EDGE = 4;  // CSS px kept between the popup and the screen's edge

let popupCount = 0;

// A language tag's parts, lower case: 'en_US' and 'en-US' are ['en', 'us'].
const tagParts = (tag) => String(tag ?? '').toLowerCase().replace(/_/g, '-').split('-');

/**
 * The voices with those of `lang` first (the same tag, then the same language: 'en-GB' before
 * 'en-US' for a page in en-GB, both in the browser's order for a page in en); the rest by language.
 */
export function voicesInOrder(voices, lang) {
  const [want, ...region] = tagParts(lang);
  const wanted = want ? [want, ...region].join('-') : '';
  const rank = (voice) => {
    const parts = tagParts(voice.lang);
    if (!want || parts[0] !== want) return 2;
    return parts.join('-') === wanted ? 0 : 1;
  };
  return voices.map((voice, at) => ({ voice, at, rank: rank(voice) }))
    .sort((a, b) => a.rank - b.rank || (a.rank === 2 ? String(a.voice.lang).localeCompare(String(b.voice.lang)) : 0) || a.at - b.at)
    .map(({ voice }) => voice);
}

/**
 * The popup for `button` (Voice and speed, which says aria-expanded). `anchorOf()`: the control it is
 * placed by and gives focus back to (the button, or More while the button is in the menu);
 * `voices()`: a promise of the browser's voices ({ name, lang }); `lang()`: the book's language;
 * `changed(change)`: the reader chose { voice } (undefined: the browser's default) or { rate }.
 * @returns {{ element: HTMLElement, choice: () => { voice?: string, rate: number },
 *   open: () => Promise<void>, close: (refocus?: boolean) => void, isOpen: () => boolean,
 *   place: () => void, remove: () => void }}
 */
export function createReadAloudMenu(labels, button, { anchorOf, voices, lang, changed }) {
  const id = `conecurl-read-menu-${++popupCount}`;
  const element = popupElement(id, 'dialog', labels.readAloudSettings, 'conecurl-menu conecurl-read-menu');
  button.setAttribute('aria-controls', id);

  const field = (text, name) => {
    const row = document.createElement('div');
    row.className = 'conecurl-read-field';
    const label = document.createElement('label');
    const select = document.createElement('select');
    select.id = `${id}-${name}`;
    select.name = name;
    label.htmlFor = select.id;
    label.textContent = text;
    row.append(label, select);
    element.append(row);
    return { row, select };
  };
  const option = (value, text) => Object.assign(document.createElement('option'), { value, textContent: text });
  const voice = field(labels.voice, 'voice');
  const speed = field(labels.speed, 'speed');
  for (const rate of SPEEDS) speed.select.append(option(String(rate), `${rate}\u00d7`));
  speed.select.value = '1';
  let chosenVoice = '';
  let rate = 1;
  voice.select.addEventListener('change', () => {
    chosenVoice = voice.select.value;
    changed({ voice: chosenVoice || undefined });
  });
  speed.select.addEventListener('change', () => {
    rate = Number(speed.select.value);
    changed({ rate });
  });

  // The voices as the browser lists them now; none: no Voice select (a narrated book still has Speed).
  function listVoices(list) {
    voice.select.replaceChildren(option('', labels.defaultVoice));
    for (const { name, lang: voiceLang } of voicesInOrder(list, lang())) {
      voice.select.append(option(name, voiceLang ? `${name} (${voiceLang})` : name));
    }
    if (!list.some(({ name }) => name === chosenVoice)) chosenVoice = '';
    voice.select.value = chosenVoice;
    voice.row.hidden = list.length === 0;
  }
  const selects = () => [voice, speed].filter(({ row }) => !row.hidden).map(({ select }) => select);

  // Above the anchor where there is room on the screen, else below it (more-menu.js placeByAnchor);
  // from the anchor's left edge, moved left as far as the screen's right edge asks.
  function place() {
    if (element.hidden) return;
    const holder = element.offsetParent ?? element.parentElement;
    if (!holder) return;
    element.style.maxHeight = '';
    const at = anchorOf().getBoundingClientRect();
    const box = holder.getBoundingClientRect();
    const screenWidth = element.ownerDocument.documentElement.clientWidth || window.innerWidth;
    const left = Math.max(EDGE, Math.min(at.left, screenWidth - element.offsetWidth - EDGE));
    element.style.left = `${Math.round(left - box.left)}px`;
    placeByAnchor(element, at, 2 * EDGE);  // its margin too
  }

  let opens = 0;  // a close, or another open, while the voices are awaited wins
  async function open() {
    if (!element.hidden) return;
    const token = ++opens;
    let list = [];
    try {
      list = await voices();
    } catch {
      list = [];
    }
    if (token !== opens || !element.hidden) return;
    listVoices(Array.isArray(list) ? list : []);
    element.hidden = false;
    button.setAttribute('aria-expanded', 'true');
    place();
    selects()[0]?.focus();
    element.ownerDocument.addEventListener('pointerdown', onOutside, true);
  }
  function close(refocus = false) {
    opens++;
    if (element.hidden) return;
    element.hidden = true;
    button.setAttribute('aria-expanded', 'false');
    element.ownerDocument.removeEventListener('pointerdown', onOutside, true);
    if (refocus) anchorOf().focus();
  }
  const onOutside = (event) => {
    const path = event.composedPath();
    if (!path.includes(element) && !path.includes(anchorOf()) && !path.includes(button)) close(false);
  };
  element.addEventListener('keydown', (event) => {
    if (event.key === 'Escape') {
      event.preventDefault();
      event.stopPropagation();
      close(true);
    } else if (event.key === 'Tab') {  // Tab and Shift+Tab go round the selects
      const list = selects();
      const at = list.indexOf(event.target);
      if (at < 0) return;
      event.preventDefault();
      list[(at + (event.shiftKey ? -1 : 1) + list.length) % list.length].focus();
    }
  });
  // Focus going elsewhere (a press on the book, another control) closes it; to its own button, that
  // button's press closes it.
  element.addEventListener('focusout', (event) => {
    const to = event.relatedTarget;
    if (to && !element.contains(to) && to !== button && to !== anchorOf()) close(false);
  });

  return {
    element,
    /** The reader's choice: { voice (a voice's name; absent for the browser's default), rate }. */
    choice: () => (chosenVoice ? { voice: chosenVoice, rate } : { rate }),
    open,
    close,
    isOpen: () => !element.hidden,
    /** Places it again by its anchor (the toolbar was fitted to a new width). */
    place,
    remove() {
      close(false);
      element.remove();
    },
  };
}
