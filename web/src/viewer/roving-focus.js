// Roving focus for a toolbar (the WAI-ARIA toolbar pattern): one Tab stop, the arrow keys move between
// its controls, Home and End go to the first and last. In a text field the arrows move the caret, and
// leave the field from its start (Left), its end (Right), or while all its text is selected.

/** Makes `toolbar`'s controls (`items()`: the focusable ones, in order) one Tab stop; returns the stop. */
export function rovingFocus(toolbar, items) {
  let current = null;
  const settle = (target) => {
    const list = items();
    current = list.includes(target) ? target : (list.includes(current) ? current : list[0] ?? null);
    for (const item of list) item.tabIndex = item === current ? 0 : -1;
  };
  const move = (to) => {
    const list = items();
    if (list.length === 0) return;
    const at = list.indexOf(current);
    const next = to === 'first' ? 0 : to === 'last' ? list.length - 1 : (at + to + list.length) % list.length;
    settle(list[next]);
    list[next].focus();
  };
  const onKey = (event) => {
    if (event.defaultPrevented || event.altKey || event.ctrlKey || event.metaKey) return;
    const field = event.target instanceof HTMLInputElement ? event.target : null;
    // A field whose whole text is selected (as it is once focused) lets the arrows move on too.
    const all = field && field.selectionStart === 0 && field.selectionEnd === field.value.length;
    const atStart = !field || all || (field.selectionStart === 0 && field.selectionEnd === 0);
    const atEnd = !field || all || (field.selectionStart === field.value.length && field.selectionEnd === field.value.length);
    const step = { ArrowLeft: atStart ? -1 : 0, ArrowRight: atEnd ? 1 : 0, Home: field ? 0 : 'first', End: field ? 0 : 'last' }[event.key];
    if (!step) return;
    event.preventDefault();
    move(step);
  };
  const onFocus = (event) => settle(event.target);
  toolbar.addEventListener('keydown', onKey);
  toolbar.addEventListener('focusin', onFocus);
  settle(null);
  return {
    /** The controls changed (one hidden or shown): one of them is the Tab stop again. */
    refresh: () => settle(current),
    stop() {
      toolbar.removeEventListener('keydown', onKey);
      toolbar.removeEventListener('focusin', onFocus);
    },
  };
}
