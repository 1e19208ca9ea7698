// Draws every page of the demo's forty-page book on a 2D canvas at run time, so the demo ships no image
// files and the browser tests can tell the pages apart by the large page number each one carries.
import { mulberry32 } from './seeded-random.js';

/** Number of pages in the demo book (covers included). */
export const DEMO_PAGE_COUNT = 40;

const SERIF = '"DejaVu Serif", Georgia, "Times New Roman", serif';
const SANS = '"DejaVu Sans", Verdana, Arial, sans-serif';

const TITLE = 'The Curl of the Page';
const SUBTITLE = 'Paper, binding and the turning leaf';
const AUTHOR = 'E. M. Quire';
const PRESS = 'Hinge & Spine Press';

const PAPER = '#fbf7ee';
const INK = '#2a2622';
const ACCENT = '#8a3b26';
const BLUE = '#2f4f7a';
const CLOTH = '#1f3d4c';
const GOLD = '#d8b66a';
const CREAM = '#f3ead6';

// The book's structure: title page, contents, six chapters of six pages each, a colophon.
const TITLE_PAGE = 2;
const CONTENTS_PAGE = 3;
const FIRST_CHAPTER_PAGE = 4;
const CHAPTER_SPACING = 6;
const COLOPHON_PAGE = DEMO_PAGE_COUNT - 3;
const CHAPTERS = ['Of Grain and Fibre', 'The Folded Sheet', 'Sewing and Casing', 'A Leaf Begins to Turn',
  'The Cone Beneath the Curl', 'Light on the Curl'];
const NUMBER_WORDS = ['One', 'Two', 'Three', 'Four', 'Five', 'Six'];
const ROMAN = ['I', 'II', 'III', 'IV', 'V', 'VI'];

const PROSE = [
  'A sheet of paper begins as a slurry of fibres, mostly cellulose, suspended in water and lifted on a fine ' +
  'mesh. As the water drains away the fibres settle and knot together, and most of them come to lie in the ' +
  'direction the mesh was moving. That direction is the grain of the sheet. Fold a page along the grain and ' +
  'it yields at once; fold it across the grain and it cracks and resists. A binder learns to feel the grain ' +
  'with a fingertip long before picking up a knife.',
  'Books are not made one page at a time. A large sheet is printed on both sides, then folded in half, and ' +
  'in half again, and perhaps once more, until sixteen or thirty-two pages nest inside one another in the ' +
  'right order. This small bundle is called a gathering, or a signature. The printer arranges the pages on ' +
  'the flat sheet so that, after folding, page five follows page four, even though on the press they sat ' +
  'far apart and one of them upside down.',
  'The gatherings are stacked and sewn through their folds with linen thread, each one tied to its ' +
  'neighbours by a small kettle stitch at the head and at the tail. Glue is brushed across the back of the ' +
  'stack, a strip of open cloth is laid over it, and the spine is gently rounded with a hammer so that the ' +
  'fore edge becomes a shallow curve. Only then is the book block cased into its boards, which are cut a ' +
  'little larger than the pages so that the covers protect every edge.',
  'When you turn a page, the paper bends but it does not stretch. It is far easier to curve a sheet than to ' +
  'pull it longer, so the leaf chooses shapes that keep every line drawn on it the same length. ' +
  'Mathematicians call such a surface developable. A cylinder is one, and so is a cone; a sphere is not, ' +
  'which is why a map of the world can never lie flat without tearing or stretching somewhere.',
  'Watch a reader lift the bottom corner of a page. The corner rises first, and the curl that follows it is ' +
  'not a cylinder at all but something closer to a cone whose point rests on the line of the spine. As the ' +
  'hand moves across, the cone grows narrower, its tip slides along the binding, and more and more of the ' +
  'page wraps around it. The paper that still lies flat stays flat, and the paper that has left the cone ' +
  'stands up as a straight, stiff plane.',
  'Light tells the eye most of what it knows about this shape. The inside of the curl falls into soft ' +
  'shadow while the outside catches the lamp, and a thin bright line runs along the crest where the surface ' +
  'faces the light most directly. Where the sheet is thin, the print on the far side glows faintly through, ' +
  'reversed, like a word seen in a mirror. These small effects are what make a turning page look like ' +
  'paper rather than painted card.',
  'A heavy cover behaves differently. The board is too stiff to curl, so it swings about its hinge as a ' +
  'single flat plane, and the first leaf of paper is pulled along behind it. Endpapers, pasted half to the ' +
  'board and half to the first gathering, take the strain at that joint. They are often marbled or printed ' +
  'with a quiet pattern, partly for beauty and partly to hide the turned-in edges of the cloth.',
  'At the end of the turn the page settles onto the growing stack on the other side. The cone has opened ' +
  'out into a flat sheet again, and nothing about the paper remembers that it was ever curved. The reader\'s ' +
  'eye has already moved to the top of the next page, and the whole small drama of grain, fold, hinge and ' +
  'curl has taken less than a second.',
];
const PARAS = PROSE.map((p) => p.split(' '));

const FIGURES = [
  { draw: figCone,
    caption: 'The leaf wraps a cone whose apex rests on the line of the spine; seen from the front and in section.' },
  { draw: figBook, caption: 'An open book, one leaf in the middle of its turn.' },
  { draw: figLandscape, caption: 'The view from the bindery window, printed across the grain.' },
  { draw: figChart, caption: 'Cone angle and curl radius over the course of one turn.' },
  { draw: figOctavo, caption: 'One side of a sheet printed in octavo: after three folds the pages fall in order.' },
];

/**
 * Draws page `index` (0-based; 0 = front cover, DEMO_PAGE_COUNT - 1 = back cover) of the demo book
 * into a new canvas of width x height pixels (default 768 x 960) and returns it.
 * Every page shows its page number legibly (a large number in a consistent place is fine, e.g. the outer
 * bottom corner) so tests can see which page is where; interior pages look like a real book:
 * a running head, a chapter heading on chapter openers (every ~6 pages), justified-looking paragraphs
 * of readable English prose (write a few hundred words of original text about paper, bookbinding and
 * how a page curls, split into paragraphs; reuse across pages with different starting offsets), and a
 * drawing on some pages (e.g. a diagram of a cone with a page wrapped around it, a sketch of a book,
 * a simple landscape, a chart) drawn with canvas paths. Even (left) and odd (right) pages mirror their
 * margins and put the number at the outer corner, as printed books do. The covers are different:
 * a full-bleed coloured cover with the title "The Curl of the Page", a subtitle, an author line, and
 * a simple ornament; the back cover a short blurb and a barcode-like pattern.
 *
 * The printed number is index + 1 (so the front cover is 1), drawn at the outer bottom corner of every
 * page: bottom right on right-hand pages (odd numbers, even indices), bottom left on left-hand ones.
 */
export function drawBookPage(index, width = 768, height = 960) {
  if (!Number.isInteger(index) || index < 0 || index >= DEMO_PAGE_COUNT) {
    throw new RangeError(`page index ${index} is outside 0..${DEMO_PAGE_COUNT - 1}`);
  }
  const W = Math.max(1, Math.round(width));
  const H = Math.max(1, Math.round(height));
  const canvas = typeof document !== 'undefined'
    ? Object.assign(document.createElement('canvas'), { width: W, height: H })
    : new OffscreenCanvas(W, H);
  const g = canvas.getContext('2d');
  const f = frame(index, W, H);
  if (index === 0) frontCover(g, f);
  else if (index === DEMO_PAGE_COUNT - 1) backCover(g, f);
  else if (index === 1 || index === DEMO_PAGE_COUNT - 2) endpaper(g, f);
  else if (index === TITLE_PAGE) titlePage(g, f);
  else if (index === CONTENTS_PAGE) contentsPage(g, f);
  else if (index === COLOPHON_PAGE) colophonPage(g, f);
  else textPage(g, f);
  return canvas;
}

/** Whether page `index` is a hard page (the covers, and the inside of each cover: 0, 1, count-2, count-1). */
export function isHardPage(index) {
  return index === 0 || index === 1 || index === DEMO_PAGE_COUNT - 2 || index === DEMO_PAGE_COUNT - 1;
}

// ---------------------------------------------------------------------------------------------------
// Page geometry and small helpers.

function frame(index, W, H) {
  const s = Math.min(W / 768, H / 960);
  const left = index % 2 === 1;  // printed number index + 1 is even: a left-hand (verso) page
  const inner = 0.125 * W;
  const outer = 0.09 * W;
  const x0 = left ? outer : inner;
  const x1 = W - (left ? inner : outer);
  return { index, number: index + 1, W, H, s, left, x0, x1, width: x1 - x0, top: 0.115 * H, bottom: 0.88 * H };
}

