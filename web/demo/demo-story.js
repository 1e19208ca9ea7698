// The demo's picture book that reads itself: eight pages about a paper boat, drawn on canvases when the
// book wants them, each with narration (story-voice.js: a synthetic voice, as a WAV blob) whose words carry
// their times and their boxes on the page, measured from where the text is drawn.
import { narrate } from './story-voice.js';

const WIDTH = 768;
const HEIGHT = 960;
const FONT = '"DejaVu Sans", Verdana, Arial, sans-serif';
const INK = '#2b2a33';
const PAPER = '#fffaf0';

// Each page: its scene and the words it prints (and speaks). The cover's title is its text.
const STORY = [
  { scene: cover, text: 'The Little Paper Boat' },
  { scene: folding, text: 'Mia folded a boat out of paper. It had a bright red sail.' },
  { scene: stream, text: 'She put it on the stream. Off it went, bobbing and spinning!' },
  { scene: duck, text: 'The boat sailed past a duck. “Quack!” said the duck.' },
  { scene: bridge, text: 'Under the bridge it went, into the dark and out again.' },
  { scene: sunset, text: 'The stream grew wide and slow. The sun went down, orange and gold.' },
  { scene: sea, text: 'At last the boat reached the sea. Goodnight, little boat!' },
  { scene: back, text: 'The End.' },
];

const canvas = (w, h) => (typeof document !== 'undefined'
  ? Object.assign(document.createElement('canvas'), { width: w, height: h })
  : new OffscreenCanvas(w, h));

/** Where page `index`'s text goes: its font and each word's box (canvas pixels, baseline y). */
function layout(g, index) {
  const cover = index === 0;
  const size = cover ? 74 : index === STORY.length - 1 ? 84 : 48;
  const font = `${cover || index === STORY.length - 1 ? 'bold ' : ''}${size}px ${FONT}`;
  // The title over the cover's sky; a story page's words on the paper under its picture.
  const box = cover ? { x: 70, y: 50, w: WIDTH - 140, h: 260 }
    : index === STORY.length - 1 ? { x: 60, y: 150, w: WIDTH - 120, h: 200 }
      : { x: 48, y: 626, w: WIDTH - 96, h: 300 };
  g.font = font;
  const space = g.measureText(' ').width;
  const measured = (text) => {
    const m = g.measureText(text);
    return { text, width: m.width, ascent: m.fontBoundingBoxAscent ?? size * 0.93, descent: m.fontBoundingBoxDescent ?? size * 0.24 };
  };
  const widthOf = (line) => line.reduce((sum, w) => sum + w.width, 0) + space * (line.length - 1);
  // Each sentence on lines of its own; one too long for a line splits in two, after a comma where both
  // halves fit, else where they are most even.
  const sentences = [[]];
  STORY[index].text.split(' ').forEach((text, i, all) => {
    sentences.at(-1).push(measured(text));
    if (/[.!?][”"]?$/.test(text) && /^[“"A-Z]/.test(all[i + 1] ?? '')) sentences.push([]);  // "“Quack!” said" goes on
  });
  const lines = [];
  for (const words of sentences) {
    let best = [words], score = Infinity;
    for (let cut = 1; cut < words.length && widthOf(words) > box.w; cut++) {
      const split = [words.slice(0, cut), words.slice(cut)];
      const widest = Math.max(...split.map(widthOf));  // better after a comma, if both halves fit
      const cost = widest + (widest <= box.w && /,$/.test(words[cut - 1].text) ? 0 : box.w);
      if (cost < score) [best, score] = [split, cost];
    }
    lines.push(...best);
  }
  const lineHeight = size * 1.35;
  let baseline = box.y + (box.h - lines.length * lineHeight) / 2 + size * 1.02;
  for (const line of lines) {
    let x = box.x + (box.w - widthOf(line)) / 2;
    for (const word of line) { Object.assign(word, { x, y: baseline }); x += word.width + space; }
    baseline += lineHeight;
  }
  return { font, words: lines.flat() };
}

