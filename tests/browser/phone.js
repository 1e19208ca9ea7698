// Phones in the browser tests: the three screens the phone projects emulate (playwright.config.js runs
// every *.phone.spec.js on each), and touch sent through CDP with the events' own timestamps, so a drag
// is a drag and a fling is a fling however busy the machine is.

/** The phone screens, by project name: CSS px, ratio 3, touch, a mobile viewport. */
export const PHONES = {
  'phone-portrait': { width: 390, height: 844 },
  'phone-landscape': { width: 844, height: 390 },
  'phone-small': { width: 320, height: 568 },
};

/** Playwright `use` options for a phone of that screen. */
export const phoneUse = ({ width, height }) => ({
  viewport: { width, height }, screen: { width, height }, deviceScaleFactor: 3, isMobile: true, hasTouch: true,
});

/**
 * Touch input on `page` through CDP, on a clock of its own: each event is stamped `ms` after the one
 * before (16 ms unless told), so velocities come from the stamps, never from how fast the machine is.
 * Points are viewport CSS px.
 */
export async function touchscreen(page) {
  const cdp = await page.context().newCDPSession(page);
  let time = Date.now() / 1000;
  const send = (type, points, ms = 16) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map((p, i) => ({ x: p.x, y: p.y, id: p.id ?? i + 1, radiusX: 4, radiusY: 4 })),
    timestamp: (time += ms / 1000),
  });
  const api = {
    /** One finger: down at path[0], through the rest `ms` apart, held `holdMs` at the end, then up. */
    async stroke(path, { ms = 16, holdMs = 0 } = {}) {
      await send('touchStart', [path[0]], ms);
      for (const p of path.slice(1)) await send('touchMove', [p], ms);
      if (holdMs > 0) await send('touchMove', [path[path.length - 1]], holdMs);
      await send('touchEnd', [], ms);
    },
    /** A straight stroke from `from` to `to` in `steps` moves over `durationMs`, held `holdMs` before lifting. */
    async drag(from, to, { steps = 12, durationMs = 320, holdMs = 150 } = {}) {
      const path = [];
      for (let i = 0; i <= steps; i++) {
        const t = i / steps;
        path.push({ x: from.x + (to.x - from.x) * t, y: from.y + (to.y - from.y) * t });
      }
      await api.stroke(path, { ms: durationMs / steps, holdMs });
    },
    /** A tap: down and up 60 ms apart; `gapMs` is the time since the previous event (a new tap, not a double). */
    async tap(p, { gapMs = 1000 } = {}) {
      await send('touchStart', [p], gapMs);
      await send('touchEnd', [], 60);
    },
    /** Two taps 150 ms apart at the same point. */
    async doubleTap(p) {
      await api.tap(p);
      await api.tap(p, { gapMs: 150 });
    },
    /** Two fingers about `center`, `from` px apart to `to` px apart (horizontally), in `steps` moves. */
    async pinch(center, from, to, { steps = 8, ms = 16 } = {}) {
      const at = (d) => [{ x: center.x - d / 2, y: center.y, id: 1 }, { x: center.x + d / 2, y: center.y, id: 2 }];
      await send('touchStart', at(from), 1000);
      for (let i = 1; i <= steps; i++) await send('touchMove', at(from + ((to - from) * i) / steps), ms);
      await send('touchEnd', [], ms);
    },
    send,
  };
  return api;
}

/** The viewport rect ({ x, y, width, height }, CSS px) of the first element matching `selector`, or null. */
export const boxOf = (page, selector) => page.locator(selector).first().boundingBox();
