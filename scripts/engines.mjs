// The one place that says how Firefox and WebKit are found, launched and driven (as chromium.mjs does for
// Chromium): Debian's firefox-esr over WebDriver BiDi (puppeteer-core) and WebKitGTK's MiniBrowser through
// WebKitWebDriver (selenium-webdriver), both on an Xvfb display of their own, behind one small interface.
import { spawn } from 'node:child_process';
import net from 'node:net';
import { PNG } from 'pngjs';
import { findOnPath, isExecutableFile } from './chromium.mjs';

export const ENGINES = ['firefox', 'webkit'];

// Where Debian puts WebKitGTK 4.1's MiniBrowser (package libwebkit2gtk-4.1-0); WEBKIT_MINIBROWSER overrides.
const MINIBROWSER_DIRS = ['/usr/lib/x86_64-linux-gnu', '/usr/lib/aarch64-linux-gnu', '/usr/lib'];


/** The executables an engine needs, or an error saying how to install them. */
export function engineExecutables(engine, env = process.env) {
  const need = (path, what) => {
    if (path) return path;
    throw new Error(`no ${what}: run \`bash scripts/setup.sh\` (installs Debian's firefox-esr, webkit2gtk-driver and xvfb)`);
  };
  const xvfb = need(findOnPath('Xvfb', env), 'Xvfb on PATH');
  if (engine === 'firefox') return { xvfb, browser: need(env.FIREFOX_PATH || findOnPath('firefox-esr', env) || findOnPath('firefox', env), 'firefox-esr on PATH') };
  if (engine === 'webkit') {
    const mini = env.WEBKIT_MINIBROWSER || MINIBROWSER_DIRS.map((d) => `${d}/webkit2gtk-4.1/MiniBrowser`).find(isExecutableFile);
    return { xvfb, browser: need(mini, 'WebKitGTK MiniBrowser'), driver: need(findOnPath('WebKitWebDriver', env), 'WebKitWebDriver on PATH') };
  }
  throw new Error(`unknown engine '${engine}' (one of ${ENGINES.join(', ')})`);
}

/** Starts Xvfb on a free display; resolves with { display: ':N', stop() }. */
export function startDisplay(xvfb = engineExecutables('firefox').xvfb) {
  return new Promise((resolve, reject) => {
    const child = spawn(xvfb, ['-displayfd', '3', '-screen', '0', '1600x1200x24', '-nolisten', 'tcp', '-noreset'],
      { stdio: ['ignore', 'ignore', 'pipe', 'pipe'] });
    let said = '', errors = '';
    child.stderr.on('data', (d) => { errors += d; });
    child.stdio[3].on('data', (d) => {
      said += d;
      if (said.includes('\n')) resolve({ display: `:${said.trim()}`, stop: () => child.kill() });
    });
    child.on('exit', (code) => reject(new Error(`Xvfb exited (${code}) before it named a display: ${errors.trim().split('\n').pop()}`)));
  });
}

const freePort = () => new Promise((resolve, reject) => {
  const server = net.createServer();
  server.once('error', reject);
  server.listen(0, '127.0.0.1', () => { const { port } = server.address(); server.close(() => resolve(port)); });
});

/** The part of a PNG buffer inside `rect` ({ x, y, width, height } px from its top left), as a PNG buffer. */
export function cropPng(buffer, { x = 0, y = 0, width, height }) {
  const png = PNG.sync.read(buffer);
  const [left, top] = [Math.max(0, Math.round(x)), Math.max(0, Math.round(y))];
  const [w, h] = [Math.min(Math.round(width), png.width - left), Math.min(Math.round(height), png.height - top)];
  if (left === 0 && top === 0 && w === png.width && h === png.height) return buffer;
  const out = new PNG({ width: w, height: h });
  PNG.bitblt(png, out, left, top, w, h, 0, 0);
  return PNG.sync.write(out);
}

// One page's function and arguments as a script both protocols run: the function's own source, called
// with JSON arguments; a promise is awaited and its value comes back (JSON), an error as its message.
const callSource = (fn, args) => `(${fn.toString()})(...${JSON.stringify(args)})`;

/**
 * A browser of `engine` on `display`, with a viewport of `width` x `height` CSS px. Its methods:
 * goto(url), evaluate(fn, ...args) (fn runs in the page; its promise is awaited), waitFor(fn, ...args)
 * (until fn is truthy; no time limit of its own beyond `timeoutMs`), mouse.move/down/up(x, y),
 * click(x, y), doubleClick(x, y), drag(points, { release }) (a move a call), stroke(points, stepMs, { holdMs })
 * (pressed, moved `stepMs` apart, held still `holdMs` and let go, in one action sequence: a fling, or a
 * stop, whatever the round trips cost), key(name), screenshot() (PNG of the viewport), setViewport(w, h),
 * close(). `version` says which browser it is.
 */
