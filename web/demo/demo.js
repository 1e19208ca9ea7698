// Demo wiring: the forty-page book in a Flipbook (the public class, as a user would use it; without
// WebGL2, the still-page fallback its create() rejects with), its controls, and the schedule the engine
// computes (theta, Ay, rho over t) plotted beside it with a scrubber that poses the next turn's exact
// frame. The Book choice swaps in the PDF, the HTML magazine or the narrated picture book (demo-story.js);
// Read aloud reads whichever is open.
import { Flipbook } from '../src/index.js';
import { loadEngine } from '../src/engine.js';
import { DEMO_PAGE_COUNT, drawBookPage, isHardPage } from './book-pages.js';
import { makeDemoPdf } from './demo-pdf.js';
import { magazinePages } from './demo-magazine.js';
import { storyPages } from './demo-story.js';

const $ = (id) => document.getElementById(id);
const deg = 180 / Math.PI;

let engine;
let book;
let building = Promise.resolve();
let pdfBytes = null;  // the PDF example, made once when first chosen

// Pages are drawn only when the book wants them: the cache keeps a handful, however long the book.
const PAGES = Array.from({ length: DEMO_PAGE_COUNT }, (_, index) => ({
  src: () => drawBookPage(index),
  alt: index === 0 ? 'Front cover: The Curl of the Page' : index === DEMO_PAGE_COUNT - 1 ? 'Back cover'
    : `Page ${index + 1}`,
  hard: isHardPage(index),
}));

// The schedule chosen (the paper's three phases, or the same key poses joined smoothly), for the plot.
const curlAt = (t) => engine.curlAtWith(t, { ...engine.defaultSchedule(), smooth: $('schedule').value === 'smooth' }, 1);

function plotSchedule(t) {
  const canvas = $('plot');
  const g = canvas.getContext('2d');
  const { width: w, height: h } = canvas;
  g.clearRect(0, 0, w, h);
  g.strokeStyle = '#ddd';
  for (const edge of [0.15, 0.4]) {
    g.beginPath(); g.moveTo(edge * w, 0); g.lineTo(edge * w, h); g.stroke();
  }
  const colour = (name) => getComputedStyle(document.documentElement).getPropertyValue(`--${name}`).trim();  // demo.css
  const curves = [
    [colour('theta'), (p) => p.theta / (Math.PI / 2)],
    [colour('apex'), (p) => -p.apexY / 15],
    [colour('rho'), (p) => p.rho / Math.PI],
  ];
  for (const [color, value] of curves) {
    g.strokeStyle = color;
    g.lineWidth = 2;
    g.beginPath();
    for (let i = 0; i <= w; i++) {
      const y = h - 8 - value(curlAt(i / w)) * (h - 16);
      if (i === 0) g.moveTo(i, y); else g.lineTo(i, y);
    }
    g.stroke();
  }
  g.strokeStyle = '#000';
  g.beginPath(); g.moveTo(t * w, 0); g.lineTo(t * w, h); g.stroke();
}

function showSchedule(t) {
  const p = curlAt(t);
  $('scrub').value = String(t);
  $('readout').textContent =
    `t ${t.toFixed(3)}  θ ${(p.theta * deg).toFixed(1)}°  Ay ${p.apexY.toFixed(2)}  ρ ${(p.rho * deg).toFixed(1)}°`;
  plotSchedule(t);
}

function showWhere() {
  const open = book.openPages;  // as the book's live region says them
  const [first, last] = [open[0], open[open.length - 1]];
  const count = book.pageCount;
  $('where').textContent = first === last ? `Page ${first + 1} of ${count}` : `Pages ${first + 1}–${last + 1} of ${count}`;
}

let reading = false;
function showReading(on) {
  reading = on;
  $('read-aloud').textContent = on ? 'Stop' : 'Read aloud';
}

// Reads the open book aloud (its narration where a page has one, else the browser's voice), or stops.
async function readAloud() {
  $('status').textContent = '';
  try {
    if (reading) book.readingAloud?.stop();
    else await book.readAloud();
  } catch (error) {
    showReading(false);
    if (error?.name !== 'AbortError') $('status').textContent = String(error?.message || error);  // not a Stop
  }
}

