// A render worker thread of `conecurl publish`: opens the PDF itself, then renders each page the main
// thread hands it (one at a time, so idle workers take the next) and writes that page's files.
import './pdfjs-node.mjs';  // the Node 20 polyfills, before pdf.js loads
import { parentPort, workerData } from 'node:worker_threads';
import { loadRenderer, openPdf } from './open-pdf.mjs';
import { renderPage } from './render-page.mjs';

const { bytes, file, password, bookDir, options } = workerData;
const { pdfjs, canvas } = await loadRenderer();
const doc = await openPdf(pdfjs, bytes, file, password);
const textDoc = await openPdf(pdfjs, bytes, file, password, { browserFonts: true });  // the text as a browser reads it

parentPort.on('message', async ({ number, index }) => {
  try {
    const result = await renderPage({ doc, textDoc, createCanvas: canvas.createCanvas, number, index, bookDir, options });
    parentPort.postMessage({ type: 'page', result });
  } catch (error) {
    parentPort.postMessage({ type: 'failed', index, message: String(error?.message ?? error).split('\n')[0], stack: error?.stack });
  }
});
parentPort.postMessage({ type: 'ready' });