/** Page `index` drawn on a new canvas of WIDTH x HEIGHT. */
export function drawStoryPage(index) {
  const c = canvas(WIDTH, HEIGHT);
  const g = c.getContext('2d');
  g.fillStyle = PAPER;
  g.fillRect(0, 0, WIDTH, HEIGHT);
  STORY[index].scene(g);
  const { font, words } = layout(g, index);
  g.font = font;
  g.textBaseline = 'alphabetic';
  g.textAlign = 'left';
  g.fillStyle = INK;
  for (const word of words) g.fillText(word.text, word.x, word.y);
  return c;
}

let pages = null;
let measurer = null;
/**
 * The book's page entries, made once: { src: () => canvas, alt, hard, narration: { src: blob: URL of a
 * WAV, words: [{ start, end, text, rect: [x, y, width, height] as fractions of the page }] } }.
 */
export function storyPages() {
  if (pages) return pages;
  measurer ??= canvas(1, 1).getContext('2d');
  pages = STORY.map((page, index) => {
    const spoken = narrate(page.text.split(' '), { seed: index + 1 });
    const placed = layout(measurer, index).words;
    const words = spoken.words.map((word, i) => {
      const box = placed[i];
      const rect = [box.x / WIDTH, (box.y - box.ascent) / HEIGHT, box.width / WIDTH, (box.ascent + box.descent) / HEIGHT];
      return { ...word, rect: rect.map((v) => Math.round(v * 10000) / 10000) };
    });
    const src = URL.createObjectURL(new Blob([spoken.wav], { type: 'audio/wav' }));
    return {
      src: () => drawStoryPage(index),
      alt: index === 0 ? `Cover: ${page.text}` : index === STORY.length - 1 ? 'Back cover: The End.' : page.text,
      hard: index === 0 || index === STORY.length - 1,
      narration: { src, words },
    };
  });
  return pages;
}

// ---------------------------------------------------------------------------------------------------
// The pictures: shapes only. A story page's picture fills a rounded frame above its text.

function framed(g, paint) {
  g.save();
  g.beginPath();
  g.roundRect(40, 40, WIDTH - 80, 570, 28);
  g.clip();
  paint();
  g.restore();
  g.strokeStyle = 'rgba(60,50,40,0.25)';
  g.lineWidth = 3;
  g.beginPath();
  g.roundRect(40, 40, WIDTH - 80, 570, 28);
  g.stroke();
}

function fill(g, colour, shape) {
  g.fillStyle = colour;
  g.beginPath();
  shape();
  g.fill();
}

function sky(g, top, bottom, y0 = 0, y1 = HEIGHT) {
  const gradient = g.createLinearGradient(0, y0, 0, y1);
  gradient.addColorStop(0, top);
  gradient.addColorStop(1, bottom);
  g.fillStyle = gradient;
  g.fillRect(0, y0, WIDTH, y1 - y0);
}

function sun(g, x, y, r, colour = '#ffd54a') {
  g.strokeStyle = colour;
  g.lineWidth = 6;
  g.lineCap = 'round';
  g.beginPath();
  for (let k = 0; k < 12; k++) {
    const a = k * Math.PI / 6;
    g.moveTo(x + Math.cos(a) * r * 1.3, y + Math.sin(a) * r * 1.3);
    g.lineTo(x + Math.cos(a) * r * 1.6, y + Math.sin(a) * r * 1.6);
  }
  g.stroke();
  fill(g, colour, () => g.arc(x, y, r, 0, Math.PI * 2));
}

function hill(g, colour, x, y, rx, ry) {
  fill(g, colour, () => g.ellipse(x, y, rx, ry, 0, Math.PI, 0));
}

function cloud(g, x, y, s) {
  fill(g, 'rgba(255,255,255,0.9)', () => {
    for (const [dx, dy, r] of [[0, 0, 28], [32, -14, 34], [66, 0, 26], [30, 10, 28]]) {
      g.moveTo(x + (dx + r) * s, y + dy * s);
      g.arc(x + dx * s, y + dy * s, r * s, 0, Math.PI * 2);
    }
  });
}