export async function launchEngine(engine, { display, width = 800, height = 600, timeoutMs = 120_000, env = {} } = {}) {
  const exe = engineExecutables(engine);
  const environment = { ...process.env, DISPLAY: display, ...env };
  const browser = engine === 'firefox' ? await launchFirefox(exe, environment, { width, height })
    : await launchWebKit(exe, environment, { width, height, timeoutMs });
  browser.engine = engine;
  browser.waitFor = async (fn, ...args) => {
    const started = Date.now();
    for (;;) {
      const value = await browser.evaluate(fn, ...args);
      if (value) return value;
      if (Date.now() - started > timeoutMs) {
        // What the page saw meanwhile, where it keeps a log (tests/engines/heard.js): what it threw, the input that came.
        const seen = await browser.evaluate(() => [window.__explain?.(), window.__frames && `frames asked ${window.__frames.asked}, run ${window.__frames.ran} (last at ${window.__frames.lastRan}ms)`,
          ...(window.__heard || []), ...(window.__seen || [])]
          .filter(Boolean).join('; ')).catch(() => '');
        throw new Error(`${engine}: waited ${timeoutMs / 1000} s for ${fn.toString().slice(0, 160)}${seen ? `; the page saw: ${seen}` : ''}`);
      }
      await new Promise((resolve) => setTimeout(resolve, 50));  // a poll's spacing, not a wait for time to pass
    }
  };
  browser.click = async (x, y) => { await browser.mouse.move(x, y); await browser.mouse.down(); await browser.mouse.up(); };
  browser.drag = async (points, { release = true } = {}) => {
    await browser.mouse.move(points[0].x, points[0].y);
    await browser.mouse.down();
    for (const p of points.slice(1)) await browser.mouse.move(p.x, p.y);
    if (release) await browser.mouse.up();
  };
  return browser;
}

async function launchFirefox(exe, env, viewport) {
  const { default: puppeteer } = await import('puppeteer-core');
  const instance = await puppeteer.launch({
    browser: 'firefox', executablePath: exe.browser, headless: true, env,
    // No first-run pages, updates or telemetry; speech through speech-dispatcher where the test gave one.
    // No fullscreen transition: a request made while the last exit's transition runs is refused (a busy machine).
    extraPrefsFirefox: { 'media.webspeech.synth.enabled': true, 'app.update.enabled': false, 'browser.shell.checkDefaultBrowser': false,
      'full-screen-api.transition-duration.enter': '0 0', 'full-screen-api.transition-duration.leave': '0 0' },
  });
  const page = await instance.newPage();
  await page.setViewport(viewport);
  const size = { ...viewport };
  return {
    version: await instance.version(),
    async goto(url) { await page.goto(url, { waitUntil: 'load', timeout: 120_000 }); },
    evaluate: (fn, ...args) => page.evaluate(callSource(fn, args)),
    mouse: {
      move: (x, y) => page.mouse.move(Math.round(x), Math.round(y)),
      down: () => page.mouse.down(),
      up: () => page.mouse.up(),
    },
    doubleClick: (x, y) => page.mouse.click(Math.round(x), Math.round(y), { count: 2 }),
    // One action sequence, so the moves are `stepMs` apart by the browser's clock, not by round trips.
    stroke: (points, stepMs, { holdMs = 0 } = {}) => page.mainFrame().browsingContext.performActions([{
      type: 'pointer', id: '__puppeteer_mouse', actions: [
        { type: 'pointerMove', x: Math.round(points[0].x), y: Math.round(points[0].y) }, { type: 'pointerDown', button: 0 },
        ...points.slice(1).map((p) => ({ type: 'pointerMove', x: Math.round(p.x), y: Math.round(p.y), duration: stepMs })),
        ...(holdMs > 0 ? [{ type: 'pause', duration: holdMs }] : []),
        { type: 'pointerUp', button: 0 }],
    }]),
    key: (name) => page.keyboard.press(name),
    async screenshot() { return cropPng(Buffer.from(await page.screenshot({ type: 'png' })), size); },
    async setViewport(width, height) { Object.assign(size, { width, height }); await page.setViewport({ width, height }); },
    close: () => instance.close(),
  };
}

