// A phone on a slow network, as the first-page measurements open one: the phone-portrait screen of the
// phone tests (390x844 at ratio 3, touch) in a fresh context, with CDP's network emulation (latency a
// request, a capped rate) and, if asked, a CPU slowdown. Shared by first-frame-network.mjs and first-spread.mjs.
import { PHONES, phoneUse } from '../../tests/browser/phone.js';

/**
 * A page of a new phone context of `browser`, throttled: `latency` ms a request, `kbps` down (and
 * `upKbps` up, default the same), CPU `cpu` times slower (1: as is). Resolves { page, cdp }.
 */
export async function throttledPhonePage(browser, { latency, kbps, upKbps = kbps, cpu = 1 }) {
  const page = await (await browser.newContext(phoneUse(PHONES['phone-portrait']))).newPage();
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.emulateNetworkConditions',
    { offline: false, latency, downloadThroughput: (kbps * 1000) / 8, uploadThroughput: (upKbps * 1000) / 8 });
  if (cpu !== 1) await cdp.send('Emulation.setCPUThrottlingRate', { rate: cpu });
  return { page, cdp };
}