function water(g, y, colour, light, y1 = 610) {
  fill(g, colour, () => g.rect(0, y, WIDTH, y1 - y));
  g.strokeStyle = light;
  g.lineWidth = 4;
  g.lineCap = 'round';
  for (let row = 0; row < 4; row++) {
    const wy = y + 28 + row * 38;
    if (wy > y1 - 10) break;
    g.beginPath();
    for (let x = (row % 2) * 60 + 30; x < WIDTH; x += 130) {
      g.moveTo(x, wy);
      g.quadraticCurveTo(x + 15, wy - 9, x + 30, wy);
      g.quadraticCurveTo(x + 45, wy + 9, x + 60, wy);
    }
    g.stroke();
  }
}

/** The paper boat: a folded hull and its red sail, `size` half its width, tilted by `tilt` radians. */
function boat(g, x, y, size, tilt = 0) {
  g.save();
  g.translate(x, y);
  g.rotate(tilt);
  g.scale(size, size);
  g.lineJoin = 'round';
  g.lineWidth = 3 / size;
  g.strokeStyle = '#5b6472';
  fill(g, '#e0453a', () => { g.moveTo(-0.5, 0); g.lineTo(0, -0.85); g.lineTo(0.5, 0); g.closePath(); });
  g.stroke();
  fill(g, '#fffdf6', () => { g.moveTo(-1, 0); g.lineTo(1, 0); g.lineTo(0.68, 0.4); g.lineTo(-0.68, 0.4); g.closePath(); });
  g.stroke();
  g.beginPath();
  g.moveTo(-0.84, 0.2); g.lineTo(0.84, 0.2);
  g.moveTo(0, -0.85); g.lineTo(0, 0);
  g.strokeStyle = 'rgba(91,100,114,0.45)';
  g.stroke();
  g.restore();
}

function cover(g) {
  sky(g, '#a9dcf5', '#e6f6fd', 0, 640);
  sun(g, 620, 380, 52);
  cloud(g, 90, 400, 1.1);
  hill(g, '#9bd487', 180, 700, 330, 210);
  hill(g, '#7cc36a', 620, 700, 300, 170);
  water(g, 640, '#4aa3d8', '#8fd0f2', HEIGHT);
  boat(g, 384, 700, 120, -0.05);
}

function folding(g) {
  framed(g, () => {
    sky(g, '#fde9c9', '#f7d7a8', 40, 610);
    fill(g, '#bfe4f6', () => g.rect(470, 90, 210, 190));  // a window, and the sun out of it
    sun(g, 590, 170, 34);
    g.strokeStyle = '#ffffff';
    g.lineWidth = 10;
    g.strokeRect(470, 90, 210, 190);
    g.beginPath(); g.moveTo(575, 90); g.lineTo(575, 280); g.moveTo(470, 185); g.lineTo(680, 185); g.stroke();
    fill(g, '#b57a4b', () => g.rect(40, 450, WIDTH - 80, 160));  // the table
    fill(g, '#9c6339', () => g.rect(40, 450, WIDTH - 80, 14));
    fill(g, '#ffffff', () => { g.moveTo(110, 520); g.lineTo(250, 500); g.lineTo(270, 560); g.lineTo(125, 585); g.closePath(); });
    boat(g, 420, 400, 150, 0.04);
  });
}

function stream(g) {
  framed(g, () => {
    sky(g, '#a9dcf5', '#e6f6fd', 40, 400);
    sun(g, 130, 130, 44);
    cloud(g, 470, 120, 1);
    fill(g, '#9bd487', () => g.ellipse(200, 420, 330, 190, 0, 0, Math.PI * 2));  // two hills, a meadow before them
    fill(g, '#7cc36a', () => g.ellipse(600, 430, 320, 150, 0, 0, Math.PI * 2));
    fill(g, '#8cd07a', () => g.ellipse(384, 700, 600, 330, 0, 0, Math.PI * 2));
    fill(g, '#4aa3d8', () => {  // the stream winds down toward us
      g.moveTo(352, 392); g.bezierCurveTo(250, 470, 560, 500, 420, 610); g.lineTo(700, 610);
      g.bezierCurveTo(760, 500, 420, 470, 372, 392); g.closePath();
    });
    for (const [fx, fy, c] of [[120, 500, '#f06292'], [180, 560, '#ffd54a'], [660, 470, '#ba68c8'], [90, 590, '#ffffff']]) {
      fill(g, c, () => g.arc(fx, fy, 12, 0, Math.PI * 2));
      fill(g, '#f9a825', () => g.arc(fx, fy, 5, 0, Math.PI * 2));
    }
    boat(g, 520, 545, 70, 0.25);
  });
}

