// What Embind costs on the one call a frame makes (FrameLoop.tick): calls per second through Embind
// against the same C++ through a plain C ABI export (conecurl_frame_tick, test build only), in Node.
// A book at rest, no drawing (the clock still composes the frame); and a call that does next to nothing
// (queuedTurns), which weighs the call alone.
// Usage: node scripts/bench/embind-call.mjs [calls]
import fs from 'node:fs';

const dist = new URL('../../dist/test/', import.meta.url);
const { default: createEngine } = await import(new URL('conecurl-engine.mjs', dist));
const engine = await createEngine({ wasmBinary: fs.readFileSync(new URL('conecurl-engine.wasm', dist)) });
const calls = Number(process.argv[2]) || 2_000_000;

const book = engine.Book.create({ pageCount: 20, display: 'double' });
const loop = new engine.FrameLoop(book, null);  // no renderer: tick(now, false) never draws
const pointer = loop.$$.ptr;  // Embind's handle on the C++ object, for the C ABI call
// cwrap of numbers only hands back the wasm export itself: no conversion in the way.
const cTick = engine.cwrap('conecurl_frame_tick', 'number', ['number', 'number', 'number']);
const cQueued = engine.cwrap('conecurl_frame_queued_turns', 'number', ['number']);
if (typeof cTick !== 'function' || typeof cQueued !== 'function') throw new Error('embind-call: the test build has no conecurl_frame_tick (rebuild: bash scripts/build-wasm.sh)');

function measure(label, call) {
  let sink = 0;
  for (let i = 0; i < 50_000; i++) sink += call(i);  // warm up the JIT
  const start = process.hrtime.bigint();
  for (let i = 0; i < calls; i++) sink += call(i * 16);
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  return { label, perSecond: calls / seconds, nsPerCall: (seconds / calls) * 1e9, sink };
}

const results = [];
for (let round = 0; round < 3; round++) {
  results.push(measure('embind FrameLoop.tick', (t) => loop.tick(t, false)));
  results.push(measure('C ABI conecurl_frame_tick', (t) => cTick(pointer, t, 0)));
  results.push(measure('embind FrameLoop.queuedTurns', () => loop.queuedTurns()));
  results.push(measure('C ABI queued_turns', () => cQueued(pointer)));
}
for (const label of new Set(results.map((r) => r.label))) {
  const best = results.filter((r) => r.label === label).sort((a, b) => a.nsPerCall - b.nsPerCall)[0];
  console.log(`${label.padEnd(28)} ${(best.perSecond / 1e6).toFixed(2)} M calls/s, ${best.nsPerCall.toFixed(0)} ns a call (best of 3, ${calls} calls)`);
}
loop.delete();
book.delete();
