// Demo wiring: a 40-page book drawn at run time, turned with buttons, keys or exact poses from the
// scrubber, and the schedule the engine computes (theta, Ay, rho over t) plotted beside it.
import { loadEngine } from '../src/engine.js';
import { BookView } from '../src/book-view.js';
import { DEMO_PAGE_COUNT, drawBookPage, isHardPage } from './book-pages.js';

const $ = (id) => document.getElementById(id);
const deg = 180 / Math.PI;
const PAGE_WINDOW = 4;  // pages kept as textures on each side of the open spread

let engine;
let view;

function plotSchedule(t) {
  const canvas = $('plot');
  const g = canvas.getContext('2d');
  const { width: w, height: h } = canvas;
  g.clearRect(0, 0, w, h);
  g.strokeStyle = '#ddd';
  for (const edge of [0.15, 0.4]) {
    g.beginPath(); g.moveTo(edge * w, 0); g.lineTo(edge * w, h); g.stroke();
  }
  const curves = [
    ['#c0392b', (p) => p.theta / (Math.PI / 2)],
    ['#2e86c1', (p) => -p.apexY / 15],
    ['#27ae60', (p) => p.rho / Math.PI],
  ];
  for (const [color, value] of curves) {
    g.strokeStyle = color;
    g.lineWidth = 2;
    g.beginPath();
    for (let i = 0; i <= w; i++) {
      const y = h - 8 - value(engine.curlAt(i / w)) * (h - 16);
      if (i === 0) g.moveTo(i, y); else g.lineTo(i, y);
    }
    g.stroke();
  }
  g.strokeStyle = '#000';
  g.beginPath(); g.moveTo(t * w, 0); g.lineTo(t * w, h); g.stroke();
}

function showSchedule(t) {
  const p = engine.curlAt(t);
  $('scrub').value = String(t);
  $('readout').textContent =
    `t ${t.toFixed(3)}  θ ${(p.theta * deg).toFixed(1)}°  Ay ${p.apexY.toFixed(2)}  ρ ${(p.rho * deg).toFixed(1)}°`;
  plotSchedule(t);
}

// Keeps textures only for the pages near the open spread: memory stays flat however long the book.
function loadPagesAround() {
  const first = view.book.firstVisiblePage();
  for (let page = 0; page < DEMO_PAGE_COUNT; page++) {
    const near = Math.abs(page - first) <= PAGE_WINDOW;
    const loaded = view.renderer.hasPageImage(page);
    if (near && !loaded) view.setPageImage(page, drawBookPage(page));
    else if (!near && loaded) view.releasePageImage(page);
  }
  const last = Math.min(DEMO_PAGE_COUNT - 1, first + (view.book.isSingle() || first === 0 ? 0 : 1));
  $('where').textContent = first === last ? `Page ${first + 1} of ${DEMO_PAGE_COUNT}`
    : `Pages ${first + 1}–${last + 1} of ${DEMO_PAGE_COUNT}`;
}

async function buildBook(page) {
  view?.destroy();
  view = await BookView.create($('book'), {
    engine,
    pageCount: DEMO_PAGE_COUNT,
    display: $('display').value,
    direction: $('direction').value,
    hardPages: Array.from({ length: DEMO_PAGE_COUNT }, (_, i) => i).filter(isHardPage),
    turnSeconds: Number($('speed').value),
    lighting: $('lighting').checked,
    shadows: $('shadows').checked,
    gutter: $('gutter').checked,
  });
  view.jumpTo(view.book.positionOfPage(page));
  loadPagesAround();
}

async function turn(direction) {
  const turning = direction === 'forward' ? view.next() : view.prev();
  loadPagesAround();
  document.body.dataset.state = 'turning';
  await turning;
  loadPagesAround();  // a turn that had to wait for a moving leaf starts only now
  if (!view.animating) document.body.dataset.state = 'open';
}

async function main() {
  engine = await loadEngine();
  const params = new URLSearchParams(location.search);
  const requested = Math.floor(Number(params.get('page') ?? 0)) || 0;
  await buildBook(Math.min(DEMO_PAGE_COUNT - 1, Math.max(0, requested)));
  const fixed = params.get('t');
  if (fixed !== null) view.showTurn('forward', Number(fixed));
  showSchedule(fixed === null ? 0 : Number(fixed));

  $('next').addEventListener('click', () => turn('forward'));
  $('prev').addEventListener('click', () => turn('backward'));
  $('book').addEventListener('keydown', (event) => {
    const forwardKeys = view.book.binding() === 'right' ? ['ArrowLeft'] : ['ArrowRight', 'ArrowDown'];
    const backwardKeys = view.book.binding() === 'right' ? ['ArrowRight'] : ['ArrowLeft', 'ArrowUp'];
    if (forwardKeys.includes(event.key) || event.key === 'PageDown') turn('forward');
    else if (backwardKeys.includes(event.key) || event.key === 'PageUp') turn('backward');
    else return;
    event.preventDefault();
  });
  $('scrub').addEventListener('input', () => {
    const t = Number($('scrub').value);
    view.showTurn('forward', t);
    showSchedule(t);
  });
  for (const id of ['display', 'direction', 'speed']) {
    $(id).addEventListener('change', () => buildBook(view.book.firstVisiblePage()));
  }
  for (const id of ['lighting', 'shadows', 'gutter']) {
    $(id).addEventListener('change', () => view.setOptions({ [id]: $(id).checked }));
  }
  // For the console and scripts/measure-turn.mjs.
  window.conecurlDemo = { engine, get view() { return view; } };
  document.body.dataset.ready = 'true';
}

main().catch((error) => {
  $('status').textContent = String(error.message || error);
  document.body.dataset.error = String(error.message || error);
});