const widthCache = new Map();
function wordWidth(g, font, word) {
  const key = font + '\u0001' + word;
  let w = widthCache.get(key);
  if (w === undefined) {
    if (widthCache.size > 20000) widthCache.clear();
    g.font = font;
    w = g.measureText(word).width;
    widthCache.set(key, w);
  }
  return w;
}

function setSpacing(g, px) {
  if ('letterSpacing' in g) g.letterSpacing = `${px}px`;
}

/** Sets `template(size)` as the font, shrunk so that `text` fits in maxWidth; returns the size used. */
function fitFont(g, text, maxWidth, size, template) {
  g.font = template(size);
  const w = g.measureText(text).width;
  if (w > maxWidth) {
    size = Math.max(1, Math.floor(size * maxWidth / w));
    g.font = template(size);
  }
  return size;
}

/** Greedy word wrap: `text` in lines no wider than `maxWidth` as `measure(line)` sees it (also demo-pdf.js). */
export function wrapWords(text, maxWidth, measure) {
  const lines = [];
  let line = '';
  for (const word of text.split(' ')) {
    const next = line ? `${line} ${word}` : word;
    if (line && measure(next) > maxWidth) {
      lines.push(line);
      line = word;
    } else {
      line = next;
    }
  }
  if (line) lines.push(line);
  return lines;
}

/** Greedy word wrap of `text` in the canvas's current font. */
function wrap(g, text, maxWidth) {
  return wrapWords(text, maxWidth, (line) => g.measureText(line).width);
}

/** Fills `text` with the current alignment, never wider than maxWidth (fillText squeezes it if needed). */
function text(g, str, x, y, maxWidth) {
  g.fillText(str, x, y, Math.max(1, maxWidth));
}

function paper(g, f) {
  const { W, H, s } = f;
  g.fillStyle = PAPER;
  g.fillRect(0, 0, W, H);
  // A faint shadow toward the spine, as the page dips into the gutter.
  const spineX = f.left ? W : 0;
  const shade = g.createLinearGradient(spineX, 0, spineX + (f.left ? -1 : 1) * 0.07 * W, 0);
  shade.addColorStop(0, 'rgba(90,70,40,0.10)');
  shade.addColorStop(1, 'rgba(90,70,40,0)');
  g.fillStyle = shade;
  g.fillRect(f.left ? W - 0.07 * W : 0, 0, 0.07 * W, H);
  // A few paper fibres, the same on every print of this page.
  const rnd = mulberry32(f.index * 2654435761 + 99);
  g.strokeStyle = 'rgba(120,100,70,0.07)';
  g.lineWidth = 1 * s;
  g.beginPath();
  for (let i = 0; i < 70; i++) {
    const x = rnd() * W, y = rnd() * H, a = rnd() * Math.PI, l = (6 + rnd() * 14) * s;
    g.moveTo(x, y);
    const ex = x + Math.cos(a) * l, ey = y + Math.sin(a) * l;
    g.quadraticCurveTo((x + ex) / 2 + 3 * s, (y + ey) / 2, ex, ey);
  }
  g.stroke();
  g.strokeStyle = 'rgba(0,0,0,0.07)';
  g.lineWidth = 2 * s;
  g.strokeRect(s, s, W - 2 * s, H - 2 * s);
}

/** The page number, large, at the outer bottom corner; `plate` draws a background label behind it. */
function folio(g, f, color = INK, plate = null) {
  const size = Math.round(40 * f.s);
  g.font = `${size}px ${SERIF}`;
  g.textBaseline = 'alphabetic';
  const label = String(f.number);
  const tw = g.measureText(label).width;
  const y = f.H - 0.052 * f.H;
  const x = f.left ? f.x0 : f.x1;
  if (plate) {
    const pad = 10 * f.s;
    const bx = f.left ? x - pad : x - tw - pad;
    g.fillStyle = plate.fill;
    roundRect(g, bx, y - size * 0.86, tw + 2 * pad, size * 1.1, 6 * f.s);
    g.fill();
    if (plate.stroke) {
      g.strokeStyle = plate.stroke;
      g.lineWidth = 1.5 * f.s;
      g.stroke();
    }
  }
  g.fillStyle = color;
  g.textAlign = f.left ? 'left' : 'right';
  g.fillText(label, x, y);
  g.textAlign = 'left';
}

function roundRect(g, x, y, w, h, r) {
  g.beginPath();
  g.moveTo(x + r, y);
  g.arcTo(x + w, y, x + w, y + h, r);
  g.arcTo(x + w, y + h, x, y + h, r);
  g.arcTo(x, y + h, x, y, r);
  g.arcTo(x, y, x + w, y, r);
  g.closePath();
}

/** A thin rule with a diamond in the middle. */
function ruleOrnament(g, cx, y, half, color, s) {
  g.strokeStyle = color;
  g.fillStyle = color;
  g.lineWidth = 1.5 * s;
  const d = 6 * s;
  g.beginPath();
  g.moveTo(cx - half, y); g.lineTo(cx - d * 2, y);
  g.moveTo(cx + d * 2, y); g.lineTo(cx + half, y);
  g.stroke();
  g.beginPath();
  g.moveTo(cx, y - d); g.lineTo(cx + d, y); g.lineTo(cx, y + d); g.lineTo(cx - d, y);
  g.closePath();
  g.fill();
}

/** Leaves fanned about a point at the spine, each bending a little: the book's emblem. */
function fanOrnament(g, cx, cy, size, color, s) {
  const px = cx, py = cy + size * 0.45;
  g.strokeStyle = color;
  g.lineWidth = 2 * s;
  g.lineCap = 'round';
  g.beginPath();
  for (let k = 0; k < 9; k++) {
    const a = (-80 + k * 20) * Math.PI / 180;
    const tipX = px + size * Math.sin(a), tipY = py - size * Math.cos(a) * 0.95;
    const ca = a + 0.32;
    g.moveTo(px, py);
    g.quadraticCurveTo(px + size * 0.62 * Math.sin(ca), py - size * 0.62 * Math.cos(ca), tipX, tipY);
  }
  g.stroke();
  g.beginPath();
  g.arc(px, py, size * 0.55, Math.PI * 1.1, Math.PI * 1.9);
  g.stroke();
  g.fillStyle = color;
  g.beginPath();
  g.arc(px, py, 4 * s, 0, Math.PI * 2);
  g.fill();
  g.lineCap = 'butt';
}

// ---------------------------------------------------------------------------------------------------
// Text pages.

function chapterOf(index) {
  if (index < FIRST_CHAPTER_PAGE || index >= COLOPHON_PAGE) return -1;
  return Math.min(CHAPTERS.length - 1, Math.floor((index - FIRST_CHAPTER_PAGE) / CHAPTER_SPACING));
}

function isChapterOpener(index) {
  const c = chapterOf(index);
  return c >= 0 && index === FIRST_CHAPTER_PAGE + c * CHAPTER_SPACING;
}

function hasFigure(index) {
  return chapterOf(index) >= 0 && !isChapterOpener(index) && index % 3 === 0;
}

function figureNumber(index) {
  let n = 0;
  for (let i = 0; i <= index; i++) if (hasFigure(i)) n++;
  return n;
}

function textPage(g, f) {
  paper(g, f);
  const chapter = chapterOf(f.index);
  const rnd = mulberry32(f.index * 7919 + 17);
  let y = f.top;
  let para, word, dropCap = false;
  if (isChapterOpener(f.index)) {
    y = chapterHeading(g, f, chapter);
    para = chapter % PARAS.length;
    word = 0;
    dropCap = true;
  } else {
    runningHead(g, f, chapter);
    para = (f.index * 3) % PARAS.length;
    word = Math.floor(rnd() * PARAS[para].length * 0.6);
  }
  let band = null;
  if (hasFigure(f.index)) {
    const n = figureNumber(f.index);
    const atTop = n % 2 === 0;
    const figTop = atTop ? f.top : f.top + 0.3 * (f.bottom - f.top);
    band = figure(g, f, n, figTop);
  }
  flowText(g, f, { y, para, word, dropCap, band });
  folio(g, f);
}

