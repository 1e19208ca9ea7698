// A panel of the viewer (thumbnails, contents, search): a non-modal dialog over the book's side (a
// sheet from the bottom on a narrow book or a phone; attach-controls.js places it), opened and closed by its toolbar button, which says so
// (aria-expanded). Escape or its close button closes it and gives focus back to that button.
import { icon } from './viewer-icons.js';

let panelCount = 0;

/**
 * A panel titled `title` for `button`; `content` is what it shows: { element, opened(), closed() }.
 * `focusTarget()` is where focus goes back to on close: the button, or the More button while the
 * button is in the More menu.
 * @returns {{ element: HTMLElement, body: HTMLElement, open: () => void, close: (refocus?: boolean) => void,
 *   isOpen: () => boolean, remove: () => void }}
 */
export function createPanel(labels, title, button, focusTarget = () => button) {
  const id = `conecurl-panel-${++panelCount}`;
  const element = document.createElement('div');
  element.className = 'conecurl-panel';
  element.id = id;
  element.hidden = true;
  element.setAttribute('role', 'dialog');
  element.setAttribute('aria-labelledby', `${id}-title`);
  const head = document.createElement('div');
  head.className = 'conecurl-panel-head';
  const heading = document.createElement('h2');
  heading.id = `${id}-title`;
  heading.textContent = title;
  const close = document.createElement('button');
  close.type = 'button';
  close.title = labels.close;
  const closeText = document.createElement('span');
  closeText.className = 'conecurl-hidden-text';
  closeText.textContent = labels.close;
  close.append(icon('close'), closeText);
  head.append(heading, close);
  const body = document.createElement('div');
  body.className = 'conecurl-panel-body';
  element.append(head, body);
  button.setAttribute('aria-controls', id);

  const listeners = new Set();
  const panel = {
    element,
    body,
    /** `listener(open)` is called as the panel opens (true) or closes (false). */
    onToggle: (listener) => listeners.add(listener),
    isOpen: () => !element.hidden,
    open() {
      if (!element.hidden) return;
      element.hidden = false;
      button.setAttribute('aria-expanded', 'true');
      for (const listener of listeners) listener(true);
    },
    /** Closes it; `refocus`: focus goes back to its button. */
    close(refocus = false) {
      if (element.hidden) return;
      element.hidden = true;
      button.setAttribute('aria-expanded', 'false');
      for (const listener of listeners) listener(false);
      if (refocus) focusTarget().focus();
    },
    remove: () => element.remove(),
  };
  close.addEventListener('click', () => panel.close(true));
  element.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || event.defaultPrevented) return;
    event.preventDefault();
    event.stopPropagation();
    panel.close(true);
  });
  return panel;
}
