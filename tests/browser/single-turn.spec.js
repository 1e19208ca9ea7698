// Browser (WebGL2 on SwiftShader): the single-display turn a phone reader sees (issue 40), read back from
// the canvas: the leaf's blank back is paper lit as its front (not a grey slab), the page's print shows
// through it as much as showThrough says (a hard cover's back stays board), and the shadow's edge fades
// over many pixels instead of ending in a hard, stair-stepped line.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

// Page 0 is the blue FRONT test image, page 1 the orange BACK one under it; one page shown at a time.
const fixture = (query = '') => `/tests/browser/fixtures/book-fixture.html?pages=2&sides=1&display=single&position=0&thickness=off${query}`;
const PAPER = [250, 247, 240];  // cpp/core/book_constants.hpp kPaperRed, kPaperGreen, kPaperBlue

/**
 * Poses the forward turn of page 0 at t and sorts the frame's opaque pixels: `neutral` are those with
 * no page's hue (the blank back: paper under some light; max - min of the channels below 25), each
 * as its brightness relative to the paper's and its blue excess; `rows` gives rows of pixels for the shadow.
 */
async function frameAt(page, t, movingScale = 1) {
  return page.evaluate(({ t, movingScale }) => {
    window.fixture.view.renderer.setOptions({ movingScale });  // a moving frame's share of the pixels
    window.fixture.view.showTurn('forward', t);
    const { width, height, data } = window.fixture.view.readPixels();
    return { width, height, data: Array.from(data) };
  }, { t, movingScale });
}

function neutralPixels({ data }) {
  const out = [];
  for (let i = 0; i < data.length; i += 4) {
    const [r, g, b, a] = [data[i], data[i + 1], data[i + 2], data[i + 3]];
    if (a < 250 || Math.max(r, g, b) - Math.min(r, g, b) >= 25 || Math.max(r, g, b) < 40) continue;
    out.push({ light: (r + g + b) / (PAPER[0] + PAPER[1] + PAPER[2]), warm: r - b });
  }
  return out;
}

const median = (values) => values.slice().sort((a, b) => a - b)[Math.floor(values.length / 2)];

test('browser: in single display a turning leaf\'s blank back is paper, lit as its front is, not a grey slab', async ({ page }) => {
  await openReady(page, fixture('&showThrough=0'));
  for (const t of [0.3, 0.45, 0.6]) {
    const frame = await frameAt(page, t);
    const back = neutralPixels(frame);
    // The back covers a good part of the canvas (the view leaves the spine's side room for it)...
    expect(back.length / (frame.width * frame.height), `back's share at t=${t}`).toBeGreaterThan(0.05);
    // ...and reads as the paper: its typical pixel within 12% of the paper's brightness (the slab was ~60%)
    // with the paper's warm tint (red above blue, as in 250, 247, 240).
    expect(median(back.map((p) => p.light)), `back's brightness at t=${t}`).toBeGreaterThan(0.88);
    expect(median(back.map((p) => p.light)), `back's brightness at t=${t}`).toBeLessThan(1.12);
    expect(median(back.map((p) => p.warm)), `back's tint at t=${t}`).toBeGreaterThan(3);
  }
});

test('browser: the page\'s print shows through the blank back as much as showThrough says; a hard cover\'s back shows none', async ({ page }) => {
  // The FRONT image is blue: seen through the paper it cools the back (blue above red).
  const coolness = async (query, t = 0.45) => {
    await openReady(page, fixture(query));
    const frame = await frameAt(page, t);
    let sum = 0;
    let n = 0;
    for (let i = 0; i < frame.data.length; i += 4) {
      const [r, g, b, a] = frame.data.slice(i, i + 4);
      const max = Math.max(r, g, b);
      // The back: light, only faintly tinted (the front's own blue is far more saturated).
      if (a < 250 || max < 60 || max - Math.min(r, g, b) > 70) continue;
      sum += b - r;
      n += 1;
    }
    return { cool: sum / n, n };
  };
  const none = await coolness('&showThrough=0');
  const some = await coolness('&showThrough=0.3');
  expect(none.n).toBeGreaterThan(10000);
  expect(none.cool).toBeLessThan(-3);            // plain paper: warm
  expect(some.cool - none.cool).toBeGreaterThan(15);  // the blue front through it
  // A board: a hard cover, turned rigidly, shows its back once past upright; with show-through asked
  // it stays blank board, as warm as a back with none.
  const board = await coolness('&showThrough=0.3&hard=0', 0.7);
  const plainBoard = await coolness('&showThrough=0&hard=0', 0.7);
  expect(board.n).toBeGreaterThan(10000);
  expect(Math.abs(board.cool - plainBoard.cool)).toBeLessThan(1);
});

/**
 * Along row y of the frame, from the canvas's right edge leftwards over the lit orange page, the
 * darkening (1 - brightness / the unshadowed page's) until the leaf begins: the shadow's profile.
 */
function shadowProfile(frame, y) {
  const { width, data } = frame;
  const profile = [];
  let clear = null;
  for (let x = width - 1; x >= 0; x--) {
    const i = (y * width + x) * 4;
    const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
    const orange = r > g + 30 && g > b + 30;  // the BACK page's orange, lit or shadowed
    if (!orange) {
      if (clear === null) continue;  // the margin right of the page
      break;                          // the leaf
    }
    const light = r + g + b;
    clear ??= light;
    profile.push({ x, dark: 1 - light / clear });
  }
  return profile;
}

test('browser: at t=0.25 the shadow a leaf casts in single display fades from dark to clear over many device pixels, at full and at a quarter of the pixels', async ({ page }) => {
  await openReady(page, fixture());
  for (const scale of [1, 0.5]) {
    const frame = await frameAt(page, 0.25, scale);
    const widths = [];
    for (const fy of [0.62, 0.72, 0.92]) {  // rows clear of the page's print
      const profile = shadowProfile(frame, Math.round(frame.height * fy));
      const darkest = Math.max(...profile.map((p) => p.dark));
      expect(darkest, `a shadow on row ${fy}`).toBeGreaterThan(0.1);
      // From the last point (going left) at 10% of the darkest to the first at 90%.
      const outer = profile.find((p) => p.dark >= 0.1 * darkest);
      const inner = profile.find((p) => p.dark >= 0.9 * darkest);
      widths.push(Math.abs(outer.x - inner.x));
    }
    // A hard edge goes from clear to dark within a pixel or two (the old one, stair-stepped, within 3).
    expect(Math.min(...widths), `edge widths ${widths} at scale ${scale}`).toBeGreaterThanOrEqual(12);
  }
});