function runningHead(g, f, chapter) {
  const { s } = f;
  const cx = (f.x0 + f.x1) / 2;
  const y = f.top - 0.05 * f.H;
  g.fillStyle = '#6b6259';
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  if (f.left) {
    setSpacing(g, 3 * s);
    fitFont(g, TITLE.toUpperCase(), f.width, Math.round(14 * s), (px) => `${px}px ${SANS}`);
    text(g, TITLE.toUpperCase(), cx, y, f.width);
    setSpacing(g, 0);
  } else {
    const head = chapter >= 0 ? CHAPTERS[chapter] : TITLE;
    fitFont(g, head, f.width, Math.round(18 * s), (px) => `italic ${px}px ${SERIF}`);
    text(g, head, cx, y, f.width);
  }
  g.textAlign = 'left';
  g.strokeStyle = 'rgba(60,50,40,0.35)';
  g.lineWidth = 1 * s;
  g.beginPath();
  g.moveTo(f.x0, y + 13 * s);
  g.lineTo(f.x1, y + 13 * s);
  g.stroke();
}

/** Draws a chapter opener's heading and returns where its text starts. */
function chapterHeading(g, f, chapter) {
  const { s } = f;
  const cx = (f.x0 + f.x1) / 2;
  const y1 = f.top + 0.07 * f.H;
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  g.fillStyle = ACCENT;
  setSpacing(g, 5 * s);
  const label = `CHAPTER ${NUMBER_WORDS[chapter].toUpperCase()}`;
  fitFont(g, label, f.width, Math.round(16 * s), (px) => `${px}px ${SANS}`);
  text(g, label, cx, y1, f.width);
  setSpacing(g, 0);
  const y2 = y1 + 0.075 * f.H;
  g.fillStyle = INK;
  fitFont(g, CHAPTERS[chapter], f.width, Math.round(38 * s), (px) => `bold ${px}px ${SERIF}`);
  text(g, CHAPTERS[chapter], cx, y2, f.width);
  g.textAlign = 'left';
  ruleOrnament(g, cx, y2 + 0.045 * f.H, Math.min(0.18 * f.W, f.width / 2), ACCENT, s);
  return y2 + 0.1 * f.H;
}

/**
 * Sets paragraphs from PROSE on a baseline grid from `y` down to the bottom margin, starting at word `word`
 * of paragraph `para` and cycling through the paragraphs; lines are justified except the last of each
 * paragraph, lines overlapping `band` ([top, bottom]) are skipped, and `dropCap` opens with a 3-line initial.
 */
function flowText(g, f, { y, para, word, dropCap, band }) {
  const { s } = f;
  const fs = 20 * s;
  const lh = 30 * s;
  const font = `${fs}px ${SERIF}`;
  const space = wordWidth(g, font, ' ');
  const indentW = fs * 1.6;
  const slots = [];
  for (let base = y + fs * 0.8; base + fs * 0.25 <= f.bottom; base += lh) {
    if (band && base + fs * 0.3 > band[0] && base - fs * 0.8 < band[1]) continue;
    slots.push({ x: f.x0, w: f.width, y: base });
  }
  let p = para;
  let words = PARAS[p];
  let wi = word;
  let noIndent = true;  // chapter openers and continued paragraphs start flush left
  if (dropCap && slots.length >= 3) {
    const first = words[0];
    const capSize = (2 * lh + 0.73 * fs) / 0.73;
    g.font = `bold ${capSize}px ${SERIF}`;
    g.fillStyle = ACCENT;
    g.textAlign = 'left';
    const letterW = g.measureText(first[0]).width;
    text(g, first[0], f.x0, slots[2].y, f.width);
    const shift = letterW + fs * 0.45;
    for (let k = 0; k < 3; k++) { slots[k].x += shift; slots[k].w -= shift; }
    const rest = first.slice(1);
    words = rest ? [rest, ...words.slice(1)] : words.slice(1);
  }
  g.font = font;
  g.fillStyle = INK;
  g.textAlign = 'left';
  g.textBaseline = 'alphabetic';
  for (const slot of slots) {
    const indent = wi === 0 && !noIndent ? indentW : 0;
    noIndent = false;
    const line = [];
    let natural = 0;
    while (wi < words.length) {
      const ww = wordWidth(g, font, words[wi]);
      const add = line.length ? space + ww : ww;
      if (line.length && indent + natural + add > slot.w) break;
      line.push(words[wi]);
      natural += add;
      wi++;
    }
    const ends = wi >= words.length;
    setLine(g, font, line, slot.x + indent, slot.y, slot.w - indent, natural, !ends, space);
    if (ends) {
      p = (p + 1) % PARAS.length;
      words = PARAS[p];
      wi = 0;
    }
  }
}

function setLine(g, font, line, x, y, width, natural, justify, space) {
  const gaps = line.length - 1;
  const gap = gaps > 0 ? space + (width - natural) / gaps : space;
  if (!justify || gaps === 0 || gap > space * 3.5) {
    text(g, line.join(' '), x, y, width);
    return;
  }
  if ('wordSpacing' in g) {              // one call per line where the canvas can space words itself
    g.wordSpacing = `${gap - space}px`;
    g.fillText(line.join(' '), x, y, width + 0.5);
    g.wordSpacing = '0px';
    return;
  }
  let cx = x;
  for (let k = 0; k < line.length; k++) {
    const ww = wordWidth(g, font, line[k]);
    if (k === gaps) {
      g.textAlign = 'right';
      g.fillText(line[k], x + width, y, ww);  // flush with the right margin
      g.textAlign = 'left';
    } else {
      g.fillText(line[k], cx, y, ww);
    }
    cx += ww + gap;
  }
}

/** Draws figure n with its caption from `top`; returns the band [top, bottom] the text must avoid. */
function figure(g, f, n, top) {
  const { s } = f;
  const fig = FIGURES[(n - 1) % FIGURES.length];
  const h = 0.28 * f.H;
  g.save();
  g.beginPath();
  g.rect(f.x0, top, f.width, h);
  g.clip();
  fig.draw(g, f.x0, top, f.width, h, s, mulberry32(f.index * 31 + n));
  g.restore();
  const capSize = Math.round(16 * s);
  g.font = `italic ${capSize}px ${SERIF}`;
  g.fillStyle = '#4a433c';
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  const lines = wrap(g, `Figure ${n}. ${fig.caption}`, f.width * 0.9);
  let y = top + h + 26 * s;
  for (const line of lines) {
    text(g, line, (f.x0 + f.x1) / 2, y, f.width);
    y += 22 * s;
  }
  g.textAlign = 'left';
  return [top - 12 * s, y + 4 * s];
}

// ---------------------------------------------------------------------------------------------------
// Figures: each draws into the box (x, y, w, h), which is clipped.

function label(g, str, x, y, s, align = 'left', size = 13) {
  g.font = `italic ${Math.round(size * s)}px ${SANS}`;
  g.textAlign = align;
  g.fillText(str, x, y);
  g.textAlign = 'left';
}