async function launchWebKit(exe, env, { width, height, timeoutMs }) {
  const { Builder, Capabilities } = await import('selenium-webdriver');
  const { Key } = await import('selenium-webdriver/lib/input.js');
  const port = await freePort();
  const driverProcess = spawn(exe.driver, [`--port=${port}`, '--host=127.0.0.1'], { env, stdio: 'ignore' });
  const driverExited = new Promise((resolve) => driverProcess.once('exit', resolve));
  let driver;
  for (let tries = 0; !driver; tries++) {
    try {
      driver = await new Builder().usingServer(`http://127.0.0.1:${port}`).withCapabilities(new Capabilities({
        browserName: 'MiniBrowser',
        'webkitgtk:browserOptions': { binary: exe.browser, args: ['--automation'] },
      })).build();
    } catch (error) {
      // The driver listens a moment after it starts: until then a refused connection is no answer.
      if (tries > 100 || !/ECONNREFUSED/.test(String(error))) { driverProcess.kill(); throw error; }
      await new Promise((resolve) => setTimeout(resolve, 100));  // a poll's spacing while the driver starts
    }
  }
  await driver.manage().setTimeouts({ script: timeoutMs, pageLoad: timeoutMs });
  const size = { width, height };
  // The window's frame takes some of its height: size the window so that the viewport is what was asked.
  // setRect answers before the page has seen the resize on a busy machine, so each size is read once the
  // page's outer size is the window's (the resize landed), never straight after the call.
  const landed = async () => {
    const { width: w, height: h } = await driver.manage().window().getRect();
    const started = Date.now();
    for (;;) {
      const [ow, oh, iw, ih] = await driver.executeScript('return [outerWidth, outerHeight, innerWidth, innerHeight]');
      if (ow === w && oh === h) return { frameWidth: ow - iw, frameHeight: oh - ih, w: iw, h: ih };
      if (Date.now() - started > timeoutMs) throw new Error(`webkit: the page never saw the window's ${w}x${h} (it has ${ow}x${oh})`);
      await new Promise((resolve) => setTimeout(resolve, 50));  // a poll's spacing while the resize lands
    }
  };
  const fit = async () => {
    await driver.manage().window().setRect({ width: size.width, height: size.height });
    const seen = await landed();
    if (seen.w !== size.width || seen.h !== size.height) {
      await driver.manage().window().setRect({ width: size.width + seen.frameWidth, height: size.height + seen.frameHeight });
      await landed();
    }
  };
  await fit();
  const keys = { ArrowRight: Key.ARROW_RIGHT, ArrowLeft: Key.ARROW_LEFT, ArrowUp: Key.ARROW_UP, ArrowDown: Key.ARROW_DOWN,
    PageDown: Key.PAGE_DOWN, PageUp: Key.PAGE_UP, Home: Key.HOME, End: Key.END, Escape: Key.ESCAPE, Enter: Key.ENTER, Tab: Key.TAB };
  const pointer = { x: 0, y: 0 };
  const act = (build) => build(driver.actions({ async: true })).perform();
  return {
    version: `webkitgtk/${(await driver.getCapabilities()).get('browserVersion')}`,
    async goto(url) { await driver.get(url); },
    async evaluate(fn, ...args) {
      const result = await driver.executeAsyncScript(`const done = arguments[arguments.length - 1];
        Promise.resolve().then(() => ${callSource(fn, args)}).then((value) => done({ value: value === undefined ? null : value }),
          (error) => done({ error: String(error && error.stack || error) }));`);
      if (result && result.error) throw new Error(`in the page: ${result.error}`);
      return result ? result.value : null;
    },
    mouse: {
      move: (x, y) => { Object.assign(pointer, { x: Math.round(x), y: Math.round(y) }); return act((a) => a.move({ x: pointer.x, y: pointer.y, duration: 0 })); },
      down: () => act((a) => a.press()),
      up: () => act((a) => a.release()),
    },
    // One action sequence, each move `stepMs` long by the driver's clock: a fling whatever the round trips cost.
    stroke: (points, stepMs, { holdMs = 0 } = {}) => act((a) => {
      const at = (p, duration) => ({ x: Math.round(p.x), y: Math.round(p.y), duration });
      let chain = a.move(at(points[0], 0)).press();
      for (const p of points.slice(1)) chain = chain.move(at(p, stepMs));
      if (holdMs > 0) chain = chain.pause(holdMs);
      return chain.release();
    }),
    doubleClick: (x, y) => { Object.assign(pointer, { x: Math.round(x), y: Math.round(y) }); return act((a) => a.move({ x: pointer.x, y: pointer.y }).doubleClick()); },
    key: (name) => act((a) => a.sendKeys(keys[name] ?? name)),
    // Element screenshots come back with a black band: the window's, cut to the viewport, is right.
    async screenshot() { return cropPng(Buffer.from(await driver.takeScreenshot(), 'base64'), size); },
    async setViewport(w, h) { Object.assign(size, { width: w, height: h }); await fit(); },
    async close() {
      await driver.quit().catch(() => {});
      driverProcess.kill();
      await driverExited;
    },
  };
}
