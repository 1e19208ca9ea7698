// Browser: the page sound (sound: true, page-sound.js): no AudioContext before a gesture, its rustle's
// gain (the GainNode's own value, sampled each frame) follows the leaf's angular speed from the engine,
// fades to 0 at rest, `muted` silences it, and reduced motion makes none. Contexts are counted by
// wrapping window.AudioContext before the page loads.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

const FIXTURE = '/tests/browser/fixtures/flipbook-fixture.html';

async function countContexts(page) {
  await page.addInitScript(() => {
    const Original = window.AudioContext;
    window.__contexts = [];
    window.AudioContext = class CountedAudioContext extends Original {
      constructor(...args) {
        super(...args);
        window.__contexts.push(this);
      }
    };
  });
}

async function open(page, options) {
  await page.evaluate(async (options) => {
    await window.openBook({ pages: 8, display: 'double', duration: 600, ...options });
    // Each frame: the engine's speed and the rustle's gain as the GainNode has it now.
    window.samples = [];
    const sample = () => {
      if (!window.book.surface) return;
      const { speed, gain, target } = window.book.sound;
      window.samples.push({ speed, gain, target });
      requestAnimationFrame(sample);
    };
    requestAnimationFrame(sample);
  }, options);
}

const contexts = (page) => page.evaluate(() => window.__contexts.map((c) => c.state));
const takeSamples = (page) => page.evaluate(() => window.samples.splice(0));

// A press on the right page's bottom corner region, then moves towards the spine and past it.
async function cornerPath(page, steps) {
  return page.evaluate((steps) => {
    const from = window.halfPoint(0.97, 0.95);
    const to = window.halfPoint(0.1, 0.9);
    return Array.from({ length: steps + 1 }, (_, i) => ({ x: from.x + ((to.x - from.x) * i) / steps, y: from.y + ((to.y - from.y) * i) / steps }));
  }, steps);
}

test('browser: sound: no AudioContext before a gesture; a click on the book makes one, later gestures reuse it, destroy() closes it', async ({ page }) => {
  await countContexts(page);
  const problems = await openReady(page, FIXTURE);
  await open(page, { sound: true });
  expect(await page.evaluate(() => window.book.sound.state)).toBe('waiting');
  expect(await contexts(page)).toEqual([]);

  const point = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(point.x, point.y);
  expect((await contexts(page)).length).toBe(1);
  expect(['running', 'suspended']).toContain(await page.evaluate(() => window.book.sound.state));
  await page.keyboard.press('ArrowRight');
  await page.mouse.click(point.x, point.y);
  expect((await contexts(page)).length).toBe(1);

  await page.evaluate(() => window.book.destroy());
  await page.waitForFunction(() => window.__contexts[0].state === 'closed');
  expect(problems).toEqual([]);
});

test('browser: sound: a turn without a user gesture (autoplay, once the page\'s activation has expired) makes no AudioContext; a page button that turns the book does', async ({ page }) => {
  // Playwright's page.evaluate counts as a user gesture (transient activation, 5 s in Chromium), so the
  // autoplay turn is heard through the console, with no evaluate between it and the book's opening.
  await countContexts(page);
  const problems = await openReady(page, FIXTURE);
  await page.evaluate(async () => {
    await window.openBook({ pages: 8, display: 'double', duration: 200, sound: true, autoplay: { interval: 6000 } });
    window.book.addEventListener('turned', () => console.log(`turned active=${navigator.userActivation.isActive} contexts=${window.__contexts.length}`));
  });
  const message = await page.waitForEvent('console', { predicate: (m) => m.text().startsWith('turned'), timeout: 20_000 });
  expect(message.text()).toBe('turned active=false contexts=0');

  await page.evaluate(() => {
    const button = document.createElement('button');
    button.textContent = 'Next';
    button.style.cssText = 'position: fixed; right: 0; bottom: 0';
    button.onclick = () => window.book.next();
    document.body.append(button);
  });
  await page.click('button');
  expect((await contexts(page)).length).toBe(1);
  expect(problems).toEqual([]);
});