function figCone(g, x, y, w, h, s) {
  g.lineJoin = 'round';
  // Front view: the page, spine on the left, its lower outer corner lifted over a cone.
  const pw = w * 0.56;
  const sx = x + pw * 0.16, pr = x + pw * 0.95;
  const pt = y + h * 0.06, pb = y + h * 0.7;
  const A = [sx, y + h * 0.95];                         // apex, on the spine line below the page
  const B = [sx + (pr - sx) * 0.45, pb];                // where the contact line meets the bottom edge
  const t = (pr - A[0]) / (B[0] - A[0]);
  const C = [pr, A[1] + (B[1] - A[1]) * t];             // ... and the outer edge
  // Flat part of the page, with lines of text.
  g.beginPath();
  g.moveTo(sx, pt); g.lineTo(pr, pt); g.lineTo(C[0], C[1]); g.lineTo(B[0], B[1]); g.lineTo(sx, pb);
  g.closePath();
  g.fillStyle = '#ffffff';
  g.fill();
  g.save();
  g.clip();
  g.strokeStyle = 'rgba(60,60,60,0.28)';
  g.lineWidth = 2 * s;
  g.beginPath();
  for (let ly = pt + 14 * s; ly < pb - 6 * s; ly += 10 * s) { g.moveTo(sx + 12 * s, ly); g.lineTo(pr - 12 * s, ly); }
  g.stroke();
  g.restore();
  g.strokeStyle = INK;
  g.lineWidth = 2 * s;
  g.beginPath();
  g.moveTo(sx, pt); g.lineTo(pr, pt); g.lineTo(C[0], C[1]);
  g.moveTo(B[0], B[1]); g.lineTo(sx, pb);
  g.stroke();
  // The spine line and its extension to the apex.
  g.strokeStyle = BLUE;
  g.lineWidth = 2.5 * s;
  g.beginPath(); g.moveTo(sx, pt - 4 * s); g.lineTo(sx, pb); g.stroke();
  g.setLineDash([5 * s, 4 * s]);
  g.lineWidth = 1.5 * s;
  g.beginPath(); g.moveTo(sx, pb); g.lineTo(A[0], A[1]); g.stroke();
  // The cone: contact line, far generator and the circle where the corner wraps it.
  const M = [(B[0] + C[0]) / 2, (B[1] + C[1]) / 2];
  const len = Math.hypot(M[0] - A[0], M[1] - A[1]);
  const u = [(M[0] - A[0]) / len, (M[1] - A[1]) / len];
  const nrm = [-u[1], u[0]];                            // points toward the lifted corner
  const r = 0.09 * h;
  const E = [M[0] + nrm[0] * r, M[1] + nrm[1] * r];
  g.beginPath();
  g.moveTo(A[0], A[1]); g.lineTo(C[0] + nrm[0] * 2 * r, C[1] + nrm[1] * 2 * r);
  g.moveTo(A[0], A[1]); g.lineTo(C[0], C[1]);
  g.stroke();
  g.beginPath();
  g.ellipse(E[0], E[1], r * 0.35, r, Math.atan2(u[1], u[0]), 0, Math.PI * 2);
  g.stroke();
  g.setLineDash([]);
  // The lifted corner: the back of the leaf, shortened as it wraps the cone.
  const corner = [pr, pb];
  const dot = (corner[0] - B[0]) * u[0] + (corner[1] - B[1]) * u[1];
  const foot = [B[0] + u[0] * dot, B[1] + u[1] * dot];
  const refl = [2 * foot[0] - corner[0], 2 * foot[1] - corner[1]];
  const K = [foot[0] + (refl[0] - foot[0]) * 0.7, foot[1] + (refl[1] - foot[1]) * 0.7];
  const grad = g.createLinearGradient(foot[0], foot[1], K[0], K[1]);
  grad.addColorStop(0, '#ffffff');
  grad.addColorStop(0.5, '#e9e4da');
  grad.addColorStop(1, '#c9c2b5');
  g.beginPath();
  g.moveTo(C[0], C[1]);
  g.quadraticCurveTo((C[0] + K[0]) / 2 - nrm[0] * 6 * s, (C[1] + K[1]) / 2 - nrm[1] * 6 * s, K[0], K[1]);
  g.quadraticCurveTo((B[0] + K[0]) / 2 - nrm[0] * 6 * s, (B[1] + K[1]) / 2 - nrm[1] * 6 * s, B[0], B[1]);
  g.quadraticCurveTo(M[0] + nrm[0] * 8 * s, M[1] + nrm[1] * 8 * s, C[0], C[1]);
  g.closePath();
  g.fillStyle = grad;
  g.fill();
  g.strokeStyle = INK;
  g.lineWidth = 2 * s;
  g.stroke();
  // Angle at the apex between the spine and the cone's axis.
  g.strokeStyle = ACCENT;
  g.lineWidth = 1.5 * s;
  const ar = 0.17 * h;
  g.beginPath();
  g.arc(A[0], A[1], ar, -Math.PI / 2, Math.atan2(u[1], u[0]));
  g.stroke();
  g.fillStyle = ACCENT;
  const mid = (-Math.PI / 2 + Math.atan2(u[1], u[0])) / 2;
  g.font = `italic ${Math.round(16 * s)}px ${SERIF}`;
  g.fillText('θ', A[0] + Math.cos(mid) * (ar + 5 * s), A[1] + Math.sin(mid) * (ar + 5 * s) + 4 * s);
  g.fillStyle = '#3a3632';
  label(g, 'apex', A[0] - 6 * s, A[1] + 2 * s, s, 'right');
  g.save();
  g.translate(sx - 7 * s, (pt + pb) / 2);
  g.rotate(-Math.PI / 2);
  label(g, 'spine', 0, 0, s, 'center');
  g.restore();
  label(g, 'cone', E[0] + 10 * s, E[1] + r + 16 * s, s);

  // Section: the page lies flat, wraps the cone and leaves it as a straight plane.
  const qx0 = x + w * 0.62, qx1 = x + w;
  const qw = qx1 - qx0;
  const yb = y + h * 0.8;
  const rr = 0.15 * h;
  const cx = qx0 + qw * 0.6, cy = yb - rr;
  g.strokeStyle = BLUE;
  g.lineWidth = 1.5 * s;
  g.setLineDash([5 * s, 4 * s]);
  g.beginPath(); g.arc(cx, cy, rr, 0, Math.PI * 2); g.stroke();
  g.beginPath(); g.moveTo(qx0, yb + 12 * s); g.lineTo(qx1, yb + 12 * s); g.stroke();
  g.setLineDash([]);
  const phi = 160 * Math.PI / 180;
  const e = Math.PI / 2 - phi;
  const P = [cx + rr * Math.cos(e), cy + rr * Math.sin(e)];
  const dir = [Math.sin(e), -Math.cos(e)];
  const L = Math.min(qw * 0.5, (P[0] - qx0 - 8 * s) / -dir[0]);
  g.strokeStyle = INK;
  g.lineWidth = 3 * s;
  g.lineCap = 'round';
  g.beginPath();
  g.moveTo(qx0 + 4 * s, yb);
  g.lineTo(cx, yb);
  g.arc(cx, cy, rr, Math.PI / 2, e, true);
  g.lineTo(P[0] + dir[0] * L, P[1] + dir[1] * L);
  g.stroke();
  g.lineCap = 'butt';
  g.fillStyle = '#3a3632';
  label(g, 'flat', qx0 + 6 * s, yb + 30 * s, s);
  label(g, 'on the cone', cx, yb + 30 * s, s, 'center');
  label(g, 'lifted', P[0] + dir[0] * L, P[1] + dir[1] * L - 10 * s, s);
  label(g, 'section', (qx0 + qx1) / 2, y + h * 0.12, s, 'center', 14);
}

function figBook(g, x, y, w, h, s) {
  const cx = x + w / 2;
  const pw = Math.min(w * 0.38, h * 1.0);
  const ty = y + h * 0.3, by = y + h * 0.86;
  const dip = 10 * s, bow = 16 * s;
  // Boards under the block.
  g.fillStyle = '#6b2a1c';
  g.beginPath();
  g.moveTo(cx - pw - 10 * s, ty - 4 * s);
  g.lineTo(cx - pw - 10 * s, by + 12 * s);
  g.quadraticCurveTo(cx - pw * 0.45, by - bow + 14 * s, cx, by + dip + 12 * s);
  g.quadraticCurveTo(cx + pw * 0.45, by - bow + 14 * s, cx + pw + 10 * s, by + 12 * s);
  g.lineTo(cx + pw + 10 * s, ty - 4 * s);
  g.closePath();
  g.fill();
  const page = (side, inset) => {
    const ox = cx + side * (pw - inset);
    g.beginPath();
    g.moveTo(cx, ty + dip);
    g.quadraticCurveTo(cx + side * pw * 0.45, ty - bow, ox, ty + inset * 0.3);
    g.lineTo(ox, by + inset * 0.3);
    g.quadraticCurveTo(cx + side * pw * 0.45, by - bow, cx, by + dip);
    g.closePath();
  };
  g.lineWidth = 1.5 * s;
  g.strokeStyle = '#5a4a3a';
  for (const side of [-1, 1]) {
    for (let k = 3; k >= 0; k--) {        // the stack of leaves under the open pair
      g.save();
      g.translate(0, k * 3 * s);
      page(side, -k * 2 * s);
      g.fillStyle = k ? '#efe8da' : '#fffdf7';
      g.fill();
      g.stroke();
      g.restore();
    }
    // Lines of text following the curve of the page.
    g.strokeStyle = 'rgba(60,55,50,0.35)';
    g.lineWidth = 2 * s;
    g.beginPath();
    for (let k = 1; k <= 9; k++) {
      const f = k / 10.5;
      const ly = ty + (by - ty) * f;
      const a = cx + side * pw * 0.9, b = cx + side * pw * 0.12;
      g.moveTo(a, ly + 0.0);
      g.quadraticCurveTo(cx + side * pw * 0.45, ly - bow * 0.9, b, ly + dip * 0.4);
    }
    g.stroke();
    g.strokeStyle = '#5a4a3a';
    g.lineWidth = 1.5 * s;
  }
  // The leaf in mid-turn, standing up from the spine and leaning left.
  const fx = cx - pw * 0.42, lift = h * 0.2;
  const grad = g.createLinearGradient(cx, 0, fx, 0);
  grad.addColorStop(0, '#d9d2c4');
  grad.addColorStop(0.6, '#fffdf7');
  grad.addColorStop(1, '#ece6da');
  g.beginPath();
  g.moveTo(cx, ty + dip);
  g.quadraticCurveTo(cx - pw * 0.02, ty - lift * 1.1, fx, ty - lift);
  g.lineTo(fx, by - lift);
  g.quadraticCurveTo(cx - pw * 0.02, by - lift * 1.1, cx, by + dip);
  g.closePath();
  g.fillStyle = grad;
  g.fill();
  g.stroke();
  // An arrow showing which way the leaf is going.
  const ay = ty - lift - 14 * s;
  g.strokeStyle = ACCENT;
  g.lineWidth = 1.8 * s;
  g.beginPath();
  g.moveTo(cx - pw * 0.02, ay + 4 * s);
  g.quadraticCurveTo(fx + pw * 0.05, ay - 12 * s, fx - pw * 0.16, ay + 16 * s);
  g.moveTo(fx - pw * 0.16 + 2 * s, ay + 5 * s);
  g.lineTo(fx - pw * 0.16, ay + 16 * s);
  g.lineTo(fx - pw * 0.16 + 11 * s, ay + 15 * s);
  g.stroke();
}

