// Node tests of the wasm build's math bindings: the schedule table, continuity, and curlPoint held
// against an independent JS transcription of docs/cone-curl-math.md over dense grids.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { loadEngineForNode } from './load-engine.mjs';

const deg = Math.PI / 180;
let engine;
before(async () => { engine = await loadEngineForNode(); });

// --- the doc's formulas, written again without the engine's guards or stable rewrites ------------
const lerp = (f, a, b) => a + (b - a) * f;
const ease = (dt, k) => Math.sin((Math.PI / 2) * dt ** k);
function docSchedule(t, H = 1) {
  let theta, ay;
  if (t <= 0.15) {
    const dt = t / 0.15;
    theta = lerp(ease(dt, 0.05), 90 * deg, 8 * deg);
    ay = lerp(ease(dt, 0.5), -15, -2.5);
  } else if (t <= 0.4) {
    const dt = (t - 0.15) / 0.25;
    theta = lerp(dt, 8 * deg, 6 * deg);
    ay = lerp(dt, -2.5, -3.5);
  } else {
    const dt = (t - 0.4) / 0.6;
    theta = lerp(ease(dt, 10), 6 * deg, 90 * deg);
    ay = lerp(ease(dt, 2), -3.5, -15);
  }
  return { theta, apexY: ay * H, rho: Math.PI * t };
}
function docCurl(x, y, { theta, apexY, rho }) {
  const R = Math.hypot(x, y - apexY);
  const r = R * Math.sin(theta);
  const beta = Math.asin(x / R) / Math.sin(theta);
  const v = [
    r * Math.sin(beta),
    R + apexY - r * (1 - Math.cos(beta)) * Math.sin(theta),
    r * (1 - Math.cos(beta)) * Math.cos(theta),
  ];
  return [v[0] * Math.cos(rho) - v[2] * Math.sin(rho), v[1], v[0] * Math.sin(rho) + v[2] * Math.cos(rho)];
}
function docNormal(x, y, { theta, apexY, rho }) {
  const beta = Math.asin(x / Math.hypot(x, y - apexY)) / Math.sin(theta);
  const [s, c] = [Math.sin(theta), Math.cos(theta)];
  const n = [-c * Math.sin(beta), s * c * (1 - Math.cos(beta)), s * s + c * c * Math.cos(beta)];
  return [n[0] * Math.cos(rho) - n[2] * Math.sin(rho), n[1], n[0] * Math.sin(rho) + n[2] * Math.cos(rho)];
}

const times = Array.from({ length: 1001 }, (_, i) => i / 1000);
const pagePoints = [];
for (let j = 0; j <= 25; j++) for (let i = 0; i <= 20; i++) pagePoints.push([0.8 * i / 20, j / 25]);

test('node: curlAt matches the Nuon table at t = 0, 0.15, 0.4 and 1', () => {
  const table = [[0, 90, -15, 0], [0.15, 8, -2.5, 27], [0.4, 6, -3.5, 72], [1, 90, -15, 180]];
  for (const [t, thetaDeg, apexY, rhoDeg] of table) {
    const p = engine.curlAt(t);
    assert.ok(Math.abs(p.theta - thetaDeg * deg) < 1e-12, `theta at t=${t}: ${p.theta / deg} deg`);
    assert.ok(Math.abs(p.apexY - apexY) < 1e-12, `apexY at t=${t}: ${p.apexY}`);
    assert.ok(Math.abs(p.rho - rhoDeg * deg) < 1e-12, `rho at t=${t}: ${p.rho / deg} deg`);
  }
});

test('node: curlAt equals the doc schedule on 1001 times and is continuous at the phase boundaries', () => {
  let worst = 0;
  for (const t of times) {
    const a = engine.curlAt(t);
    const b = docSchedule(t);
    worst = Math.max(worst, Math.abs(a.theta - b.theta), Math.abs(a.apexY - b.apexY), Math.abs(a.rho - b.rho));
  }
  assert.ok(worst < 1e-12, `worst schedule difference ${worst}`);
  for (const edge of [0.15, 0.4]) {
    const below = engine.curlAt(edge - 1e-9);
    const above = engine.curlAt(edge + 1e-9);
    for (const key of ['theta', 'apexY', 'rho']) {
      assert.ok(Math.abs(below[key] - above[key]) < 1e-6, `${key} jumps at t=${edge}: ${below[key]} vs ${above[key]}`);
    }
  }
});

