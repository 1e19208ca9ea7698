// `--pages` publishes some of a PDF's pages: links and bookmarks point at source pages, so they are
// renumbered to the published ones, and those that point at a page left out are dropped.

/** The published index (from 0) of each source page index (from 0) in `numbers` (source pages from 1). */
const indexOf = (numbers) => new Map(numbers.map((number, index) => [number - 1, index]));

/** A page's links for the published book: page links renumbered, those to pages left out dropped. */
export function remapLinks(links, numbers) {
  const map = indexOf(numbers);
  return links.flatMap((link) => {
    if (link.page === undefined) return [link];
    return map.has(link.page) ? [{ rect: link.rect, page: map.get(link.page) }] : [];
  });
}

/** The outline for the published book: an entry whose page is left out gives its place to its children. */
export function remapOutline(entries, numbers, map = indexOf(numbers)) {
  return entries.flatMap((entry) => {
    const children = remapOutline(entry.children ?? [], numbers, map);
    return map.has(entry.page) ? [{ title: entry.title, page: map.get(entry.page), children }] : children;
  });
}
