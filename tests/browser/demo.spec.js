// Browser: the demo page served by `npm start` loads without errors, shows the page, and its button
// turns the page over and back, ending on exact frames.
import { test, expect } from '@playwright/test';
import { openReady } from './helpers.js';

test('browser: demo loads with no console error and draws the page', async ({ page }) => {
  const problems = await openReady(page, '/web/demo/');
  expect(problems).toEqual([]);
  await expect(page.locator('#readout')).toContainText('θ 90.0°');
  const drawn = await page.evaluate(() => {
    const canvas = document.getElementById('book');
    return canvas.width > 0 && canvas.height > 0;
  });
  expect(drawn).toBe(true);
});

test('browser: demo button turns the page to t=1 and back to t=0', async ({ page }) => {
  await openReady(page, '/web/demo/');
  await page.selectOption('#duration', '600');
  await page.click('#turn');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'turned', { timeout: 15000 });
  await expect(page.locator('#readout')).toContainText('t 1.000');
  await expect(page.locator('#readout')).toContainText('ρ 180.0°');
  await expect(page.locator('#turn')).toHaveText('Turn back');
  await page.click('#turn');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'open', { timeout: 15000 });
  await expect(page.locator('#readout')).toContainText('t 0.000');
});

test('browser: demo ?t=0.25 opens frozen at that frame with the schedule read out', async ({ page }) => {
  await openReady(page, '/web/demo/?t=0.25');
  await expect(page.locator('#readout')).toContainText('t 0.250');
  await expect(page.locator('#readout')).toContainText('ρ 45.0°');
});
