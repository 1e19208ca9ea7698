// Links to a passage: the passage button of the text layer (text-layer.js) hands over a selection; its
// link (#page=N&text=..., passage-address.js) goes to the clipboard, and the book says so
// with a `passagelink` event the host can hear (to show a toast, or share the link its own way).
import { passageUrl } from './passage-address.js';

/**
 * Puts `text` on the clipboard: the Clipboard API where the page may use it, else a hidden textarea's
 * selection copied with execCommand('copy'). Resolves with whether it was copied.
 */
export async function copyText(text) {
  try {
    if (globalThis.navigator?.clipboard?.writeText) {
      await navigator.clipboard.writeText(text);
      return true;
    }
  } catch {
    // refused (no permission, an insecure page, no focus): the old way below
  }
  const area = document.createElement('textarea');
  area.value = text;
  area.setAttribute('readonly', '');
  area.setAttribute('aria-hidden', 'true');
  area.style.cssText = 'position:fixed;left:-10000px;top:0;width:1px;height:1px;opacity:0';
  const selection = document.getSelection();
  const kept = selection && selection.rangeCount > 0 ? selection.getRangeAt(0) : null;
  const focused = document.activeElement;
  document.body.append(area);
  area.select();
  let copied = false;
  try {
    copied = document.execCommand('copy');
  } catch {
    copied = false;
  }
  area.remove();
  if (kept) {
    selection.removeAllRanges();
    selection.addRange(kept);  // the reader's selection stays what it was
  }
  if (focused && typeof focused.focus === 'function') focused.focus({ preventScroll: true });
  return copied;
}

/** The passage { page, text } as a link, copied; resolves with the `passagelink` event's detail. */
export async function sharePassage({ page, text }) {
  const url = passageUrl(page, text);
  const copied = await copyText(url);
  return { page, text, url, copied };
}