// Without WebGL2 (a browser or GPU without it; Chrome without a GPU) create() rejects, and its error's
// `fallback` is the book as still pages, already in the box: the demo keeps that one as its book, as a
// host does (docs/api.md, Errors), so its buttons, the page shown and Jump go on working.
async function createBook(container, options) {
  try {
    return await Flipbook.create(container, options);
  } catch (error) {
    if (!error.fallback) throw error;
    $('status').textContent = `${error.message}: the pages are shown still.`;
    return error.fallback;
  }
}

// Direction, schedule and speed are fixed for a book's life: changing one makes a new book at the page.
function buildBook(startPage) {
  building = building.then(async () => {
    book?.destroy();
    const source = $('source').value;
    const pdf = source === 'pdf';
    if (pdf) pdfBytes ??= await makeDemoPdf();
    const pages = source === 'html' ? magazinePages() : source === 'story' ? storyPages() : PAGES;
    book = await createBook($('book'), {
      ...(pdf ? { pdf: pdfBytes, controls: true } : { pages }),  // the PDF as a document: toolbar, thumbnails, search
      ...(source === 'story' ? { controls: true } : {}),  // the picture book with the toolbar (its Read button)
      startPage: source === 'drawn' ? startPage : 0,
      display: $('display').value,
      direction: $('direction').value,
      duration: Number($('speed').value) * 1000,
      schedule: $('schedule').value,
      lighting: $('lighting').checked,
      shadows: $('shadows').checked,
      gutter: $('gutter').checked,
      thickness: $('thickness').checked,
      sound: $('sound').checked,
      label: source === 'story' ? 'The Little Paper Boat, a picture book that reads itself' : 'The Curl of the Page, a demo book',
    });
    showReading(false);
    book.addEventListener('readaloudstart', () => showReading(true));
    book.addEventListener('readaloudend', () => showReading(false));
    book.addEventListener('turnstart', () => { document.body.dataset.state = 'turning'; });
    for (const type of ['turned', 'turncancel']) {
      book.addEventListener(type, () => {
        showWhere();
        if (!book.animating) document.body.dataset.state = 'open';
      });
    }
    book.addEventListener('resize', showWhere);
    book.addEventListener('pageerror', (e) => { $('status').textContent = `page ${e.detail.index + 1}: ${e.detail.error.message}`; });
    $('jump-page').max = String(book.pageCount);
    showWhere();
  });
  return building;
}

async function main() {
  engine = await loadEngine();
  const params = new URLSearchParams(location.search);
  const requested = Math.floor(Number(params.get('page') ?? 0)) || 0;
  await buildBook(Math.min(DEMO_PAGE_COUNT - 1, Math.max(0, requested)));
  const fixed = params.get('t');
  if (fixed !== null) book.previewTurn('forward', Math.min(1, Math.max(0, Number(fixed) || 0)));
  showSchedule(fixed === null ? 0 : Number(fixed));

  $('next').addEventListener('click', () => book.next());
  // A far page riffles there: several leaves at once, landing within RIFFLE_SPAN turns.
  $('jump').addEventListener('submit', (event) => {
    event.preventDefault();
    const page = Math.min(book.pageCount, Math.max(1, Math.floor(Number($('jump-page').value)) || 1));
    book.flip(page - 1).catch((error) => { $('status').textContent = error.message; });
  });
  $('prev').addEventListener('click', () => book.prev());
  $('read-aloud').addEventListener('click', readAloud);
  $('scrub').addEventListener('input', () => {
    const t = Number($('scrub').value);
    book.previewTurn('forward', t);
    showSchedule(t);
  });
  for (const id of ['source', 'direction', 'schedule', 'speed']) {
    $(id).addEventListener('change', () => buildBook(book.page));
  }
  $('schedule').addEventListener('change', () => showSchedule(Number($('scrub').value)));
  // Live changes wait for a book being built (a new source, say), or they would reach the one it replaces.
  const live = (options) => building.then(() => book.setOptions(options));
  $('display').addEventListener('change', () => live({ display: $('display').value }));
  // Live: the effects, the stacks' thickness and the page sound (it starts with the next gesture on the book).
  for (const id of ['lighting', 'shadows', 'gutter', 'thickness', 'sound']) {
    $(id).addEventListener('change', () => live({ [id]: $(id).checked }));
  }
  // For the console and scripts/measure-turn.mjs (which times the engine's own BookView).
  window.conecurlDemo = { engine, get book() { return book; }, storyPages };
  document.body.dataset.ready = 'true';
}

main().catch((error) => {
  $('status').textContent = String(error.message || error);
  document.body.dataset.error = String(error.message || error);
});
