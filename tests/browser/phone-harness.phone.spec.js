// Browser (phone): the phone projects are what they say (a mobile viewport of the screen's size at
// ratio 3 with touch), and a CDP tap reaches the page as a touch pointer event.
import { test, expect } from '@playwright/test';
import { PHONES, touchscreen } from './phone.js';

test('browser (phone): the project emulates its phone, and a CDP tap arrives as a pointer event of type touch', async ({ page }, testInfo) => {
  await page.goto('/web/demo/');
  const screen = PHONES[testInfo.project.name];
  const seen = await page.evaluate(() => ({
    width: innerWidth, height: innerHeight, ratio: devicePixelRatio, coarse: matchMedia('(pointer: coarse)').matches,
  }));
  expect(seen).toEqual({ width: screen.width, height: screen.height, ratio: 3, coarse: true });
  await page.evaluate(() => {
    window.pointerTypes = [];
    addEventListener('pointerdown', (e) => window.pointerTypes.push(e.pointerType), { capture: true });
  });
  const touch = await touchscreen(page);
  await touch.tap({ x: 10, y: 10 });
  await page.waitForFunction(() => window.pointerTypes.length > 0);
  expect(await page.evaluate(() => window.pointerTypes)).toEqual(['touch']);
});
