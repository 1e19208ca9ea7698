// The room the viewer's toolbar takes under the book, in one place: attach-controls.js lays the book out
// in the rest of its box, and a book whose toolbar comes after its first spread keeps the room till then.

/** The book's height beside the toolbar (--conecurl-toolbar-height, 44px unless the page says). */
export const BOOK_HEIGHT = 'calc(100% - var(--conecurl-toolbar-height, 44px))';

/**
 * Lays `element` (the book's) out as the toolbar will, before the toolbar is there: the first spread is drawn
 * at the size it keeps. Returns the release: the element's own height back, as attachControls() then
 * finds and keeps it (call it in the same task as attachControls(), so nothing is drawn between).
 */
export function keepToolbarRoom(element) {
  const given = element.style.height;
  element.style.height = BOOK_HEIGHT;
  return () => { element.style.height = given; };
}
