// The toolbar's "More" menu (the WAI-ARIA menu button pattern): the controls that do not fit the
// toolbar's width, as role="menuitem" buttons under a button with aria-haspopup="menu". Up/Down, Home,
// End move; Enter/Space press; Escape or Tab closes (Escape gives focus back to the More button); a
// press outside closes it.
import { icon } from './viewer-icons.js';

let menuCount = 0;

/** A closed popup of the toolbar (`role` 'menu' or 'dialog', named `label`), styled as the More menu. */
export function popupElement(id, role, label, className = 'conecurl-menu') {
  const element = document.createElement('div');
  element.className = className;
  element.id = id;
  element.hidden = true;
  element.setAttribute('role', role);
  element.setAttribute('aria-label', label);
  return element;
}

/**
 * A popup opened by a control at `at` (its client rect): above it where there is room on the screen,
 * else below it (`data-below`), never taller than the screen leaves it, `margin` CSS px kept. The
 * Voice and speed popup (read-aloud-menu.js) is placed by it too.
 */
export function placeByAnchor(element, at, margin) {
  const above = at.top;
  const below = window.innerHeight - at.bottom;
  const up = above >= Math.min(below, element.scrollHeight) || above >= element.scrollHeight;
  element.toggleAttribute('data-below', !up);
  element.style.maxHeight = `${Math.max(44, Math.floor((up ? above : below) - margin))}px`;
}

/**
 * The More button and its menu. `items`: [{ part, label, iconName }] in menu order; `press(part)` runs
 * when one is chosen. The caller puts `button` in the toolbar and `element` beside the toolbar.
 * @returns {{ button: HTMLButtonElement, element: HTMLElement, show: (parts: string[]) => void,
 *   open: (focusAt?: 'first'|'last') => void, close: (refocus?: boolean) => void, isOpen: () => boolean,
 *   items: Record<string, HTMLButtonElement>, remove: () => void }}
 */
export function createMoreMenu(labels, items, press) {
  const id = `conecurl-more-${++menuCount}`;
  const button = document.createElement('button');
  button.type = 'button';
  button.dataset.control = 'more';
  button.title = labels.more;
  button.setAttribute('aria-haspopup', 'menu');
  button.setAttribute('aria-expanded', 'false');
  button.setAttribute('aria-controls', id);
  const buttonText = document.createElement('span');
  buttonText.className = 'conecurl-hidden-text';
  buttonText.textContent = labels.more;
  button.append(icon('more'), buttonText);

  const element = popupElement(id, 'menu', labels.more);
  const byPart = {};
  for (const { part, label, iconName } of items) {
    const item = document.createElement('button');
    item.type = 'button';
    item.tabIndex = -1;
    item.dataset.control = part;
    item.setAttribute('role', 'menuitem');
    const text = document.createElement('span');
    text.textContent = label;
    item.append(icon(iconName), text);
    item.addEventListener('click', () => {
      close(true);
      press(part);
    });
    byPart[part] = item;
    element.append(item);
  }
  const shown = () => [...element.children].filter((item) => !item.hidden);

  function open(focusAt = 'first') {
    if (!element.hidden) return;
    element.hidden = false;
    button.setAttribute('aria-expanded', 'true');
    placeByAnchor(element, button.getBoundingClientRect(), 4);
    const list = shown();
    list[focusAt === 'last' ? list.length - 1 : 0]?.focus();
    document.addEventListener('pointerdown', onOutside, true);
  }
  function close(refocus = false) {
    if (element.hidden) return;
    element.hidden = true;
    button.setAttribute('aria-expanded', 'false');
    document.removeEventListener('pointerdown', onOutside, true);
    if (refocus) button.focus();
  }
  const onOutside = (event) => {
    const path = event.composedPath();
    if (!path.includes(element) && !path.includes(button)) close(false);
  };

  button.addEventListener('click', () => (element.hidden ? open('first') : close(false)));
  button.addEventListener('keydown', (event) => {
    if (event.key !== 'ArrowDown' && event.key !== 'ArrowUp') return;
    event.preventDefault();
    open(event.key === 'ArrowUp' ? 'last' : 'first');
  });
  element.addEventListener('keydown', (event) => {
    const list = shown();
    const at = list.indexOf(event.target);
    const to = { ArrowDown: at + 1, ArrowUp: at - 1, Home: 0, End: list.length - 1 }[event.key];
    if (to !== undefined) {
      event.preventDefault();
      list[(to + list.length) % list.length]?.focus();
    } else if (event.key === 'Escape') {
      event.preventDefault();
      event.stopPropagation();
      close(true);
    } else if (event.key === 'Tab') {
      close(false);
    }
  });
  // A menu item pressed by the keyboard gives focus back to the More button (or a panel takes it);
  // focus leaving the menu otherwise closes it.
  element.addEventListener('focusout', (event) => {
    if (event.relatedTarget && !element.contains(event.relatedTarget) && event.relatedTarget !== button) close(false);
  });

  return {
    button,
    element,
    items: byPart,
    /** The parts the menu holds now (the others' items are hidden); none: the More button is hidden. */
    show(parts) {
      for (const [part, item] of Object.entries(byPart)) item.hidden = !parts.includes(part);
      button.hidden = parts.length === 0;
      if (parts.length === 0) close(false);
    },
    open,
    close,
    isOpen: () => !element.hidden,
    remove() {
      close(false);
      element.remove();
    },
  };
}
