// The read-aloud marks on a curling leaf, for docs/features.md: a spread of text pages read aloud by an
// engine that begins a sentence (and, in the second picture, says a word in it), caught as the reading's
// own turn lifts the leaf: docs/media/read-aloud-sentence.png and read-aloud-word.png.
// Usage: node scripts/read-aloud-pictures.mjs (after scripts/build-wasm.sh)
import path from 'node:path';
import { chromium } from '@playwright/test';
import { chromiumLaunchOptions } from './chromium.mjs';
import { serveDirectory } from './serve.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
const TURN_MS = 30_000;  // a slow turn, so that the leaf is caught early in it
const CAUGHT_AT_MS = 2500;

const { server, url } = await serveDirectory(root);
const browser = await chromium.launch(chromiumLaunchOptions());
try {
  const page = await browser.newPage({ viewport: { width: 900, height: 600 } });
  await page.goto(`${url}tests/browser/fixtures/html-fixture.html`);
  await page.waitForFunction(() => document.body.dataset.ready);
  for (const withWord of [false, true]) {
    await page.evaluate(async ({ withWord, duration }) => {
      window.book?.destroy();
      const texts = ['Chapter one.', 'The pond was still.', 'A small paper boat set out on the pond one windy morning. '
        + 'It sailed past the reeds and the ducks, all the way to the far bank.', 'The boat came home at night.', 'The end.'];
      const pages = texts.map((t) => window.makeTextPage(t));
      window.book = await window.Flipbook.create(window.container, { pages, display: 'double', duration, startPage: 1 });
      await window.book.whenIdle();
      const quiet = { pause() {}, resume() {}, cancel() {} };
      // Says each page at once, except the boat's: its second sentence begins, (its word "ducks"), and ends.
      const engine = { speak(text, { onSentence, onWord, onEnd }) {
        if (text.includes('It sailed')) {
          onSentence(text.indexOf('It sailed'), text.length);
          if (withWord) onWord(text.indexOf('ducks'), 5);
        }
        setTimeout(onEnd, 20);
        return quiet;
      } };
      const started = new Promise((resolve) => window.book.addEventListener('turnstart', resolve, { once: true }));
      window.book.readAloud({ engine });
      await started;
    }, { withWord, duration: TURN_MS });
    await page.waitForTimeout(CAUGHT_AT_MS);  // a picture, not a test: the leaf some way into its turn
    const file = path.join(root, 'docs/media', `read-aloud-${withWord ? 'word' : 'sentence'}.png`);
    await page.locator('#container').screenshot({ path: file });
    console.log(`wrote ${path.relative(root, file)}`);
  }
} finally {
  await browser.close();
  server.close();
}