function figLandscape(g, x, y, w, h, s, rnd) {
  const sky = g.createLinearGradient(0, y, 0, y + h);
  sky.addColorStop(0, '#a9cbe6');
  sky.addColorStop(0.65, '#eef0e4');
  g.fillStyle = sky;
  g.fillRect(x, y, w, h);
  // Sun.
  const sunX = x + w * (0.66 + rnd() * 0.2), sunY = y + h * 0.26, sunR = h * 0.1;
  const glow = g.createRadialGradient(sunX, sunY, sunR * 0.5, sunX, sunY, sunR * 2.6);
  glow.addColorStop(0, 'rgba(255,226,150,0.8)');
  glow.addColorStop(1, 'rgba(255,226,150,0)');
  g.fillStyle = glow;
  g.fillRect(x, y, w, h);
  g.fillStyle = '#f2bf4a';
  g.beginPath(); g.arc(sunX, sunY, sunR, 0, Math.PI * 2); g.fill();
  // Far mountains.
  g.fillStyle = '#8fa5bb';
  g.beginPath();
  g.moveTo(x, y + h);
  for (let k = 0; k <= 10; k++) {
    const px = x + (w * k) / 10, py = y + h * (k % 2 ? 0.34 + rnd() * 0.12 : 0.5 + rnd() * 0.08);
    g.lineTo(px, py);
  }
  g.lineTo(x + w, y + h);
  g.fill();
  // Two rows of rolling hills.
  const hill = (base, amp, color, phase) => {
    g.fillStyle = color;
    g.beginPath();
    g.moveTo(x, y + h);
    g.lineTo(x, y + h * base);
    const n = 4;
    for (let k = 0; k < n; k++) {
      const x0 = x + (w * k) / n, x1 = x + (w * (k + 1)) / n;
      const up = ((k + phase) % 2 ? -1 : 1) * amp * (0.6 + rnd() * 0.6);
      g.quadraticCurveTo((x0 + x1) / 2, y + h * (base + up), x1, y + h * base);
    }
    g.lineTo(x + w, y + h);
    g.fill();
  };
  hill(0.66, 0.12, '#86ad6c', 0);
  hill(0.8, 0.1, '#5f8d4c', 1);
  // A river winding toward the viewer.
  g.fillStyle = '#dbe9f1';
  g.beginPath();
  g.moveTo(x + w * 0.46, y + h * 0.7);
  g.bezierCurveTo(x + w * 0.38, y + h * 0.8, x + w * 0.6, y + h * 0.86, x + w * 0.42, y + h);
  g.lineTo(x + w * 0.58, y + h);
  g.bezierCurveTo(x + w * 0.72, y + h * 0.86, x + w * 0.44, y + h * 0.8, x + w * 0.48, y + h * 0.7);
  g.closePath();
  g.fill();
  // Trees.
  for (const [tx, ts] of [[0.14, 1], [0.2, 0.75], [0.8, 1.15], [0.88, 0.8]]) {
    const bx = x + w * tx, by = y + h * 0.93, sz = h * 0.09 * ts;
    g.fillStyle = '#5b4330';
    g.fillRect(bx - sz * 0.1, by - sz * 1.2, sz * 0.2, sz * 1.2);
    g.fillStyle = '#355c30';
    g.beginPath();
    g.arc(bx, by - sz * 1.5, sz * 0.62, 0, Math.PI * 2);
    g.arc(bx - sz * 0.35, by - sz * 1.15, sz * 0.45, 0, Math.PI * 2);
    g.arc(bx + sz * 0.35, by - sz * 1.15, sz * 0.45, 0, Math.PI * 2);
    g.fill();
  }
  // Birds.
  g.strokeStyle = '#3b3b3b';
  g.lineWidth = 1.6 * s;
  g.beginPath();
  for (let k = 0; k < 3; k++) {
    const bx = x + w * (0.25 + k * 0.07 + rnd() * 0.03), byy = y + h * (0.16 + rnd() * 0.1), b = 7 * s;
    g.moveTo(bx - b, byy - b * 0.4);
    g.quadraticCurveTo(bx - b * 0.4, byy - b * 0.7, bx, byy);
    g.quadraticCurveTo(bx + b * 0.4, byy - b * 0.7, bx + b, byy - b * 0.4);
  }
  g.stroke();
  g.strokeStyle = '#4a433c';
  g.lineWidth = 2 * s;
  g.strokeRect(x + s, y + s, w - 2 * s, h - 2 * s);
}

function figChart(g, x, y, w, h, s, rnd) {
  const left = x + 58 * s, right = x + w - 26 * s, top = y + 30 * s, bottom = y + h - 44 * s;
  g.fillStyle = '#fffdf8';
  g.fillRect(x, y, w, h);
  g.strokeStyle = 'rgba(0,0,0,0.1)';
  g.lineWidth = 1 * s;
  g.beginPath();
  for (let k = 0; k <= 4; k++) {
    const gy = bottom - ((bottom - top) * k) / 4;
    g.moveTo(left, gy); g.lineTo(right, gy);
    const gx = left + ((right - left) * k) / 4;
    g.moveTo(gx, top); g.lineTo(gx, bottom);
  }
  g.stroke();
  g.strokeStyle = INK;
  g.lineWidth = 1.5 * s;
  g.beginPath(); g.moveTo(left, top - 6 * s); g.lineTo(left, bottom); g.lineTo(right, bottom); g.stroke();
  g.fillStyle = '#4a433c';
  g.font = `${Math.round(12 * s)}px ${SANS}`;
  g.textAlign = 'center';
  for (let k = 0; k <= 4; k++) g.fillText(`${k * 25}%`, left + ((right - left) * k) / 4, bottom + 16 * s);
  g.textAlign = 'right';
  for (let k = 0; k <= 4; k++) g.fillText((k / 4).toFixed(2), left - 6 * s, bottom - ((bottom - top) * k) / 4 + 4 * s);
  g.textAlign = 'center';
  g.fillText('progress of the turn', (left + right) / 2, bottom + 34 * s);
  const X = (t) => left + (right - left) * t;
  const Y = (v) => bottom - (bottom - top) * v;
  const series = [
    { color: ACCENT, f: (t) => 0.92 * Math.pow(1 - t, 1.6) + 0.04, name: 'cone angle θ' },
    { color: BLUE, f: (t) => 0.1 + 0.72 * Math.pow(Math.sin(Math.PI * t), 1.3) * (1 - 0.25 * t), name: 'curl radius' },
  ];
  for (const ser of series) {
    g.strokeStyle = ser.color;
    g.lineWidth = 2.5 * s;
    g.beginPath();
    for (let k = 0; k <= 40; k++) {
      const t = k / 40;
      if (k) g.lineTo(X(t), Y(ser.f(t))); else g.moveTo(X(t), Y(ser.f(t)));
    }
    g.stroke();
    g.fillStyle = ser.color;
    for (let k = 1; k < 10; k++) {     // "measured" points scattered about the curve
      const t = k / 10;
      g.beginPath();
      g.arc(X(t), Y(ser.f(t) + (rnd() - 0.5) * 0.06), 3.2 * s, 0, Math.PI * 2);
      g.fill();
    }
  }
  // Legend.
  g.font = `${Math.round(13 * s)}px ${SANS}`;
  g.textAlign = 'left';
  let ly = top + 4 * s;
  const lx = right - 150 * s;
  g.fillStyle = 'rgba(255,253,248,0.9)';
  g.fillRect(lx - 8 * s, ly - 14 * s, 156 * s, 44 * s);
  for (const ser of series) {
    g.strokeStyle = ser.color;
    g.lineWidth = 2.5 * s;
    g.beginPath(); g.moveTo(lx, ly); g.lineTo(lx + 22 * s, ly); g.stroke();
    g.fillStyle = INK;
    g.fillText(ser.name, lx + 30 * s, ly + 4 * s, right - lx - 34 * s);
    ly += 20 * s;
  }
}