test('browser: sound: the rustle\'s gain follows the leaf\'s angular speed: a slow drag whispers, a fling is louder, at rest it fades to 0, each landing taps', async ({ page }) => {
  await countContexts(page);
  const problems = await openReady(page, FIXTURE);
  await open(page, { sound: true });
  const slow = await cornerPath(page, 60);
  await page.mouse.move(slow[0].x, slow[0].y);
  await page.mouse.down();  // the gesture that makes the context
  expect(await contexts(page)).toEqual(['running']);
  await takeSamples(page);
  for (const point of slow.slice(1, 31)) {  // half way, slowly: one small step a frame or so
    await page.mouse.move(point.x, point.y);
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  }
  const dragged = await takeSamples(page);
  await page.mouse.up();
  await page.waitForFunction(() => !window.book.animating);
  await page.waitForFunction(() => window.book.sound.gain < 1e-3);  // at rest it fades out
  await takeSamples(page);

  const fast = await cornerPath(page, 4);
  await page.mouse.move(fast[0].x, fast[0].y);
  await page.mouse.down();
  for (const point of fast.slice(1)) await page.mouse.move(point.x, point.y);
  await page.mouse.up();
  await page.waitForFunction(() => !window.book.animating);
  await page.waitForFunction(() => window.book.sound.gain < 1e-3);
  const flung = await takeSamples(page);

  const peak = (samples, key) => Math.max(...samples.map((s) => s[key]));
  const slowPeak = peak(dragged, 'gain');
  const fastPeak = peak(flung, 'gain');
  console.log(`sound: slow drag peak ${peak(dragged, 'speed').toFixed(2)} rad/s gain ${slowPeak.toFixed(4)}; `
    + `fling peak ${peak(flung, 'speed').toFixed(2)} rad/s gain ${fastPeak.toFixed(4)}; ${dragged.length} + ${flung.length} samples`);
  expect(peak(dragged, 'speed')).toBeGreaterThan(0);  // the slow drag did move the leaf
  expect(slowPeak).toBeGreaterThan(0);
  expect(fastPeak).toBeGreaterThan(2 * slowPeak);

  // Sampled gain follows speed: a Spearman rank correlation over every frame of both strokes.
  const all = [...dragged, ...flung];
  const ranks = (values) => {
    const order = values.map((v, i) => [v, i]).sort((a, b) => a[0] - b[0]);
    const r = new Array(values.length);
    order.forEach(([, i], k) => { r[i] = k; });
    return r;
  };
  const rs = ranks(all.map((s) => s.speed));
  const rg = ranks(all.map((s) => s.gain));
  const mean = (all.length - 1) / 2;
  let num = 0; let ds = 0; let dg = 0;
  for (let i = 0; i < all.length; i++) {
    num += (rs[i] - mean) * (rg[i] - mean);
    ds += (rs[i] - mean) ** 2;
    dg += (rg[i] - mean) ** 2;
  }
  const rho = num / Math.sqrt(ds * dg);
  console.log(`sound: rank correlation of sampled gain with angular speed ${rho.toFixed(3)} over ${all.length} frames`);
  expect(rho).toBeGreaterThan(0.6);
  // Each stroke ended in a landing (the slow one fell back or landed, the fling landed): a tap each.
  expect(await page.evaluate(() => window.book.sound.taps)).toBe(2);
  expect(problems).toEqual([]);
});

