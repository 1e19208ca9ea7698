// A render worker thread of `conecurl publish`: opens the PDF itself, then renders each page the main
// thread hands it (one at a time, so idle workers take the next) and writes that page's files.
import './pdfjs-node.mjs';  // the Node 20 polyfills, before pdf.js loads
import { parentPort, workerData } from 'node:worker_threads';
import { loadRenderer, openPdf } from './open-pdf.mjs';
import { POOL_PIXELS, renderPage } from './render-page.mjs';

const { bytes, file, password, bookDir, options, gate } = workerData;
// The pixels all workers hold in canvases now (shared, render-pool.js): a page waits for room under
// POOL_PIXELS, in megapixels; one page alone always goes ahead, however large.
const drawing = gate ? new Int32Array(gate) : null;
async function reserve(pixels) {
  if (!drawing) return () => {};
  const units = Math.max(1, Math.ceil(pixels / 1e6));
  for (;;) {
    const now = Atomics.load(drawing, 0);
    if ((now === 0 || now + units <= POOL_PIXELS / 1e6) && Atomics.compareExchange(drawing, 0, now, now + units) === now) break;
    await Atomics.waitAsync(drawing, 0, now, 1000).value;
  }
  return () => {
    Atomics.sub(drawing, 0, units);
    Atomics.notify(drawing, 0);
  };
}
const { pdfjs, canvas } = await loadRenderer();
const doc = await openPdf(pdfjs, bytes, file, password);
const textDoc = await openPdf(pdfjs, bytes, file, password, { browserFonts: true });  // the text as a browser reads it

parentPort.on('message', async ({ number, index }) => {
  try {
    const result = await renderPage({ doc, textDoc, createCanvas: canvas.createCanvas, number, index, bookDir, options, reserve });
    parentPort.postMessage({ type: 'page', result });
  } catch (error) {
    parentPort.postMessage({ type: 'failed', index, message: String(error?.message ?? error).split('\n')[0], stack: error?.stack });
  }
});
parentPort.postMessage({ type: 'ready' });