function duck(g) {
  framed(g, () => {
    sky(g, '#a9dcf5', '#e6f6fd', 40, 300);
    hill(g, '#8fcf7a', 384, 330, 520, 120);
    fill(g, '#4f9c45', () => g.rect(40, 300, WIDTH - 80, 40));
    water(g, 330, '#4aa3d8', '#8fd0f2');
    fill(g, '#ffd23f', () => g.ellipse(480, 470, 95, 55, 0, 0, Math.PI * 2));  // the duck
    fill(g, '#ffd23f', () => g.arc(560, 380, 45, 0, Math.PI * 2));
    fill(g, '#f28c28', () => { g.moveTo(598, 372); g.lineTo(650, 386); g.lineTo(598, 398); g.closePath(); });
    fill(g, INK, () => g.arc(570, 368, 7, 0, Math.PI * 2));
    fill(g, '#f2bd1d', () => g.ellipse(460, 455, 45, 25, -0.3, 0, Math.PI * 2));
    boat(g, 200, 470, 80, -0.12);
  });
}

function bridge(g) {
  framed(g, () => {
    sky(g, '#a9dcf5', '#e6f6fd', 40, 420);
    cloud(g, 100, 110, 0.9);
    water(g, 420, '#3f95cc', '#86c8ee');
    fill(g, '#b9a58c', () => g.rect(40, 200, WIDTH - 80, 260));  // the bridge's stones, then its dark arch
    g.strokeStyle = '#8d7a63';
    g.lineWidth = 3;
    g.beginPath();
    for (let row = 0; row < 4; row++) {
      const y = 200 + row * 55;
      g.moveTo(40, y); g.lineTo(WIDTH - 40, y);
      for (let x = 40 + (row % 2) * 45; x < WIDTH; x += 90) { g.moveTo(x, y); g.lineTo(x, y + 55); }
    }
    g.stroke();
    fill(g, '#1e2a3a', () => { g.moveTo(190, 460); g.arc(384, 460, 194, Math.PI, 0); g.closePath(); });
    fill(g, '#a3917a', () => g.rect(40, 180, WIDTH - 80, 26));
    boat(g, 560, 500, 70, 0.1);
  });
}

function sunset(g) {
  framed(g, () => {
    sky(g, '#f6a25e', '#fde1a8', 40, 420);
    sun(g, 384, 400, 80, '#ff7a3d');
    hill(g, '#a07a9a', 130, 430, 240, 90);
    hill(g, '#8a6a8c', 660, 430, 220, 70);
    water(g, 420, '#e58a5a', '#ffc27a');
    boat(g, 280, 520, 85, -0.04);
  });
}

function sea(g) {
  framed(g, () => {
    sky(g, '#1d2750', '#3a4a86', 40, 420);
    fill(g, '#fff3c4', () => { g.arc(560, 160, 60, 0, Math.PI * 2); });
    fill(g, '#1d2750', () => { g.arc(590, 140, 56, 0, Math.PI * 2); });  // a crescent
    for (const [x, y] of [[120, 110], [230, 180], [330, 90], [420, 230], [160, 300], [690, 290], [700, 90], [300, 330]]) {
      fill(g, '#fff3c4', () => g.arc(x, y, 5, 0, Math.PI * 2));
    }
    water(g, 420, '#20477a', '#4c7bb8');
    boat(g, 384, 480, 95, 0.06);
  });
}

function back(g) {
  sky(g, '#1d2750', '#3a4a86', 0, HEIGHT);
  fill(g, PAPER, () => g.roundRect(90, 130, WIDTH - 180, 240, 30));
  for (const [x, y] of [[120, 440], [300, 520], [640, 470], [520, 600], [180, 640]]) {
    fill(g, '#fff3c4', () => g.arc(x, y, 5, 0, Math.PI * 2));
  }
  water(g, 720, '#20477a', '#4c7bb8', HEIGHT);
  boat(g, 384, 760, 70, 0);
}