function figOctavo(g, x, y, w, h, s) {
  // The sheet: eight pages, the top row printed upside down.
  const sh = h * 0.82, sw = Math.min(w * 0.58, sh * 1.55);
  const cw = sw / 4, ch = sh / 2;
  const gw = Math.min(w * 0.16, cw * 0.9), gh = gw * 1.3;
  const gap = Math.max(90 * s, w * 0.16);
  const sx = x + (w - (sw + gap + gw)) / 2, sy = y + (h - sh) / 2;
  g.fillStyle = '#fffdf7';
  g.fillRect(sx, sy, sw, sh);
  g.strokeStyle = INK;
  g.lineWidth = 1.5 * s;
  g.strokeRect(sx, sy, sw, sh);
  const order = [[5, 12, 9, 8], [4, 13, 16, 1]];
  g.font = `${Math.round(22 * s)}px ${SERIF}`;
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  for (let r = 0; r < 2; r++) {
    for (let c = 0; c < 4; c++) {
      const px = sx + c * cw, py = sy + r * ch;
      g.fillStyle = 'rgba(60,55,50,0.18)';
      for (let k = 0; k < 5; k++) g.fillRect(px + cw * 0.2, py + ch * (0.22 + k * 0.12), cw * 0.6, 3 * s);
      g.save();
      g.translate(px + cw / 2, py + ch / 2);
      if (r === 0) g.rotate(Math.PI);
      g.fillStyle = '#fffdf7';
      g.fillRect(-16 * s, -14 * s, 32 * s, 28 * s);
      g.fillStyle = ACCENT;
      g.fillText(String(order[r][c]), 0, 0);
      g.restore();
    }
  }
  g.textBaseline = 'alphabetic';
  // Folds, in the order they are made.
  g.strokeStyle = BLUE;
  g.lineWidth = 1.5 * s;
  g.setLineDash([6 * s, 4 * s]);
  g.beginPath();
  g.moveTo(sx + sw / 2, sy); g.lineTo(sx + sw / 2, sy + sh);
  g.moveTo(sx, sy + sh / 2); g.lineTo(sx + sw, sy + sh / 2);
  g.moveTo(sx + sw / 4, sy); g.lineTo(sx + sw / 4, sy + sh);
  g.moveTo(sx + (3 * sw) / 4, sy); g.lineTo(sx + (3 * sw) / 4, sy + sh);
  g.stroke();
  g.setLineDash([]);
  // An arrow to the folded gathering.
  const ax0 = sx + sw + 14 * s, ax1 = sx + sw + gap - 20 * s, ay = y + h * 0.5;
  g.strokeStyle = INK;
  g.lineWidth = 2 * s;
  g.beginPath();
  g.moveTo(ax0, ay); g.lineTo(ax1, ay);
  g.moveTo(ax1 - 9 * s, ay - 6 * s); g.lineTo(ax1, ay); g.lineTo(ax1 - 9 * s, ay + 6 * s);
  g.stroke();
  g.fillStyle = '#3a3632';
  label(g, 'fold ×3', (ax0 + ax1) / 2, ay - 10 * s, s, 'center');
  // The gathering: a little stack of leaves, sewn at the fold.
  const gx = sx + sw + gap, gy = y + (h - gh) / 2;
  for (let k = 3; k >= 0; k--) {
    g.fillStyle = k ? '#efe8da' : '#fffdf7';
    g.fillRect(gx + k * 3 * s, gy - k * 3 * s, gw, gh);
    g.strokeRect(gx + k * 3 * s, gy - k * 3 * s, gw, gh);
  }
  g.fillStyle = ACCENT;
  g.font = `${Math.round(20 * s)}px ${SERIF}`;
  g.textAlign = 'center';
  g.fillText('1', gx + gw / 2, gy + gh / 2 + 7 * s);
  g.fillStyle = '#3a3632';
  label(g, '16 pages', gx + gw / 2, gy + gh + 22 * s, s, 'center');
}

// ---------------------------------------------------------------------------------------------------
// Front matter, back matter and covers.

function titlePage(g, f) {
  paper(g, f);
  const { s, H } = f;
  const cx = (f.x0 + f.x1) / 2;
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  g.fillStyle = INK;
  const size = Math.min(
    fitFont(g, 'of the Page', f.width, Math.round(54 * s), (px) => `bold ${px}px ${SERIF}`),
    fitFont(g, 'The Curl', f.width, Math.round(54 * s), (px) => `bold ${px}px ${SERIF}`));
  g.font = `bold ${size}px ${SERIF}`;
  text(g, 'The Curl', cx, 0.24 * H, f.width);
  text(g, 'of the Page', cx, 0.24 * H + size * 1.2, f.width);
  ruleOrnament(g, cx, 0.36 * H, Math.min(0.2 * f.W, f.width / 2), ACCENT, s);
  g.fillStyle = '#4a433c';
  fitFont(g, SUBTITLE, f.width, Math.round(23 * s), (px) => `italic ${px}px ${SERIF}`);
  text(g, SUBTITLE, cx, 0.42 * H, f.width);
  fanOrnament(g, cx, 0.54 * H, 0.09 * H, ACCENT, s);
  g.fillStyle = INK;
  setSpacing(g, 4 * s);
  fitFont(g, AUTHOR.toUpperCase(), f.width, Math.round(22 * s), (px) => `${px}px ${SERIF}`);
  text(g, AUTHOR.toUpperCase(), cx, 0.7 * H, f.width);
  setSpacing(g, 0);
  g.fillStyle = '#6b6259';
  fitFont(g, PRESS, f.width, Math.round(16 * s), (px) => `${px}px ${SANS}`);
  text(g, PRESS, cx, 0.85 * H, f.width);
  g.textAlign = 'left';
  folio(g, f);
}

function contentsPage(g, f) {
  paper(g, f);
  const { s, H } = f;
  const cx = (f.x0 + f.x1) / 2;
  g.textAlign = 'center';
  g.fillStyle = INK;
  fitFont(g, 'Contents', f.width, Math.round(36 * s), (px) => `bold ${px}px ${SERIF}`);
  text(g, 'Contents', cx, f.top + 0.06 * H, f.width);
  ruleOrnament(g, cx, f.top + 0.1 * H, Math.min(0.14 * f.W, f.width / 2), ACCENT, s);
  const entries = CHAPTERS.map((title, c) => [ROMAN[c], title, FIRST_CHAPTER_PAGE + c * CHAPTER_SPACING + 1]);
  entries.push(['', 'Colophon', COLOPHON_PAGE + 1]);
  const font = `${Math.round(21 * s)}px ${SERIF}`;
  const numCol = 44 * s;
  let y = f.top + 0.19 * H;
  for (const [roman, title, page] of entries) {
    g.font = font;
    g.fillStyle = ACCENT;
    g.textAlign = 'right';
    if (roman) text(g, roman, f.x0 + numCol - 12 * s, y, numCol);
    g.fillStyle = INK;
    const pageStr = String(page);
    const pw = g.measureText(pageStr).width;
    text(g, pageStr, f.x1, y, f.width);
    g.textAlign = 'left';
    const tx = f.x0 + numCol;
    const room = f.x1 - pw - 14 * s - tx;
    text(g, title, tx, y, room);
    const tw = Math.min(room, g.measureText(title).width);
    g.fillStyle = '#9a9088';
    for (let dx = tx + tw + 12 * s; dx < f.x1 - pw - 12 * s; dx += 10 * s) g.fillRect(dx, y - 2 * s, 2 * s, 2 * s);
    y += 0.06 * H;
  }
  // The small print.
  g.font = `${Math.round(13 * s)}px ${SANS}`;
  g.fillStyle = '#6b6259';
  const small = 'This book exists only while it is being read. Its pages are drawn on demand, one canvas at a ' +
    'time, and each leaf is turned around a cone whose apex slides along the spine. No trees were felled, ' +
    'no thread was pulled and no glue was warmed in the making of this copy.';
  const lines = wrap(g, small, f.width);
  let sy = f.bottom - lines.length * 19 * s;
  for (const line of lines) { text(g, line, f.x0, sy, f.width); sy += 19 * s; }
  folio(g, f);
}

