// The startup profile's instrument (scripts/bench/startup.mjs): run in the page before anything else by
// Chromium's init script; in Firefox and WebKit, whose drivers have none, by harness.js before the library loads.
// Wraps the calls each phase makes and notes when each ran and
// how long it blocked the main thread (GL calls that wait for the GPU process block here).
(() => {
  const t = { calls: {}, events: [], long: [], frames: [] };
  const frame = (now) => { t.frames.push(now); if (t.frames.length < 600) requestAnimationFrame(frame); };
  requestAnimationFrame(frame);  // when each animation frame ran, to see the frames between ready and the first frame
  window.__startup = t;
  const note = (name, start, end) => {
    const c = (t.calls[name] ??= { count: 0, ms: 0, first: start, last: end });
    c.count++;
    c.ms += end - start;
    c.last = end;
    if (end - start >= 1) t.long.push({ name, start, ms: end - start });  // to split the time after create() resolved
  };
  const wrap = (proto, name, label = name) => {
    const f = proto[name];
    if (typeof f !== 'function') return;
    proto[name] = function wrapped(...args) {
      const start = performance.now();
      try { return f.apply(this, args); } finally { note(label, start, performance.now()); }
    };
  };
  const wrapAsync = (object, name, label = name) => {
    const f = object[name];
    object[name] = function wrapped(...args) {
      const start = performance.now();
      const result = f.apply(this, args);
      Promise.resolve(result).then(() => t.events.push({ name: label, start, end: performance.now(), what: String(args[0]?.url ?? args[0] ?? '').slice(-40) }), () => {});
      return result;
    };
  };
  const gl = WebGL2RenderingContext.prototype;
  for (const name of ['compileShader', 'linkProgram', 'getShaderParameter', 'getProgramParameter', 'getUniformLocation',
    'getActiveUniform', 'texImage2D', 'texSubImage2D', 'drawArrays', 'drawElements', 'getParameter', 'getExtension',
    'getSupportedExtensions', 'readPixels', 'clear', 'generateMipmap']) wrap(gl, name);
  wrap(HTMLCanvasElement.prototype, 'getContext');
  wrapAsync(WebAssembly, 'instantiateStreaming');
  wrapAsync(WebAssembly, 'instantiate');
  wrapAsync(window, 'createImageBitmap');
  wrapAsync(window, 'fetch');
})();