test('node: curlAtWith scales the apex by page height and honours custom constants', () => {
  const schedule = engine.defaultSchedule();
  const tall = engine.curlAtWith(0.3, schedule, 1.5);
  const unit = engine.curlAt(0.3);
  assert.ok(Math.abs(tall.apexY - 1.5 * unit.apexY) < 1e-12);
  assert.equal(tall.theta, unit.theta);
  assert.equal(tall.rho, unit.rho);
  const custom = engine.curlAtWith(0.15, { ...schedule, thetaPhase1: 20 * deg, apexPhase1: -4 }, 1);
  assert.ok(Math.abs(custom.theta - 20 * deg) < 1e-12 && Math.abs(custom.apexY + 4) < 1e-12);
});

test('node: curlPoint and its normal equal the doc formulas over 546 page points x 1001 times', () => {
  let worstPoint = 0;
  let worstNormal = 0;
  let where = '';
  for (const t of times) {
    const params = engine.curlAt(t);
    for (const [x, y] of pagePoints) {
      const got = engine.curlPoint(x, y, params);
      const want = docCurl(x, y, params);
      const e = Math.max(Math.abs(got.x - want[0]), Math.abs(got.y - want[1]), Math.abs(got.z - want[2]));
      if (e > worstPoint) { worstPoint = e; where = `t=${t} (${x}, ${y})`; }
      const n = docNormal(x, y, params);
      worstNormal = Math.max(worstNormal,
        Math.abs(got.normal.x - n[0]), Math.abs(got.normal.y - n[1]), Math.abs(got.normal.z - n[2]));
    }
  }
  // The engine uses cancellation-free rewrites of the same formulas: they agree to rounding.
  assert.ok(worstPoint < 1e-12, `worst point difference ${worstPoint} at ${where}`);
  assert.ok(worstNormal < 1e-12, `worst normal difference ${worstNormal}`);
});

test('node: invariants hold in the wasm build: apex distance, fixed spine, flat ends, unit normals', () => {
  for (const t of times.filter((_, i) => i % 10 === 0)) {
    const p = engine.curlAt(t);
    for (const [x, y] of pagePoints) {
      const q = engine.curlPoint(x, y, p);
      const R = Math.hypot(x, y - p.apexY);
      assert.ok(Math.abs(Math.hypot(q.x, q.y - p.apexY, q.z) - R) < 1e-12, `apex distance at t=${t}`);
      const n = q.normal;
      assert.ok(Math.abs(Math.hypot(n.x, n.y, n.z) - 1) < 1e-12, 'unit normal');
      if (x === 0) assert.ok(Math.abs(q.x) + Math.abs(q.y - y) + Math.abs(q.z) < 1e-12, `spine moved at t=${t}`);
    }
  }
  for (const [x, y] of pagePoints) {
    const start = engine.curlPoint(x, y, engine.curlAt(0));
    const end = engine.curlPoint(x, y, engine.curlAt(1));
    assert.ok(Math.abs(start.x - x) + Math.abs(start.y - y) + Math.abs(start.z) < 1e-12, 'flat at t=0');
    assert.ok(Math.abs(end.x + x) + Math.abs(end.y - y) + Math.abs(end.z) < 1e-9, 'flat and turned at t=1');
  }
});

test('node: the finite-difference normal of the paper agrees with the analytic normal', () => {
  let worst = 0;
  for (const t of times.filter((_, i) => i % 20 === 0)) {
    const p = engine.curlAt(t);
    for (const [x, y] of pagePoints) {
      const a = engine.curlPoint(x, y, p).normal;
      const f = engine.curlNormalFiniteDifference(x, y, p, 1e-6);
      worst = Math.max(worst, Math.abs(a.x - f.x), Math.abs(a.y - f.y), Math.abs(a.z - f.z));
    }
  }
  assert.ok(worst < 1e-4, `worst normal disagreement ${worst}`);
});

test('node: bad parameters give finite output, never NaN', () => {
  const bad = [
    { theta: NaN, apexY: NaN, rho: NaN },
    { theta: 0, apexY: 0, rho: 0 },
    { theta: -1, apexY: 2, rho: Infinity },
  ];
  for (const params of bad) {
    for (const [x, y] of [[0, 0], [0.8, 0], [0.8, 1], [0.4, 0.5]]) {
      const q = engine.curlPoint(x, y, params);
      for (const v of [q.x, q.y, q.z, q.normal.x, q.normal.y, q.normal.z]) {
        assert.ok(Number.isFinite(v), `non-finite output for ${JSON.stringify(params)} at (${x}, ${y})`);
      }
    }
  }
  for (const t of [NaN, -1, 2]) {
    const p = engine.curlAt(t);
    assert.ok([p.theta, p.apexY, p.rho].every(Number.isFinite), `curlAt(${t}) not finite`);
  }
  const s = engine.sanitizeCurlParams({ theta: 0, apexY: 1, rho: NaN });
  assert.ok(s.theta > 0 && s.apexY < 0 && s.rho === 0);
});
