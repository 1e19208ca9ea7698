// Put first into every page the cross-engine suite opens (its server adds it to each <head>): what the
// page throws, rejects or logs as an error, kept on window.__heard, since WebKit's driver hears no console;
// and the last input events, fullscreen changes and WebGL context losses the page saw (window.__seen) and its animation frames
// (window.__frames), told when a wait times out, with what the test adds (window.__explain()).
(() => {
  const heard = (window.__heard = []);
  const say = (kind, what) => heard.push(`${kind}: ${what instanceof Error ? `${what.name}: ${what.message}` : String(what)}`);
  window.addEventListener('error', (event) => { if (event instanceof ErrorEvent) say('error', event.error || event.message); });
  window.addEventListener('unhandledrejection', (event) => say('unhandled rejection', event.reason && (event.reason.message || event.reason)));
  const consoleError = console.error;
  console.error = (...args) => { say('console.error', args.map(String).join(' ')); consoleError.apply(console, args); };
  const seen = (window.__seen = []);
  const t0 = performance.now();
  const note = (event) => {
    const where = 'clientX' in event ? ` ${Math.round(event.clientX)},${Math.round(event.clientY)}` : '';
    const on = event.target && event.target.nodeName ? event.target.nodeName.toLowerCase() : 'document';
    seen.push(`${Math.round(performance.now() - t0)}ms ${event.type}${where} on ${on}${event.defaultPrevented ? ' (prevented)' : ''}`);
    if (seen.length > 40) seen.shift();
  };
  // (WebGL's context events do not bubble: a listener on the window in the capture phase hears every canvas's.)
  for (const type of ['pointerdown', 'pointerup', 'click', 'dblclick', 'keydown', 'fullscreenchange', 'fullscreenerror', 'blur', 'focus',
    'webglcontextlost', 'webglcontextrestored']) {
    window.addEventListener(type, note, { capture: true });
  }
  document.addEventListener('visibilitychange', () => note({ type: `visibilitychange (${document.visibilityState})`, target: document }));
  // Animation frames asked for and run: a wait that times out says whether the page's clock stood still.
  const frames = (window.__frames = { asked: 0, ran: 0, lastRan: 0 });
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => {
    frames.asked += 1;
    return raf((now) => { frames.ran += 1; frames.lastRan = Math.round(performance.now() - t0); callback(now); });
  };
})();
