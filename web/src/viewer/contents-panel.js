// The Contents panel: book.outline() as nested lists of buttons named by their titles (each with its
// page number); a press turns to the entry's page, and the entry of the section being read is marked
// (aria-current) as the pages turn.

/** The tree in `panel` (panel.js) for `book`, read once when the panel first opens; returns { remove }. */
export function contentsPanel(book, panel, labels) {
  let entries = null;  // [{ page, button }] in reading order, once built
  let loading = null;

  function build(outline) {
    entries = [];
    if (outline.length === 0) {
      const empty = document.createElement('p');
      empty.className = 'conecurl-empty';
      empty.textContent = labels.noContents;
      panel.body.replaceChildren(empty);
      return;
    }
    const list = (items) => {
      const ul = document.createElement('ul');
      for (const item of items) {
        const li = document.createElement('li');
        const button = document.createElement('button');
        button.type = 'button';
        const title = document.createElement('span');
        title.textContent = item.title;
        const number = document.createElement('span');
        number.className = 'conecurl-result-page';
        number.textContent = String(item.page + 1);
        number.setAttribute('aria-hidden', 'true');
        button.append(title, number);
        button.addEventListener('click', () => { book.flip(item.page).catch(() => {}); });
        entries.push({ page: item.page, button });
        li.append(button);
        if (item.children?.length) li.append(list(item.children));
        ul.append(li);
      }
      return ul;
    };
    const tree = list(outline);
    tree.className = 'conecurl-tree';
    tree.setAttribute('aria-label', labels.contents);
    panel.body.replaceChildren(tree);
    followPage();
  }

  // The section being read: the last entry, in reading order, that starts at or before the last open page.
  function followPage() {
    if (!entries || entries.length === 0) return;
    const last = Math.max(...book.openPages);
    let current = null;
    for (const entry of entries) if (entry.page <= last && (!current || entry.page >= current.page)) current = entry;
    for (const entry of entries) {
      if (entry === current) entry.button.setAttribute('aria-current', 'location');
      else entry.button.removeAttribute('aria-current');
    }
  }

  const reload = () => {
    entries = null;
    loading = null;
    if (panel.isOpen()) load();
  };
  function load() {
    loading ??= book.outline().then((outline) => { if (!removed) build(outline); }, (error) => {
      const failed = document.createElement('p');
      failed.className = 'conecurl-empty';
      failed.textContent = String(error?.message ?? error);
      panel.body.replaceChildren(failed);
    });
  }
  let removed = false;
  panel.onToggle((open) => { if (open) load(); });
  book.addEventListener('turned', followPage);
  book.addEventListener('pageschange', reload);
  return {
    /** Resolves once the outline is shown (for tests and tools). */
    get ready() { return loading ?? Promise.resolve(); },
    remove() {
      removed = true;
      book.removeEventListener('turned', followPage);
      book.removeEventListener('pageschange', reload);
    },
  };
}