function colophonPage(g, f) {
  paper(g, f);
  const { s, H } = f;
  const cx = (f.x0 + f.x1) / 2;
  g.textAlign = 'center';
  g.fillStyle = INK;
  setSpacing(g, 5 * s);
  fitFont(g, 'COLOPHON', f.width, Math.round(20 * s), (px) => `${px}px ${SANS}`);
  text(g, 'COLOPHON', cx, f.top + 0.14 * H, f.width);
  setSpacing(g, 0);
  ruleOrnament(g, cx, f.top + 0.18 * H, Math.min(0.12 * f.W, f.width / 2), ACCENT, s);
  const body = 'This book was set in DejaVu Serif, with DejaVu Sans for its figures and labels. Its pages were ' +
    'drawn onto a canvas at the moment they were needed, and every leaf was turned around a cone, just as ' +
    'the fifth chapter describes. No paper was cut, folded or sewn in its making, and none of it will yellow.';
  g.font = `italic ${Math.round(19 * s)}px ${SERIF}`;
  g.fillStyle = '#3a332c';
  let y = f.top + 0.26 * H;
  for (const line of wrap(g, body, f.width * 0.82)) { text(g, line, cx, y, f.width); y += 30 * s; }
  fanOrnament(g, cx, y + 0.1 * H, 0.06 * H, ACCENT, s);
  g.fillStyle = INK;
  fitFont(g, 'The End', f.width, Math.round(30 * s), (px) => `italic ${px}px ${SERIF}`);
  text(g, 'The End', cx, y + 0.25 * H, f.width);
  g.textAlign = 'left';
  folio(g, f);
}

const layers = new Map();
/** A canvas drawn once by `paint(g, width, height)` and kept: pattern tiles, and backgrounds shared by pages. */
function layer(key, width, height, paint) {
  let c = layers.get(key);
  if (!c) {
    if (layers.size > 16) layers.clear();
    c = typeof document !== 'undefined'
      ? Object.assign(document.createElement('canvas'), { width, height })
      : new OffscreenCanvas(width, height);
    paint(c.getContext('2d'), width, height);
    layers.set(key, c);
  }
  return c;
}

function tile(name, size, paint) {
  return layer(`${name}:${size}`, size, size, paint);
}

function weaveTile(g, size) {
  g.fillStyle = 'rgba(255,255,255,0.035)';
  g.fillRect(0, 0, size, 1);
  g.fillStyle = 'rgba(0,0,0,0.05)';
  g.fillRect(0, 0, 1, size);
}

/** Two by two cells of quarter curls, alternating in direction, with a dot in each cell. */
function endpaperTile(g, size) {
  const cell = size / 2;
  const s = cell / 44;
  g.strokeStyle = 'rgba(128,88,44,0.42)';
  g.lineWidth = 1.6 * s;
  g.beginPath();
  for (let j = -1; j <= 2; j++) {          // neighbours too, so strokes wrap across the tile's edges
    for (let i = -1; i <= 2; i++) {
      const tx = i * cell, ty = j * cell;
      const odd = ((i + j) % 2 + 2) % 2 === 1;
      const ox = odd ? tx + cell : tx, sgn = odd ? -1 : 1;
      for (const r of [0.34, 0.56]) {
        g.moveTo(ox + sgn * cell * r, ty + cell);
        g.arc(ox, ty + cell, cell * r, odd ? Math.PI : 0, Math.PI * 1.5, !odd);
      }
    }
  }
  g.stroke();
  g.fillStyle = 'rgba(128,88,44,0.35)';
  g.beginPath();
  for (const [dx, dy] of [[0.5, 0.5], [1.5, 0.5], [0.5, 1.5], [1.5, 1.5]]) {
    g.moveTo(dx * cell + 2.5 * s, dy * cell);
    g.arc(dx * cell, dy * cell, 2.5 * s, 0, Math.PI * 2);
  }
  g.fill();
}

function cloth(g, f) {
  g.drawImage(layer(`cloth:${f.W}x${f.H}:${f.left}`, f.W, f.H, (c) => paintCloth(c, f)), 0, 0);
}

function paintCloth(g, f) {
  const { W, H, s } = f;
  const light = g.createLinearGradient(0, 0, W, H);  // the cloth, lit from the top left
  light.addColorStop(0, '#33505e');
  light.addColorStop(1, '#19323e');
  g.fillStyle = light;
  g.fillRect(0, 0, W, H);
  // The weave, from a tiny cached tile.
  g.fillStyle = g.createPattern(tile('weave', Math.max(2, Math.round(3 * s)), weaveTile), 'repeat');
  g.fillRect(0, 0, W, H);
  // The groove of the hinge, on the spine side.
  const hx = f.left ? W - 0.05 * W : 0.05 * W;
  g.strokeStyle = 'rgba(0,0,0,0.35)';
  g.lineWidth = 4 * s;
  g.beginPath(); g.moveTo(hx, 0); g.lineTo(hx, H); g.stroke();
  g.strokeStyle = 'rgba(255,255,255,0.12)';
  g.lineWidth = 1.5 * s;
  g.beginPath(); g.moveTo(hx + (f.left ? -4 : 4) * s, 0); g.lineTo(hx + (f.left ? -4 : 4) * s, H); g.stroke();
}

function goldFrame(g, f) {
  const { W, H, s } = f;
  const spine = 0.05 * W;
  const l = (f.left ? 0.05 * W : spine + 0.04 * W), r = W - (f.left ? spine + 0.04 * W : 0.05 * W);
  const t = 0.045 * H, b = H - 0.025 * H;
  g.strokeStyle = GOLD;
  g.lineWidth = 2.5 * s;
  g.strokeRect(l, t, r - l, b - t);
  g.lineWidth = 1 * s;
  g.strokeRect(l + 8 * s, t + 8 * s, r - l - 16 * s, b - t - 16 * s);
  return (l + r) / 2;
}

function frontCover(g, f) {
  cloth(g, f);
  const { s, H, W } = f;
  const cx = goldFrame(g, f);
  const maxW = W * 0.7;
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  g.fillStyle = GOLD;
  const size = Math.min(
    fitFont(g, 'of the Page', maxW, Math.round(68 * s), (px) => `bold ${px}px ${SERIF}`),
    fitFont(g, 'The Curl', maxW, Math.round(68 * s), (px) => `bold ${px}px ${SERIF}`));
  g.font = `bold ${size}px ${SERIF}`;
  g.shadowColor = 'rgba(0,0,0,0.35)';
  g.shadowOffsetY = 2 * s;
  text(g, 'The Curl', cx, 0.22 * H, maxW);
  text(g, 'of the Page', cx, 0.22 * H + size * 1.18, maxW);
  g.shadowColor = 'transparent';
  ruleOrnament(g, cx, 0.35 * H, Math.min(0.22 * W, maxW / 2), GOLD, s);
  g.fillStyle = CREAM;
  fitFont(g, SUBTITLE, maxW, Math.round(24 * s), (px) => `italic ${px}px ${SERIF}`);
  text(g, SUBTITLE, cx, 0.41 * H, maxW);
  // The emblem in a roundel.
  g.strokeStyle = GOLD;
  g.lineWidth = 2 * s;
  g.beginPath(); g.arc(cx, 0.58 * H, 0.12 * H, 0, Math.PI * 2); g.stroke();
  g.lineWidth = 1 * s;
  g.beginPath(); g.arc(cx, 0.58 * H, 0.12 * H - 7 * s, 0, Math.PI * 2); g.stroke();
  fanOrnament(g, cx, 0.565 * H, 0.075 * H, GOLD, s);
  g.fillStyle = GOLD;
  setSpacing(g, 5 * s);
  fitFont(g, AUTHOR.toUpperCase(), maxW, Math.round(24 * s), (px) => `${px}px ${SERIF}`);
  text(g, AUTHOR.toUpperCase(), cx, 0.8 * H, maxW);
  setSpacing(g, 0);
  g.textAlign = 'left';
  folio(g, f, CLOTH, { fill: GOLD });
}

