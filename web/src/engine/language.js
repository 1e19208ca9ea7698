// The language an element of the page is in, one rule for every layer that asks (read-aloud's voice,
// the Voice and speed popup's order of voices): its nearest `lang`, through shadow roots to their hosts.

/**
 * The language page `entry` is read in: an HTML page's own (its element's nearest lang), else the book's
 * document's (`documentLang`: a PDF's /Lang, a published document's), else the book element's (`root`).
 */
export function pageLanguage(entry, documentLang, root) {
  return (entry?.html ? languageOf(entry.html) : documentLang) || languageOf(root);
}

/** The nearest `lang` around `element` (through shadow hosts), else the document's, else the browser's. */
export function languageOf(element) {
  for (let node = element; node; node = node.getRootNode?.().host) {
    const given = node.closest?.('[lang]');
    if (given) return given.lang;
  }
  return element?.ownerDocument?.documentElement.lang || globalThis.navigator?.language || '';
}