test('browser: sound: muted makes no AudioContext on a gesture; muting a playing book sets its gain to 0 at once', async ({ page }) => {
  await countContexts(page);
  const problems = await openReady(page, FIXTURE);
  await open(page, { sound: true, muted: true });
  const point = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(point.x, point.y);
  expect(await contexts(page)).toEqual([]);
  expect(await page.evaluate(() => [window.book.muted, window.book.sound.state])).toEqual([true, 'muted']);
  await page.evaluate(() => window.settle());

  await page.evaluate(() => { window.book.muted = false; });
  // The open book's right page (the closed book sat centred: the point above now lies on the spine, whose
  // middle band turns nothing).
  const right = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(right.x, right.y);
  expect((await contexts(page)).length).toBe(1);
  await page.waitForFunction(() => window.book.sound.gain > 0.01);  // the click's turn rustles
  await page.evaluate(() => { window.book.muted = true; });
  expect(await page.evaluate(() => [window.book.sound.state, window.book.sound.gain, window.book.options.muted])).toEqual(['muted', 0, true]);
  await page.waitForFunction(() => window.__contexts[0].state === 'suspended');
  await expect(page.evaluate(() => { window.book.muted = 'yes'; })).rejects.toThrow(/option 'muted' must be true or false, got "yes"/);
  expect(problems).toEqual([]);
});

test('browser: sound: under prefers-reduced-motion no AudioContext is made and the book is silent', async ({ page }) => {
  await countContexts(page);
  await page.emulateMedia({ reducedMotion: 'reduce' });
  const problems = await openReady(page, FIXTURE);
  await open(page, { sound: true });
  const point = await page.evaluate(() => window.halfPoint(0.75, 0.5));
  await page.mouse.click(point.x, point.y);
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.book.page >= 3);
  expect(await contexts(page)).toEqual([]);
  expect(await page.evaluate(() => window.book.sound)).toEqual({ state: 'silent', gain: 0, target: 0, speed: 0, taps: 0, ducked: false, level: 0 });
  expect(problems).toEqual([]);
});

test('browser: sound: <cone-flipbook sound muted> sets the options; the muted attribute and property change the same live book', async ({ page }) => {
  const problems = await openReady(page, '/tests/browser/fixtures/element-fixture.html');
  const result = await page.evaluate(async () => {
    const pages = Array.from({ length: 4 }, (_, i) => window.pageUrl(i)).join(' ');
    const element = window.makeElement({ pages, sound: '', muted: 'true' });
    document.getElementById('stage').append(element);
    const book = await element.whenReady();
    const seen = [[book.options.sound, book.muted, book.sound.state, element.muted]];
    element.removeAttribute('muted');  // absent: the default, not muted
    seen.push([book.muted, book.sound.state]);
    element.muted = true;  // the property writes the attribute
    seen.push([book.muted, book.sound.state, element.getAttribute('muted')]);
    element.setAttribute('sound', 'false');
    seen.push([book.options.sound, book.sound.state]);
    return { seen, same: element.book === book };
  });
  expect(result.seen).toEqual([[true, true, 'muted', true], [false, 'waiting'], [true, 'muted', 'true'], [false, 'off']]);
  expect(result.same).toBe(true);
  expect(problems).toEqual([]);
});

test('browser: sound: a voice reading aloud ducks the page sound (its level glides to 0.3) and gives it back when it stops', async ({ page }) => {
  await countContexts(page);
  await openReady(page, FIXTURE);
  await open(page, { sound: true });
  await page.evaluate(() => window.book.element.focus());
  await page.keyboard.press('Shift');  // the gesture that makes the AudioContext (a key that turns nothing)
  await page.waitForFunction(() => window.book.sound.level === 1);
  // A speech engine that says nothing until told: the reading stays on page 2.
  await page.evaluate(() => window.book.readAloud({ engine: { speak: () => ({ pause() {}, resume() {}, cancel() {} }) } }));
  expect(await page.evaluate(() => window.book.sound.ducked)).toBe(true);
  await page.waitForFunction(() => window.book.sound.level < 0.31);
  await page.evaluate(() => window.book.readingAloud.stop());
  expect(await page.evaluate(() => window.book.sound.ducked)).toBe(false);
  await page.waitForFunction(() => window.book.sound.level > 0.99);
});
