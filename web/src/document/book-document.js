// What a reader does with the whole document: download (the `download` option's URL, else the document's
// PDF) and print (the pages rendered to images in a hidden frame). Each first fires a cancelable event, so a
// host can do it its own way. Loaded by the first call of either (fullscreen is fullscreen.js: it cannot wait).

/**
 * The URL download() fetches: the `download` option, else the document's (a PDF's URL or bytes as a
 * Blob URL, `made`: revoke it when done; a published document's PDF); null when there is nothing to download.
 */
async function downloadUrl(settings, doc) {
  if (settings.download) return { url: settings.download, made: false };
  return doc ? doc.downloadUrl() : null;
}

/**
 * Fires the cancelable `download` event ({ url }) on `target`; unless a listener prevented it, the
 * browser downloads the URL through an <a download>. Resolves false when prevented or nothing to download.
 */
export async function downloadDocument(target, root, settings, doc) {
  const found = await downloadUrl(settings, doc);
  if (!found) return false;
  const proceed = target.dispatchEvent(new CustomEvent('download', { detail: { url: found.url }, cancelable: true }));
  if (proceed) {
    const a = document.createElement('a');
    a.href = found.url;
    a.download = fileName(found.url);
    a.style.display = 'none';
    root.append(a);
    a.click();
    a.remove();
  }
  if (found.made) setTimeout(() => URL.revokeObjectURL(found.url), proceed ? 60000 : 0);  // the download has the bytes by then
  return proceed;
}

function fileName(url) {
  if (url.startsWith('blob:')) return 'document.pdf';
  try {
    return decodeURIComponent(new URL(url, document.baseURI).pathname.split('/').pop()) || 'document.pdf';
  } catch {
    return 'document.pdf';
  }
}

const PRINT_WIDTH = 1600;  // pixels across a printed page: about 190 dpi on A4

/**
 * Fires the cancelable `print` event ({ pages }) on `target`; unless prevented, draws every page
 * (`draw(index, { width })`: the thumbnails' drawing, from the page sources or pdf.js) into a hidden
 * frame, one page a sheet, and prints it. Resolves false when prevented.
 */
export async function printDocument(target, pageCount, draw) {
  const pages = Array.from({ length: pageCount }, (_, i) => i);
  if (!target.dispatchEvent(new CustomEvent('print', { detail: { pages: pages.slice() }, cancelable: true }))) return false;
  document.querySelector('iframe[data-conecurl-print]')?.remove();  // a frame from an earlier print
  const frame = document.createElement('iframe');
  frame.dataset.conecurlPrint = '';
  frame.setAttribute('aria-hidden', 'true');
  frame.tabIndex = -1;
  frame.style.cssText = 'position:fixed;right:0;bottom:0;width:0;height:0;border:0;visibility:hidden';
  document.body.append(frame);
  const doc = frame.contentDocument;  // about:blank: an empty document of this origin
  const style = doc.createElement('style');
  style.textContent = '@page { margin: 0 } html, body { margin: 0 } img { display: block; width: 100%; height: auto; break-after: page }';
  doc.head.append(style);
  const urls = [];
  for (const index of pages) {
    const canvas = await draw(index, { width: PRINT_WIDTH });
    const blob = await new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
    const url = URL.createObjectURL(blob);
    urls.push(url);
    const img = doc.createElement('img');
    img.alt = `Page ${index + 1}`;
    img.src = url;
    doc.body.append(img);
    await img.decode();
  }
  const done = () => {
    for (const url of urls) URL.revokeObjectURL(url);
    frame.remove();
  };
  frame.contentWindow.addEventListener('afterprint', done, { once: true });
  frame.contentWindow.print();
  return true;
}
