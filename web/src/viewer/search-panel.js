// The Search panel: a search field (Enter searches, or goes to the next hit once searched; Shift+Enter
// the previous), previous and next hit buttons, a polite live region saying "3 of 17", and the results
// (page number and snippet); a result chosen is shown on its page (book.showHit). A new search aborts
// the one under way; closing the panel ends the search (book.clearSearch).
import { icon } from './viewer-icons.js';
import { fill } from './viewer-labels.js';

function iconButton(name, label) {
  const button = document.createElement('button');
  button.type = 'button';
  button.title = label;
  const text = document.createElement('span');
  text.className = 'conecurl-hidden-text';
  text.textContent = label;
  button.append(icon(name), text);
  return button;
}

/**
 * The search in `panel` (panel.js) for `book`; `revealHit(hit)` is called once a hit is shown (the
 * viewer keeps it clear of a sheet); returns { remove }.
 */
export function searchPanel(book, panel, labels, { revealHit = () => {} } = {}) {
  const row = document.createElement('div');
  row.className = 'conecurl-search-row';
  const field = document.createElement('input');
  field.type = 'search';
  field.setAttribute('aria-label', labels.searchField);
  field.autocomplete = 'off';
  field.enterKeyHint = 'search';
  const previous = iconButton('up', labels.previousHit);
  const next = iconButton('down', labels.nextHit);
  row.append(field, previous, next);
  const status = document.createElement('div');
  status.className = 'conecurl-search-status';
  status.setAttribute('role', 'status');
  status.setAttribute('aria-live', 'polite');
  const results = document.createElement('ul');
  results.className = 'conecurl-results';
  results.setAttribute('aria-label', labels.search);
  panel.body.append(results);
  panel.body.before(row, status);

  let query = '';
  let hits = [];
  let current = -1;
  let controller = null;

  async function run(text) {
    controller?.abort();
    controller = new AbortController();
    const { signal } = controller;
    query = text;
    hits = [];
    current = -1;
    results.replaceChildren();
    if (text.trim() === '') {
      book.clearSearch();
      announce('');
      return;
    }
    announce(labels.searching);
    let found;
    try {
      found = await book.search(text, { signal });
    } catch (error) {
      if (signal.aborted) return;
      announce(String(error?.message ?? error));
      return;
    }
    if (signal.aborted || removed) return;
    hits = found;
    results.replaceChildren(...hits.map((hit, i) => resultItem(hit, i)));
    if (hits.length === 0) announce(labels.noHits);
    else choose(0);
  }

  function resultItem(hit, i) {
    const li = document.createElement('li');
    const button = document.createElement('button');
    button.type = 'button';
    const page = document.createElement('span');
    page.className = 'conecurl-result-page';
    page.textContent = fill(labels.hitPage, { n: hit.page + 1 });
    const snippet = document.createElement('span');
    snippet.textContent = hit.snippet;
    button.append(page, snippet);
    button.addEventListener('click', () => choose(i));
    li.append(button);
    return li;
  }

  function choose(i) {
    if (hits.length === 0) return;
    mark(i);
    const hit = hits[current];
    book.showHit(hit).then(() => { if (!removed && hits[current] === hit) revealHit(hit); }, () => {});
  }

  // Hit `i` is the current one: marked in the list, announced.
  function mark(i) {
    current = (i + hits.length) % hits.length;
    results.querySelector('[aria-current]')?.removeAttribute('aria-current');
    const button = results.children[current]?.firstElementChild;
    button?.setAttribute('aria-current', 'true');
    button?.scrollIntoView({ block: 'nearest' });
    announce(fill(labels.hitOf, { n: current + 1, total: hits.length }));
  }

  // The book says what its search is (searchchange): a search run or ended elsewhere shows here, and a
  // hit shown elsewhere (a tick on the book's edge) becomes the current one.
  const followBook = (event) => {
    const { query: shown, hits: now, current: hit } = event.detail;
    if (shown === '' && query !== '') {
      controller?.abort();
      query = '';
      hits = [];
      current = -1;
      results.replaceChildren();
      announce('');
      return;
    }
    if (shown !== '' && !(now.length === hits.length && now.every((h, i) => h === hits[i]))) {
      query = shown;
      field.value = shown;
      hits = now;
      current = -1;
      results.replaceChildren(...hits.map((h, i) => resultItem(h, i)));
      announce(hits.length === 0 ? labels.noHits : '');
    }
    const at = hit ? hits.indexOf(hit) : -1;
    if (at >= 0 && at !== current) mark(at);
  };
  book.addEventListener('searchchange', followBook);

  function announce(text) {
    if (status.textContent !== text) status.textContent = text;
  }

  field.addEventListener('keydown', (event) => {
    if (event.key !== 'Enter') return;
    event.preventDefault();
    if (field.value !== query || hits.length === 0) run(field.value);
    else choose(current + (event.shiftKey ? -1 : 1));
  });
  previous.addEventListener('click', () => choose(current - 1));
  next.addEventListener('click', () => choose(current + 1));

  let removed = false;
  const end = () => {
    controller?.abort();
    controller = null;
    if (query !== '') book.clearSearch();
    query = '';
    hits = [];
    current = -1;
    results.replaceChildren();
    announce('');
  };
  panel.onToggle((open) => {
    if (open) field.focus();
    else end();
  });
  return {
    remove() {
      removed = true;
      controller?.abort();
      book.removeEventListener('searchchange', followBook);
    },
  };
}
