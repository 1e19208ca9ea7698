// Demo wiring: loads the engine, shows the generated page, animates turns, and plots the schedule
// the engine computes (theta, Ay, rho over t) with a marker at the frame on screen.
import { loadEngine } from '../src/engine.js';
import { CurlPageView } from '../src/curl-page-view.js';
import { drawFront, drawBack } from './page-art.js';

const $ = (id) => document.getElementById(id);
const deg = 180 / Math.PI;

function plotSchedule(engine, t) {
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

function showSchedule(engine, t) {
  const p = engine.curlAt(t);
  $('scrub').value = String(t);
  $('readout').textContent =
    `t ${t.toFixed(3)}  θ ${(p.theta * deg).toFixed(1)}°  Ay ${p.apexY.toFixed(2)}  ρ ${(p.rho * deg).toFixed(1)}°`;
  plotSchedule(engine, t);
}

function show(engine, view, t) {
  view.drawAt(t);
  showSchedule(engine, t);
}

async function main() {
  const engine = await loadEngine();
  const view = await CurlPageView.create($('book'), { engine });
  view.setImage('front', drawFront());
  view.setImage('back', drawBack());
  const fixed = new URLSearchParams(location.search).get('t');
  show(engine, view, fixed === null ? 0 : Number(fixed));

  $('turn').addEventListener('click', async () => {
    const to = view.t < 0.5 ? 1 : 0;
    $('turn').disabled = true;
    document.body.dataset.state = 'turning';
    await view.turnTo(to, { duration: Number($('duration').value), onFrame: (t) => showSchedule(engine, t) });
    $('turn').textContent = to === 1 ? 'Turn back' : 'Turn page';
    $('turn').disabled = false;
    document.body.dataset.state = to === 1 ? 'turned' : 'open';
  });
  $('scrub').addEventListener('input', () => show(engine, view, Number($('scrub').value)));
  $('shading').addEventListener('change', () => {
    view.renderer.setShading($('shading').checked);
    show(engine, view, view.t);
  });
  new ResizeObserver(() => show(engine, view, view.t)).observe($('book'));
  document.body.dataset.ready = 'true';
}

main().catch((error) => {
  $('status').textContent = String(error.message || error);
  document.body.dataset.error = String(error.message || error);
});