function backCover(g, f) {
  cloth(g, f);
  const { s, H, W } = f;
  const cx = goldFrame(g, f);
  const x0 = f.x0, x1 = f.x1, width = f.width;
  g.textAlign = 'center';
  g.textBaseline = 'alphabetic';
  g.fillStyle = GOLD;
  setSpacing(g, 4 * s);
  fitFont(g, TITLE.toUpperCase(), width, Math.round(17 * s), (px) => `${px}px ${SANS}`);
  text(g, TITLE.toUpperCase(), cx, 0.11 * H, width);
  setSpacing(g, 0);
  g.font = `italic ${Math.round(30 * s)}px ${SERIF}`;
  let y = 0.2 * H;
  for (const line of wrap(g, '“For a moment, every page is a cone.”', width)) {
    text(g, line, cx, y, width);
    y += 40 * s;
  }
  g.textAlign = 'left';
  g.fillStyle = CREAM;
  const blurb = 'A short, illustrated book about the humble act of turning a page: how paper gets its grain, ' +
    'how sheets are folded and sewn into a book, and why a lifted leaf curls around an invisible cone before ' +
    'it settles on the other side. Written for readers, binders, and anyone who has ever watched the corner ' +
    'of a page rise and wondered at the shape it made.';
  g.font = `${Math.round(20 * s)}px ${SERIF}`;
  y += 20 * s;
  for (const line of wrap(g, blurb, width)) { text(g, line, x0, y, width); y += 31 * s; }
  y += 24 * s;
  g.font = `italic ${Math.round(18 * s)}px ${SERIF}`;
  g.fillStyle = GOLD;
  for (const [quote, who] of [['“Turns beautifully, and never tears.”', '— The Bindery Gazette'],
    ['“I read it twice, then read it backwards.”', '— A patient reader']]) {
    text(g, quote, x0, y, width);
    g.textAlign = 'right';
    g.fillStyle = CREAM;
    text(g, who, x1, y + 26 * s, width);
    g.textAlign = 'left';
    g.fillStyle = GOLD;
    y += 70 * s;
  }
  // Barcode in a white box toward the spine, the publisher beside it.
  const bw = Math.min(0.34 * W, width * 0.55), bh = 0.13 * H;
  const bx = x1 - bw, by = 0.93 * H - bh;
  g.fillStyle = '#ffffff';
  g.fillRect(bx, by, bw, bh);
  const rnd = mulberry32(97800);
  const barTop = by + 12 * s, barBottom = by + bh - 30 * s;
  const unit = (bw - 28 * s) / 95;
  let bxp = bx + 14 * s;
  g.fillStyle = '#111111';
  const guard = (n) => {                    // guard bars, a little longer than the rest
    for (let k = 0; k < n; k++) {
      if (k % 2 === 0) g.fillRect(bxp, barTop, unit, barBottom - barTop + 8 * s);
      bxp += unit;
    }
  };
  guard(3);
  for (let half = 0; half < 2; half++) {
    for (let d = 0; d < 6; d++) {
      let left = 7;
      let dark = half === 1;
      while (left > 0) {                    // each digit: seven modules in four runs
        const run = Math.min(left, 1 + Math.floor(rnd() * 3));
        if (dark) g.fillRect(bxp, barTop, unit * run, barBottom - barTop);
        bxp += unit * run;
        left -= run;
        dark = !dark;
      }
    }
    if (half === 0) { bxp += unit; guard(3); bxp -= unit; }
  }
  guard(3);
  g.fillStyle = '#111111';
  g.font = `${Math.round(14 * s)}px ${SANS}`;
  g.textAlign = 'center';
  const digits = '9 780000 ' + Array.from({ length: 6 }, () => Math.floor(rnd() * 10)).join('');
  text(g, digits, bx + bw / 2, by + bh - 10 * s, bw - 10 * s);
  g.textAlign = 'left';
  g.fillStyle = CREAM;
  g.font = `${Math.round(15 * s)}px ${SANS}`;
  text(g, PRESS, x0, by + 20 * s, bx - x0 - 16 * s);
  fanOrnament(g, x0 + 26 * s, by + 62 * s, 24 * s, GOLD, s);
  folio(g, f, CLOTH, { fill: GOLD });
}

function endpaper(g, f) {
  const { W, H, s } = f;
  // The cloth turned in over the board's edges, then the pasted-down endpaper, flush at the hinge.
  g.fillStyle = CLOTH;
  g.fillRect(0, 0, W, H);
  const turn = 0.035 * W;
  const ex = f.left ? turn : 0, ew = W - turn;
  const ey = 0.03 * H, eh = H - 0.06 * H;
  g.fillStyle = '#eadcbf';
  g.fillRect(ex, ey, ew, eh);
  g.save();
  g.beginPath();
  g.rect(ex, ey, ew, eh);
  g.clip();
  g.fillStyle = g.createPattern(tile('endpaper', Math.max(8, Math.round(44 * s)) * 2, endpaperTile), 'repeat');
  g.fillRect(ex, ey, ew, eh);
  // Shadow along the hinge.
  const hx = f.left ? W : 0;
  const shade = g.createLinearGradient(hx, 0, hx + (f.left ? -1 : 1) * 0.08 * W, 0);
  shade.addColorStop(0, 'rgba(60,40,20,0.25)');
  shade.addColorStop(1, 'rgba(60,40,20,0)');
  g.fillStyle = shade;
  g.fillRect(f.left ? W - 0.08 * W : 0, 0, 0.08 * W, H);
  g.restore();

  const cx = (f.x0 + f.x1) / 2;
  if (f.index === 1) {
    // A bookplate.
    const pw = Math.min(0.5 * W, f.width), ph = 0.32 * H;
    const px = cx - pw / 2, py = 0.3 * H;
    g.fillStyle = '#fbf6ea';
    g.fillRect(px, py, pw, ph);
    g.strokeStyle = ACCENT;
    g.lineWidth = 2 * s;
    g.strokeRect(px + 8 * s, py + 8 * s, pw - 16 * s, ph - 16 * s);
    g.lineWidth = 1 * s;
    g.strokeRect(px + 13 * s, py + 13 * s, pw - 26 * s, ph - 26 * s);
    g.fillStyle = ACCENT;
    g.textAlign = 'center';
    setSpacing(g, 5 * s);
    fitFont(g, 'EX LIBRIS', pw - 50 * s, Math.round(24 * s), (px2) => `${px2}px ${SERIF}`);
    text(g, 'EX LIBRIS', cx, py + 0.075 * H, pw - 50 * s);
    setSpacing(g, 0);
    fanOrnament(g, cx, py + 0.15 * H, 0.05 * H, ACCENT, s);
    g.strokeStyle = '#7a7068';
    g.lineWidth = 1 * s;
    const ly = py + ph - 0.06 * H;
    g.beginPath(); g.moveTo(px + 40 * s, ly); g.lineTo(px + pw - 40 * s, ly); g.stroke();
    g.fillStyle = '#7a7068';
    g.font = `italic ${Math.round(14 * s)}px ${SERIF}`;
    text(g, 'this book belongs to', cx, py + ph - 0.035 * H, pw - 50 * s);
    g.textAlign = 'left';
  } else {
    // The binder's ticket.
    const tw = Math.min(0.34 * W, f.width), th = 0.075 * H;
    const tx = f.x0, ty = f.top;
    g.fillStyle = '#fbf6ea';
    g.fillRect(tx, ty, tw, th);
    g.strokeStyle = INK;
    g.lineWidth = 1 * s;
    g.strokeRect(tx + 4 * s, ty + 4 * s, tw - 8 * s, th - 8 * s);
    g.fillStyle = INK;
    g.textAlign = 'center';
    g.font = `italic ${Math.round(13 * s)}px ${SERIF}`;
    text(g, 'Bound on a cone by', tx + tw / 2, ty + th * 0.42, tw - 16 * s);
    fitFont(g, PRESS, tw - 16 * s, Math.round(15 * s), (px2) => `${px2}px ${SANS}`);
    text(g, PRESS, tx + tw / 2, ty + th * 0.75, tw - 16 * s);
    g.textAlign = 'left';
  }
  folio(g, f, INK, { fill: '#fbf6ea', stroke: 'rgba(60,40,20,0.4)' });
}
