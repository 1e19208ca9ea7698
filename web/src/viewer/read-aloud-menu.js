// The Read aloud part's "Voice and speed" popup: the reader's voice and speed, kept between readings
// (and, by language, in the book's read-aloud memory), in native selects over the toolbar; what a choice
// does (readAloud(), update()) is the caller's.
import { placeByAnchor, popupElement } from './more-menu.js';
import { languageOfTag, orderVoices, voiceMemory } from '../engine/voice-choice.js';

/** The speeds offered, as `rate` (1: the voice's own). */
export const SPEEDS = [0.5, 0.75, 1, 1.25, 1.5, 2];
const EDGE = 4;  // CSS px kept between the popup and the screen's edge
/**
 * Up to this many voices are listed in one select, the page's language first; more (Firefox lists
 * eSpeak's 13,362) and a Language select lists one language's voices at a time.
 */
export const LIST_ALL = 300;

let popupCount = 0;

/**
 * The voices with those of `lang` first (engine/voice-choice.js orderVoices: the reader's region,
 * then `lang`'s own, local before network, eSpeak last); the rest by language.
 */
export function voicesInOrder(voices, lang) {
  return orderVoices(voices, lang);
}

/**
 * The popup for `button` (Voice and speed, which says aria-expanded). `anchorOf()`: the control it is
 * placed by and gives focus back to (the button, or More while the button is in the menu);
 * `voices()`: a promise of the browser's voices ({ name, lang }); `lang()`: the book's language;
 * `changed(change)`: the reader chose { voice } (undefined: the browser's default) or { rate };
 * `memory()`: the book's `readAloudMemory` (the popup starts from the voice and speed kept there for
 * `lang()` and keeps each choice there; absent: nothing kept).
 * @returns {{ element: HTMLElement, choice: () => { voice?: string, rate: number },
 *   open: () => Promise<void>, close: (refocus?: boolean) => void, isOpen: () => boolean,
 *   place: () => void, remove: () => void }}
 */
export function createReadAloudMenu(labels, button, { anchorOf, voices, lang, changed, memory = () => false }) {
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
  const language = field(labels.voiceLanguage, 'language');  // shown for a long list only
  language.row.hidden = true;
  const voice = field(labels.voice, 'voice');
  const speed = field(labels.speed, 'speed');
  const speedText = (rate) => `${rate}\u00d7`;
  for (const rate of SPEEDS) speed.select.append(option(String(rate), speedText(rate)));
  speed.select.value = '1';
  const kept = () => voiceMemory(memory());
  let chosenVoice = null;  // the voice chosen here ('': the browser's default); null: the one kept, if any
  let rate = null;         // the speed chosen here; null: the one kept, else 1
  let ordered = [];        // the voices listed, in order
  let shownLanguage = null;
  const currentVoice = () => chosenVoice ?? kept().recall(lang()).voice ?? '';
  const currentRate = () => rate ?? kept().recall(lang()).rate ?? 1;
  voice.select.addEventListener('change', () => {
    chosenVoice = voice.select.value;
    kept().remember(lang(), { voice: chosenVoice || undefined });
    changed({ voice: chosenVoice || undefined });
  });
  speed.select.addEventListener('change', () => {
    rate = Number(speed.select.value);
    kept().remember(lang(), { rate });
    changed({ rate });
  });
  language.select.addEventListener('change', () => {
    shownLanguage = language.select.value;
    listLanguage();
  });

  // The voices as the browser lists them now; none: no Voice select (a narrated book still has Speed).
  // A long list: the Language select, on the language of the voice chosen (else the page's), and that
  // language's voices alone, so no more than one language's options are ever made.
  function listVoices(list) {
    ordered = voicesInOrder(list, lang());
    const now = currentVoice();
    const long = list.length > LIST_ALL;
    language.row.hidden = !long;
    voice.row.hidden = list.length === 0;
    if (long) {
      const codes = [...new Set(ordered.map((v) => languageOfTag(v.lang)))];
      let names = null;
      try { names = new Intl.DisplayNames([lang() || 'en'], { type: 'language' }); } catch { /* the codes alone */ }
      const nameOf = (code) => {
        try { return names?.of(code) ?? code; } catch { return code; }
      };
      language.select.replaceChildren(...codes.map((code) => option(code, code && nameOf(code) !== code ? `${nameOf(code)} (${code})` : code)));
      const ofVoice = ordered.find((v) => v.name === now);
      if (!codes.includes(shownLanguage)) shownLanguage = ofVoice ? languageOfTag(ofVoice.lang) : codes[0];
      language.select.value = shownLanguage;
      listLanguage();
    } else {
      fillVoices(ordered);
    }
    showRate(currentRate());
  }
  function listLanguage() {
    fillVoices(ordered.filter((v) => languageOfTag(v.lang) === shownLanguage));
  }
  function fillVoices(list) {
    voice.select.replaceChildren(option('', labels.defaultVoice), ...list.map(({ name, lang: voiceLang }) => option(name, voiceLang ? `${name} (${voiceLang})` : name)));
    const now = currentVoice();
    voice.select.value = list.some(({ name }) => name === now) ? now : '';
  }
  // The speed select on `value`, given an option of its own where it is none of SPEEDS (set through the API).
  function showRate(value) {
    const text = String(value);
    if (![...speed.select.options].some((o) => o.value === text)) {
      const after = [...speed.select.options].find((o) => Number(o.value) > value) ?? null;
      speed.select.insertBefore(option(text, speedText(value)), after);
    }
    speed.select.value = text;
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
    (voice.row.hidden ? selects()[0] : voice.select)?.focus();
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
    /**
     * The reader's choice: { voice (a voice's name chosen here; absent for the browser's default, or the
     * one kept, which readAloud() takes itself), rate (chosen here, else the one kept, else 1) }.
     */
    choice: () => (chosenVoice ? { voice: chosenVoice, rate: currentRate() } : { rate: currentRate() }),
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
