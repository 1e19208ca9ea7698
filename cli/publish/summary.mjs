// The last words of `conecurl publish`: how many pages, how many bytes of images and of text, how long it
// took, how to look at the site, and the <iframe> that shows it on another page.

const size = (bytes) => (bytes >= 1024 * 1024 ? `${(bytes / 1024 / 1024).toFixed(1)} MB` : `${(bytes / 1024).toFixed(1)} KB`);

/** The summary text; `written` is [{ bytes, kind: 'image' | 'text' | 'runtime' | 'narration' | 'pdf' }]. */
export function summary({ out, pages, failed, seconds, written, embed = null }) {
  const total = (kind) => written.filter((file) => file.kind === kind).reduce((sum, file) => sum + file.bytes, 0);
  const rate = seconds > 0 ? pages / seconds : 0;
  const lines = [
    `Published ${pages - failed} of ${pages} pages in ${seconds.toFixed(1)} s (${rate.toFixed(1)} pages/s)${failed ? `; ${failed} failed (listed above)` : ''}`,
    `Wrote ${written.length} files: images ${size(total('image'))}, text ${size(total('text'))}, reader ${size(total('runtime'))}`
      + `${total('narration') ? `, narration ${size(total('narration'))}` : ''}${total('pdf') ? `, the PDF ${size(total('pdf'))}` : ''}`,
    `Open it: python3 -m http.server -d ${JSON.stringify(out).slice(1, -1).includes(' ') ? JSON.stringify(out) : out} 8000, then http://localhost:8000/`,
    ...(embed ? [`Embed it (src as the embedding page sees the site): ${embed}`] : []),
    '',
  ];
  return lines.join('\n');
}
