// Node tests of the benchmark's arithmetic and page images (not of any speed): order statistics,
// ratios taken within one repetition, the target verdicts (against the peers and against the floor),
// that the report shows the floor targets (the phone configuration judged by its own) and, with a baseline
// checkout, before and after, the engine rows (conecurl against the WebGL floor in each engine, an engine
// not installed saying so), and that the generated PNGs are valid.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import zlib from 'node:zlib';
import { summarize } from '../../scripts/bench/metrics.mjs';
import {
  BEFORE_AFTER, drawingText, ENGINE_METRICS, FLOOR_TARGETS, floorLimitText, markdown, readmeTables, summarizeEngines, summarizeRuns,
} from '../../scripts/bench/report.mjs';
import { drawPage, encodePalettePng, PAGE_HEIGHT, PAGE_WIDTH } from '../../scripts/bench/page-images.mjs';

test('node: bench summarize gives the median of an even count and the nearest-rank p95', () => {
  const s = summarize([4, 1, 3, 2]);
  assert.equal(s.median, 2.5);
  assert.equal(s.min, 1);
  assert.equal(s.max, 4);
  const hundred = summarize(Array.from({ length: 100 }, (_, i) => i + 1));
  assert.equal(hundred.p95, 95);
  assert.ok(Number.isNaN(summarize([]).median));
});

// A run result with just what the report reads; `scale` multiplies every figure.
function fakeResult({ frameMs, mainMs, gpuMs, idle = 0.5, first = 1000, textures, frames = 3, turnMs = 1000, askedTurnMs = 1000, drawing, renderer }) {
  return {
    ...(drawing ? { drawing } : {}),
    ...(renderer ? { renderer } : {}),
    firstFrameMs: first,
    turnSeconds: turnMs / 1000,
    askedTurnMs,
    turns: [{ start: 0, end: turnMs }],
    intervals: Array.from({ length: frames }, () => frameMs),
    frames,
    perFrame: { mainThreadMs: mainMs, scriptMs: 0, rendererCpuMs: mainMs, gpuCpuMs: gpuMs },
    idle: { totalCpuPercent: idle, mainThreadPercent: 0 },
    memory: { jsHeapBytes: 1 << 20, rendererPssBytes: 1 << 20, gpuPssBytes: 1 << 20 },
    stats: textures === undefined ? {} : { pageTextures: textures, wasmHeapBytes: 1 << 24 },
  };
}

test('node: bench ratios to the best peer come from the same repetition, not from the medians', () => {
  const configs = [{ id: 'double-20', display: 'double', pages: 20 }];
  // Repetition 1 is slow for everyone, repetition 2 fast: per-repetition ratios are 0.4 and 0.4,
  // while the ratio of medians across repetitions would mix the two machines' states.
  const runs = [
    { rep: 1, config: 'double-20', lib: 'conecurl', result: fakeResult({ frameMs: 40, mainMs: 4, gpuMs: 80, first: 1200 }) },
    { rep: 1, config: 'double-20', lib: 'page-flip', result: fakeResult({ frameMs: 100, mainMs: 10, gpuMs: 100 }) },
    { rep: 1, config: 'double-20', lib: 'turnjs', result: fakeResult({ frameMs: 200, mainMs: 20, gpuMs: 50 }) },
    { rep: 2, config: 'double-20', lib: 'conecurl', result: fakeResult({ frameMs: 4, mainMs: 0.4, gpuMs: 8, first: 1200 }) },
    { rep: 2, config: 'double-20', lib: 'page-flip', result: fakeResult({ frameMs: 10, mainMs: 1, gpuMs: 10 }) },
    { rep: 2, config: 'double-20', lib: 'turnjs', result: fakeResult({ frameMs: 20, mainMs: 2, gpuMs: 5 }) },
  ];
  const { ratios, targets } = summarizeRuns(runs, configs, { conecurl: { totalGzip: 40 * 1024, jsGzip: 0, wasmGzip: 0 } });
  const main = ratios['double-20'].mainThreadMsPerFrame;
  assert.equal(main.bestPeer.median, 0.4);
  assert.equal(main['page-flip'].median, 0.4);
  assert.equal(main.turnjs.median, 0.2);
  // The best peer is chosen per metric: turn.js for GPU time (50 and 5), so 80/50 and 8/5.
  assert.equal(ratios['double-20'].gpuCpuMsPerFrame.bestPeer.median, 1.6);
  const verdict = Object.fromEntries(targets.map((t) => [t.id, t.holds]));
  // Turns and memory equal to the peers' (1.0x) hold; ready 1.2x does not.
  assert.deepEqual(verdict, { 'main-thread': true, gpu: false, turn: true, memory: true, ready: false, idle: true, smooth: true, bytes: false });
  assert.equal(targets.find((t) => t.id === 'ready').values[0].value, 1.2);
});

test('node: bench 1000-page targets compare first frames and resident textures within a repetition', () => {
  const configs = [
    { id: 'single-20', display: 'single', pages: 20 },
    { id: 'single-1000', display: 'single', pages: 1000 },
  ];
  const run = (rep, config, first, textures) => ({
    rep, config, lib: 'conecurl', result: fakeResult({ frameMs: 10, mainMs: 1, gpuMs: 1, first, textures }),
  });
  const runs = [run(1, 'single-20', 1000, 5), run(1, 'single-1000', 1400, 5), run(2, 'single-20', 500, 5), run(2, 'single-1000', 1000, 6)];
  const { targets } = summarizeRuns(runs, configs, {});
  const first = targets.find((t) => t.id === 'first-frame-single');
  assert.equal(first.values[0].value, (1.4 + 2) / 2);
  assert.equal(first.holds, false);
  const textures = targets.find((t) => t.id === 'textures-single');
  assert.equal(textures.holds, false, 'one repetition kept 6 textures for 1000 pages and 5 for 20');
});

test('node: bench compares the most page textures after any turn, not the count at the end of a short book', () => {
  const configs = [
    { id: 'double-20', display: 'double', pages: 20 },
    { id: 'double-1000', display: 'double', pages: 1000 },
  ];
  const run = (config, perTurn) => {
    const result = fakeResult({ frameMs: 10, mainMs: 1, gpuMs: 1, textures: perTurn[perTurn.length - 1] });
    result.turnStats = perTurn.map((pageTextures) => ({ pageTextures }));
    return { rep: 1, config, lib: 'conecurl', result };
  };
  // The 20-page book reaches its back cover, where the load window holds only 5 pages.
  const bounded = summarizeRuns([run('double-20', [8, 10, 10, 5]), run('double-1000', [8, 10, 10, 10])], configs, {});
  assert.equal(bounded.targets.find((t) => t.id === 'textures-double').holds, true);
  const growing = summarizeRuns([run('double-20', [8, 10, 10, 5]), run('double-1000', [8, 10, 12, 14])], configs, {});
  assert.equal(growing.targets.find((t) => t.id === 'textures-double').holds, false);
});

test('node: bench page images are valid palette PNGs with the page number in ink', () => {
  const pixels = drawPage(122);
  const png = encodePalettePng(PAGE_WIDTH, PAGE_HEIGHT, pixels, [[255, 255, 255], [0, 0, 0]]);
  assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  const chunks = [];
  for (let at = 8; at < png.length;) {
    const length = png.readUInt32BE(at);
    const type = png.toString('ascii', at + 4, at + 8);
    const data = png.subarray(at + 8, at + 8 + length);
    assert.equal(png.readUInt32BE(at + 8 + length), zlib.crc32(png.subarray(at + 4, at + 8 + length)), `CRC of ${type}`);
    chunks.push({ type, data });
    at += 12 + length;
  }
  assert.deepEqual(chunks.map((c) => c.type), ['IHDR', 'PLTE', 'IDAT', 'IEND']);
  assert.equal(chunks[0].data.readUInt32BE(0), PAGE_WIDTH);
  assert.equal(chunks[0].data.readUInt32BE(4), PAGE_HEIGHT);
  const raw = zlib.inflateSync(chunks[2].data);
  assert.equal(raw.length, (PAGE_WIDTH + 1) * PAGE_HEIGHT);
  for (let y = 0; y < PAGE_HEIGHT; y++) assert.equal(raw[y * (PAGE_WIDTH + 1)], 0, 'filter byte 0 on every row');
  // The big number "123" sits centred from y = 70 to 154; its first digit's stem is ink.
  const ink = (x, y) => raw[y * (PAGE_WIDTH + 1) + 1 + x] === 1;
  let inkInNumber = 0;
  for (let y = 70; y < 154; y++) for (let x = 200; x < 440; x++) inkInNumber += ink(x, y);
  assert.ok(inkInNumber > 2000, `the page number is drawn (${inkInNumber} ink pixels)`);
  assert.notDeepEqual(drawPage(1), drawPage(2), 'pages differ');
  assert.deepEqual(drawPage(7), drawPage(7), 'pages are the same on every run');
});

// A small run with conecurl, the two floors and the peers in two configurations, one repetition:
// double-20 meets every floor target, single-20 misses the GPU and frames targets.
function floorFixture({ withFloor = true } = {}) {
  const configs = [
    { id: 'double-20', display: 'double', pages: 20, label: 'Two-page spread, 1600x1100, 20 pages' },
    { id: 'single-20', display: 'single', pages: 20, label: 'Single page, 800x1100, 20 pages' },
  ];
  const figures = {
    'double-20': {
      conecurl: { gpuMs: 120, frames: 45, mainMs: 4, turnMs: 620 },
      'floor-webgl': { gpuMs: 100, frames: 50, mainMs: 4, turnMs: 610 },
      'floor-2d': { gpuMs: 40, frames: 30, mainMs: 8, turnMs: 640 },
      'page-flip': { gpuMs: 150, frames: 40, mainMs: 4, turnMs: 660 },
      turnjs: { gpuMs: 160, frames: 38, mainMs: 8, turnMs: 630 },
    },
    'single-20': {
      conecurl: { gpuMs: 60, frames: 30, mainMs: 6, turnMs: 690 },
      'floor-webgl': { gpuMs: 40, frames: 60, mainMs: 2, turnMs: 610 },
      'floor-2d': { gpuMs: 20, frames: 40, mainMs: 4, turnMs: 610 },
      'page-flip': { gpuMs: 60, frames: 50, mainMs: 2, turnMs: 480 },
      turnjs: { gpuMs: 70, frames: 45, mainMs: 4, turnMs: 620 },
    },
  };
  const runs = [];
  for (const [config, libs] of Object.entries(figures)) {
    for (const [lib, f] of Object.entries(libs)) {
      if (!withFloor && lib === 'floor-webgl') continue;
      runs.push({ rep: 1, config, lib, result: fakeResult({ frameMs: 600 / f.frames, askedTurnMs: 600, ...f }) });
    }
  }
  const loadBytes = { conecurl: { js: 0, wasm: 0, totalGzip: 40 * 1024, jsGzip: 25 * 1024, wasmGzip: 15 * 1024 } };
  const meta = {
    date: '2026-11-25T17:00:00Z', chromium: 'Chromium 0', cpus: 2, reps: 1, turns: 1, turnDurationMs: 600, idleMs: 2000,
    wallSeconds: 60, loadavgStart: [1, 1, 1], loadavgEnd: [1, 1, 1],
  };
  return { configs, runs, loadBytes, meta };
}

test('node: bench floor targets are issue 24\'s five for the desktop and issue 29\'s four for the phone, each a ratio to the WebGL floor, the asked duration or KB', () => {
  assert.deepEqual(FLOOR_TARGETS.map((t) => [t.id, t.screen ?? 'all', floorLimitText(t)]), [
    ['floor-gpu', 'desktop', "<= 1.3x the WebGL floor's"],
    ['floor-frames', 'desktop', ">= 0.8x the WebGL floor's"],
    ['floor-main', 'desktop', "<= 1.1x the WebGL floor's"],
    ['turn-asked', 'desktop', '<= 1.05x the asked duration'],
    ['load', 'all', '<= 30 KB'],
    ['phone-frames', 'phone', ">= 0.8x the WebGL floor's"],
    ['phone-gpu', 'phone', "<= 1.5x the WebGL floor's"],
    ['phone-turn-asked', 'phone', '<= 1.05x the asked duration'],
    ['phone-first-page', 'phone', "<= 1.1x the WebGL floor's"],
  ]);
  assert.deepEqual(FLOOR_TARGETS.filter((t) => t.screen === 'phone').map((t) => t.metric),
    ['frames', 'gpuCpuMsPerFrame', 'turnOverAsked', 'firstFrameMs']);
});

test('node: bench floor targets measure conecurl against the WebGL floor per configuration and say which hold', () => {
  const { configs, runs, loadBytes } = floorFixture();
  const { floorTargets, ratios } = summarizeRuns(runs, configs, loadBytes);
  const byId = Object.fromEntries(floorTargets.map((t) => [t.id, t]));
  const values = (id) => byId[id].values.map((v) => [v.config, Number(v.value.toFixed(4))]);
  assert.deepEqual(values('floor-gpu'), [['double-20', 1.2], ['single-20', 1.5]]);
  assert.equal(byId['floor-gpu'].holds, false, 'single-20 is 1.5x the floor');
  assert.deepEqual(values('floor-frames'), [['double-20', 0.9], ['single-20', 0.5]]);
  assert.equal(byId['floor-frames'].holds, false);
  // Over the turns, not per frame: 4 ms x 45 frames against 4 ms x 50, and 6 x 30 against 2 x 60.
  assert.deepEqual(values('floor-main'), [['double-20', 0.9], ['single-20', 1.5]]);
  assert.equal(byId['floor-main'].holds, false);
  assert.deepEqual(values('turn-asked'), [['double-20', 1.0333], ['single-20', 1.15]]);
  assert.equal(byId['turn-asked'].holds, false);
  assert.deepEqual(values('load'), [['all', 40]]);
  assert.equal(byId.load.holds, false);
  // The same ratios sit beside the peers' in the tables.
  assert.equal(ratios['double-20'].gpuCpuMsPerFrame['floor-webgl'].median, 1.2);
  assert.equal(ratios['double-20'].gpuCpuMsPerFrame['floor-2d'].median, 3);
  assert.equal(ratios['double-20'].gpuCpuMsPerFrame['page-flip'].median, 0.8);

  // Only the double spread measured: every desktop target but the load then holds; no phone, so the
  // phone's targets are not measured.
  const double = summarizeRuns(runs.filter((r) => r.config === 'double-20'), [configs[0]], loadBytes).floorTargets;
  assert.deepEqual(double.map((t) => [t.id, t.holds]),
    [['floor-gpu', true], ['floor-frames', true], ['floor-main', true], ['turn-asked', true], ['load', false],
      ['phone-frames', null], ['phone-gpu', null], ['phone-turn-asked', null], ['phone-first-page', null]]);
});

test('node: bench report and published tables show every floor target with its limit, measured value and verdict', () => {
  const { configs, runs, loadBytes, meta } = floorFixture();
  const { summary, ratios, targets, floorTargets } = summarizeRuns(runs.filter((r) => r.config === 'double-20'), [configs[0]], loadBytes);
  const md = markdown({ meta, loadBytes, summary, ratios, targets, floorTargets, configs: [configs[0]] });
  const published = readmeTables({ meta, loadBytes, summary, targets, floorTargets, configs: [configs[0]] });
  const expected = {
    'floor-gpu': ['double-20: 1.20x (120.0 vs 100.0 ms)', 'holds'],
    'floor-frames': ['double-20: 0.90x (45 vs 50)', 'holds'],
    'floor-main': ['double-20: 0.90x (180 vs 200 ms)', 'holds'],
    'turn-asked': ['double-20: 1.03x', 'holds'],
    load: ['all: 40.00 KB (JS 25.0 KB + wasm 15.0 KB)', '**does not hold**'],
  };
  for (const target of FLOOR_TARGETS.filter((t) => t.screen === 'phone')) {
    expected[target.id] = ['no phone configuration in the run', 'not measured'];
  }
  for (const text of [md, published]) {
    for (const target of FLOOR_TARGETS) {
      const row = text.split('\n').find((line) => line.startsWith(`| ${target.figure} |`));
      assert.ok(row, `a row for ${target.id}`);
      const [measured, verdict] = expected[target.id];
      assert.equal(row, `| ${target.figure} | ${floorLimitText(target)} | ${measured} | ${verdict} |`);
    }
  }
  assert.match(published, /^\| double-20 \| floor-webgl \| /m, 'the published table has a row for each floor');
  assert.match(published, /^\| double-20 \| floor-2d \| /m);
  // The per-configuration table has a column per contender and conecurl's ratio to each.
  const header = md.split('\n').find((line) => line.startsWith('| metric |'));
  assert.equal(header, '| metric | conecurl | page-flip | turn.js | WebGL floor | 2D floor | conecurl / page-flip | conecurl / turn.js '
    + '| conecurl / WebGL floor | conecurl / 2D floor |');
  const gpuRow = md.split('\n').find((line) => line.startsWith('| GPU process CPU per frame'));
  assert.equal(gpuRow, '| GPU process CPU per frame (ms) | 120.0 | 150.0 | 160.0 | 100.0 | 40.0 | 0.80 | 0.75 | 1.20 | 3.00 |');
});

test('node: bench floor targets say "not measured" when the WebGL floor was not in the run', () => {
  const { configs, runs, loadBytes, meta } = floorFixture({ withFloor: false });
  const { summary, ratios, targets, floorTargets } = summarizeRuns(runs, configs, loadBytes);
  assert.deepEqual(floorTargets.map((t) => t.holds), [null, null, null, false, false, null, null, null, null]);
  const md = markdown({ meta, loadBytes, summary, ratios, targets, floorTargets, configs });
  const gpuRow = md.split('\n').find((line) => line.startsWith('| GPU-process CPU per turning frame |'));
  assert.match(gpuRow, /\| not measured \|$/);
});

// conecurl against a baseline checkout (`--baseline`), two repetitions of double-20, with the WebGL floor:
// repetition 1 is slow for both, repetition 2 fast, so after / before within a repetition differs from
// the ratio of the medians.
function baselineFixture() {
  const { meta } = floorFixture();
  const config = { id: 'double-20', display: 'double', pages: 20, label: 'Two-page spread, 1600x1100, 20 pages' };
  const figures = [
    { rep: 1, lib: 'conecurl', gpuMs: 120, frames: 40, mainMs: 5, turnMs: 660, frameMs: 15 },
    { rep: 1, lib: 'conecurl-baseline', gpuMs: 100, frames: 50, mainMs: 4, turnMs: 600, frameMs: 12 },
    { rep: 1, lib: 'floor-webgl', gpuMs: 90, frames: 55, mainMs: 3, turnMs: 600, frameMs: 11 },
    { rep: 2, lib: 'conecurl', gpuMs: 60, frames: 50, mainMs: 2, turnMs: 600, frameMs: 12 },
    { rep: 2, lib: 'conecurl-baseline', gpuMs: 60, frames: 40, mainMs: 2, turnMs: 630, frameMs: 15 },
    { rep: 2, lib: 'floor-webgl', gpuMs: 50, frames: 60, mainMs: 1, turnMs: 600, frameMs: 10 },
  ];
  const runs = figures.map(({ rep, lib, ...f }) => ({
    rep, config: 'double-20', lib, result: fakeResult({ askedTurnMs: 600, textures: lib.startsWith('conecurl') ? 10 : undefined, ...f }),
  }));
  const loadBytes = {
    conecurl: { js: 0, wasm: 0, totalGzip: 40 * 1024, jsGzip: 25 * 1024, wasmGzip: 15 * 1024, lazy: { files: [] } },
    'conecurl-baseline': { js: 0, wasm: 0, totalGzip: 50 * 1024, jsGzip: 30 * 1024, wasmGzip: 20 * 1024, lazy: { files: [] } },
  };
  return {
    configs: [config], runs, loadBytes,
    meta: { ...meta, reps: 2, commit: 'abc1234', baseline: { dir: '/tmp/before', commit: 'ed27d46', label: 'conecurl (before, ed27d46)' } },
  };
}

test('node: bench with a baseline gives before, after and after / before within a repetition for the issue 24 figures', () => {
  const { configs, runs, loadBytes } = baselineFixture();
  const { beforeAfter, ratios, summary } = summarizeRuns(runs, configs, loadBytes);
  assert.deepEqual(BEFORE_AFTER.map((f) => f.metric),
    ['gpuCpuMsPerFrame', 'frames', 'frameMedianMs', 'mainThreadMsTurns', 'turnOverAsked', 'totalGzip']);
  const rows = Object.fromEntries(beforeAfter.map((f) => [f.metric,
    f.values.map((v) => [v.config, ...[v.before, v.after, v.ratio].map((x) => Number(x.toFixed(4)))])]));
  assert.deepEqual(rows, {
    // Medians 90 vs 80; ratios 120/100 and 60/60 within the repetitions, median 1.1 (not 90/80 = 1.125).
    gpuCpuMsPerFrame: [['double-20', 80, 90, 1.1]],
    frames: [['double-20', 45, 45, 1.025]],  // 40/50 and 50/40
    frameMedianMs: [['double-20', 13.5, 13.5, 1.025]],  // 15/12 and 12/15
    mainThreadMsTurns: [['double-20', 140, 150, 1.125]],  // 5x40 / 4x50 = 1 and 2x50 / 2x40 = 1.25
    turnOverAsked: [['double-20', 1.025, 1.05, 1.0262]],  // 660/600 and 600/630
    totalGzip: [['all', 50, 40, 0.8]],
  });
  // Ratios to the baseline sit beside the others', for the conecurl-only figures too.
  assert.equal(ratios['double-20'].gpuCpuMsPerFrame['conecurl-baseline'].median, 1.1);
  assert.equal(ratios['double-20'].pageTextures['conecurl-baseline'].median, 1);
  assert.deepEqual(Object.keys(summary['double-20']), ['conecurl', 'page-flip', 'turnjs', 'floor-webgl', 'floor-2d', 'conecurl-baseline']);
});

test('node: bench report and published tables show a baseline\'s column, its ratios and the before-and-after table', () => {
  const { configs, runs, loadBytes, meta } = baselineFixture();
  const { summary, ratios, targets, floorTargets, beforeAfter } = summarizeRuns(runs, configs, loadBytes);
  const md = markdown({ meta, loadBytes, summary, ratios, targets, floorTargets, beforeAfter, configs });
  const published = readmeTables({ meta, loadBytes, summary, targets, floorTargets, beforeAfter, configs });
  const table = [
    '| figure | configuration | before (ed27d46) | after (abc1234) | after / before |',
    '|---|---|---|---|---|',
    '| GPU-process CPU per frame | double-20 | 80.0 ms | 90.0 ms | 1.10x |',
    '| frames during the turns | double-20 | 45 | 45 | 1.02x |',
    '| frame interval, median | double-20 | 13.5 ms | 13.5 ms | 1.02x |',
    '| main-thread busy over the turns | double-20 | 140 ms | 150 ms | 1.13x |',
    '| turn duration / asked duration | double-20 | 1.025 | 1.050 | 1.03x |',
    '| load up front, JS + wasm, gzip -9 | all | 50.0 KB | 40.0 KB | 0.80x |',
  ].join('\n');
  assert.ok(md.includes(`## Before and after\n\nconecurl in this tree (after) against conecurl (before, ed27d46) from /tmp/before`));
  assert.ok(md.includes(table), md);
  assert.ok(published.includes(table), published);
  const lines = md.split('\n');
  assert.equal(lines.find((line) => line.startsWith('| metric |')),
    '| metric | conecurl | page-flip | turn.js | WebGL floor | 2D floor | before (ed27d46) | conecurl / page-flip | conecurl / turn.js '
    + '| conecurl / WebGL floor | conecurl / 2D floor | conecurl / before |');
  assert.equal(lines.find((line) => line.startsWith('| GPU process CPU per frame')),
    '| GPU process CPU per frame (ms) | 90.0 (60.0–120.0) | – | – | 70.0 (50.0–90.0) | – | 80.0 (60.0–100.0) | – | – '
    + '| 1.27 (1.20–1.33) | – | 1.10 (1.00–1.20) |');
  assert.ok(lines.includes('| conecurl (before, ed27d46) | 0.0 KB | 30.0 KB | – | – | **50.0 KB** | – |'), 'a load-bytes row for the baseline');
  assert.match(published, /^\| double-20 \| conecurl before \(ed27d46\) \| /m);
  assert.match(published, /conecurl before \(ed27d46\) 50\.0 KB/);
});

test('node: bench without a baseline has no before-and-after table and no baseline column', () => {
  const { configs, runs, loadBytes, meta } = floorFixture();
  const result = summarizeRuns(runs, configs, loadBytes);
  assert.equal(result.beforeAfter, null);
  assert.deepEqual(Object.keys(result.summary['double-20']), ['conecurl', 'page-flip', 'turnjs', 'floor-webgl', 'floor-2d']);
  const md = markdown({ meta, loadBytes, ...result, configs });
  assert.doesNotMatch(md, /Before and after|before \(/);
  assert.doesNotMatch(readmeTables({ meta, loadBytes, ...result, configs }), /Before and after|before \(/);
});

// A run with the desktop single page and the phone (390x844 at ratio 3), one repetition: on the phone conecurl
// keeps 0.9x the floor's frames and shows its first page in 1.05x the floor's time (hold), but costs 2x its
// GPU time a frame and turns in 1.1x the asked duration (do not).
function phoneFixture() {
  const { meta } = floorFixture();
  const configs = [
    { id: 'single-20', screen: 'desktop', display: 'single', pages: 20, label: 'Single page, 800x1100, 20 pages' },
    { id: 'phone-20', screen: 'phone', display: 'single', pages: 20, label: 'Phone, single page, 390x844 at ratio 3, 20 pages' },
  ];
  const canvas = (width, height, ratio) => ({ width: width * ratio, height: height * ratio, cssWidth: width, cssHeight: height });
  const figures = {
    'single-20': {
      conecurl: { gpuMs: 60, frames: 30, mainMs: 6, turnMs: 690, first: 600, drawing: { devicePixelRatio: 1, canvases: [canvas(800, 1100, 1)] } },
      'floor-webgl': { gpuMs: 40, frames: 60, mainMs: 2, turnMs: 610, first: 500, drawing: { devicePixelRatio: 1, canvases: [canvas(800, 1100, 1)] } },
      'page-flip': { gpuMs: 60, frames: 50, mainMs: 2, turnMs: 480, first: 400, drawing: { devicePixelRatio: 1, canvases: [canvas(800, 1100, 1)] } },
      turnjs: { gpuMs: 70, frames: 45, mainMs: 4, turnMs: 620, first: 400, drawing: { devicePixelRatio: 1, canvases: [] } },
    },
    'phone-20': {
      conecurl: { gpuMs: 80, frames: 45, mainMs: 3, turnMs: 660, first: 630, drawing: { devicePixelRatio: 3, canvases: [canvas(390, 844, 3)] } },
      'floor-webgl': { gpuMs: 40, frames: 50, mainMs: 2, turnMs: 610, first: 600, drawing: { devicePixelRatio: 3, canvases: [canvas(390, 844, 3)] } },
      'page-flip': { gpuMs: 30, frames: 60, mainMs: 2, turnMs: 480, first: 300, drawing: { devicePixelRatio: 3, canvases: [canvas(390, 844, 1)] } },
      turnjs: { gpuMs: 70, frames: 45, mainMs: 4, turnMs: 620, first: 100, drawing: { devicePixelRatio: 3, canvases: [] } },
    },
  };
  const runs = Object.entries(figures).flatMap(([config, libs]) => Object.entries(libs).map(([lib, f]) => ({
    rep: 1, config, lib, result: fakeResult({ frameMs: 600 / f.frames, askedTurnMs: 600, ...f }),
  })));
  const loadBytes = { conecurl: { js: 0, wasm: 0, totalGzip: 40 * 1024, jsGzip: 25 * 1024, wasmGzip: 15 * 1024 } };
  return { configs, runs, loadBytes, meta };
}

test('node: bench judges the phone configuration by its four targets and the desktop ones by theirs, never mixed', () => {
  const { configs, runs, loadBytes } = phoneFixture();
  const { floorTargets, targets } = summarizeRuns(runs, configs, loadBytes);
  const byId = Object.fromEntries(floorTargets.map((t) => [t.id, t]));
  const values = (id) => byId[id].values.map((v) => [v.config, Number(v.value.toFixed(4))]);
  // Desktop targets see only single-20; the phone's only phone-20.
  assert.deepEqual(values('floor-gpu'), [['single-20', 1.5]]);
  assert.deepEqual(values('turn-asked'), [['single-20', 1.15]]);
  assert.deepEqual(values('phone-frames'), [['phone-20', 0.9]]);
  assert.deepEqual(values('phone-gpu'), [['phone-20', 2]]);
  assert.deepEqual(values('phone-turn-asked'), [['phone-20', 1.1]]);
  assert.deepEqual(values('phone-first-page'), [['phone-20', 1.05]]);
  assert.deepEqual(floorTargets.filter((t) => t.screen === 'phone').map((t) => [t.id, t.holds]),
    [['phone-frames', true], ['phone-gpu', false], ['phone-turn-asked', false], ['phone-first-page', true]]);
  assert.equal(byId['phone-first-page'].values[0].detail, '630 vs 600 ms');
  // The targets against the peers stay the desktop's: no phone-20 value in any of them.
  for (const target of targets) assert.ok(target.values.every((v) => !String(v.config).includes('phone')), target.id);
  // A run of the phone alone has nothing for the peer targets to judge but the load: "not measured", not a vacuous yes.
  const alone = summarizeRuns(runs.filter((r) => r.config === 'phone-20'), [configs[1]], loadBytes);
  assert.deepEqual(alone.targets.map((t) => [t.id, t.holds]), [['main-thread', null], ['gpu', null], ['turn', null], ['memory', null],
    ['ready', null], ['idle', null], ['smooth', null], ['bytes', false]]);
  assert.match(markdown({ meta: phoneFixture().meta, loadBytes, ...alone, configs: [configs[1]] }),
    /^\| idle CPU of conecurl, renderer \+ GPU process \| <= 2% of a core \| no desktop configuration in the run \| not measured \|$/m);
});

test('node: bench report and published tables have a phone row, its targets\' verdicts with where the misses are explained, and the drawing buffers', () => {
  const { configs, runs, loadBytes, meta } = phoneFixture();
  const result = summarizeRuns(runs, configs, loadBytes);
  const md = markdown({ meta, loadBytes, ...result, configs });
  const published = readmeTables({ meta, loadBytes, ...result, configs });
  const why = ' (why: "On a phone" in docs/benchmark.md)';
  const rows = {
    'phone-frames': `phone-20: 0.90x (45 vs 50) | holds |`,
    'phone-gpu': `phone-20: 2.00x (80.0 vs 40.0 ms) | **does not hold**${why} |`,
    'phone-turn-asked': `phone-20: 1.10x | **does not hold**${why} |`,
    'phone-first-page': `phone-20: 1.05x (630 vs 600 ms) | holds |`,
  };
  for (const text of [md, published]) {
    for (const target of FLOOR_TARGETS.filter((t) => t.screen === 'phone')) {
      assert.ok(text.split('\n').includes(`| ${target.figure} | ${floorLimitText(target)} | ${rows[target.id]}`), `${target.id} in\n${text}`);
    }
  }
  // The phone's row sits beside the desktop's in the published table, a row per contender.
  assert.match(published, /^\| single-20 \| conecurl \| 600 \| /m);
  assert.match(published, /^\| phone-20 \| conecurl \| 630 \| /m);
  assert.match(published, /^\| phone-20 \| floor-webgl \| 600 \| /m);
  // Drawing buffers: published for the phone (ratio 3), not for the desktop (ratio 1); in the full report for both.
  const phoneDrawing = 'Drawing buffers in phone-20 (device pixel ratio 3): conecurl 1170x2532 px for 390x844 CSS px (ratio 3.00); '
    + 'page-flip 390x844 px for 390x844 CSS px (ratio 1.00, below the device\'s 3); turn.js no canvas (DOM, composited by the browser); '
    + 'WebGL floor 1170x2532 px for 390x844 CSS px (ratio 3.00).';
  assert.ok(published.includes(phoneDrawing), published);
  assert.doesNotMatch(published, /Drawing buffers in single-20/);
  assert.ok(md.includes(phoneDrawing));
  assert.match(md, /^Drawing buffers in single-20 \(device pixel ratio 1\): conecurl 800x1100 px/m);
  assert.ok(md.includes('## Phone, single page, 390x844 at ratio 3, 20 pages'));
  assert.equal(drawingText(null), '–');
});

// Chromium's runs of two configurations and Firefox's of the first (two repetitions, the machine slower in
// the second), WebKit not installed: what run.mjs's measureEngines returns beside the Chromium runs.
function engineFixture() {
  const configs = [
    { id: 'double-20', display: 'double', pages: 20, label: 'Two-page spread, 1600x1100, 20 pages' },
    { id: 'single-20', display: 'single', pages: 20, label: 'Single page, 800x1100, 20 pages' },
  ];
  const result = (frames, first, turnMs, renderer) => fakeResult({ frameMs: 600 / frames, frames, first, turnMs, askedTurnMs: 600, mainMs: 1, gpuMs: 1, renderer });
  const runs = [
    { rep: 1, config: 'double-20', lib: 'conecurl', result: result(40, 900, 630, 'SwiftShader') },
    { rep: 1, config: 'double-20', lib: 'floor-webgl', result: result(50, 600, 610, 'SwiftShader') },
    { rep: 1, config: 'double-20', lib: 'page-flip', result: result(10, 100, 900) },
    { rep: 1, config: 'single-20', lib: 'conecurl', result: result(5, 5000, 5000) },
    { rep: 1, config: 'single-20', lib: 'floor-webgl', result: result(60, 100, 600) },
  ];
  const firefox = (rep, lib, frames, first, turnMs) => ({ engine: 'firefox', rep, config: 'double-20', lib, result: result(frames, first, turnMs, 'llvmpipe, or similar') });
  const engines = {
    config: 'double-20',
    info: { firefox: { version: 'firefox/153.0' }, webkit: { missing: 'no WebKitGTK MiniBrowser: run `bash scripts/setup.sh`' } },
    runs: [
      firefox(1, 'conecurl', 30, 1500, 660), firefox(1, 'floor-webgl', 60, 500, 600),
      firefox(2, 'floor-webgl', 20, 1000, 900), firefox(2, 'conecurl', 15, 2000, 990),
      { engine: 'firefox', rep: 3, config: 'double-20', lib: 'conecurl', error: 'conecurl: turn 1 did not land within 30000 ms' },
    ],
  };
  const meta = {
    date: '2026-11-25T17:00:00Z', chromium: 'Chromium 0', cpus: 2, reps: 2, turns: 1, turnDurationMs: 600, idleMs: 2000,
    wallSeconds: 60, loadavgStart: [1, 1, 1], loadavgEnd: [1, 1, 1],
  };
  return { configs, runs, engines, meta, loadBytes: {} };
}

test('node: bench engine rows take conecurl / the floor within a repetition of the same engine, Chromium\'s from its runs of the same configuration', () => {
  const { configs, runs, engines, meta } = engineFixture();
  const rows = summarizeEngines(runs, engines, configs, meta);
  assert.deepEqual(rows.map((r) => r.engine), ['chromium', 'firefox', 'webkit']);
  const [chromium, firefox, webkit] = rows;
  assert.deepEqual(Object.keys(firefox.figures), ENGINE_METRICS);
  // Chromium: double-20 only (single-20's conecurl would be 5 frames), and neither peer nor 2D floor.
  assert.deepEqual(chromium.figures.frames.conecurl.median, 40);
  assert.equal(chromium.figures.frames.ratio.median, 0.8);
  assert.equal(chromium.figures.firstFrameMs.ratio.median, 1.5);
  assert.equal(chromium.renderer, 'SwiftShader');
  assert.equal(chromium.browser, 'Chromium 0');
  // Firefox: 30/60 and 15/20 frames, so 0.5 and 0.75 within the repetitions; the median of the ratios
  // (0.625), not the ratio of the medians (22.5 / 40).
  assert.equal(firefox.figures.frames.ratio.median, 0.625);
  assert.deepEqual([firefox.figures.frames.conecurl.median, firefox.figures.frames.floor.median], [22.5, 40]);
  assert.equal(firefox.figures.firstFrameMs.ratio.median, (3 + 2) / 2);
  assert.equal(firefox.figures.turnOverAsked.conecurl.median, (1.1 + 1.65) / 2);
  assert.equal(firefox.figures.frameMedianMs.ratio.median, (2 + 20 / 15) / 2);
  assert.equal(firefox.failed, 1, 'the third repetition\'s failed run is counted, not measured');
  assert.equal(firefox.browser, 'firefox/153.0');
  assert.deepEqual(webkit, { engine: 'webkit', note: 'not installed: no WebKitGTK MiniBrowser: run `bash scripts/setup.sh`' });
  // An engine that did not start says so too; a run with no engine measured has Chromium's row alone.
  const failed = summarizeEngines(runs, { ...engines, info: { firefox: { failed: 'Xvfb exited (1)' } } }, configs, meta);
  assert.deepEqual(failed[1], { engine: 'firefox', note: 'did not start: Xvfb exited (1)' });
  assert.deepEqual(summarizeEngines(runs, { config: 'double-20', info: {}, runs: [] }, configs, meta).map((r) => r.engine), ['chromium']);
  assert.deepEqual(summarizeEngines(runs, { config: null, info: {}, runs: [] }, configs, meta), []);
});

test('node: bench report and published tables have a row per engine, conecurl vs the floor, and one line for an engine not installed', () => {
  const { configs, runs, engines, meta, loadBytes } = engineFixture();
  const engineRows = summarizeEngines(runs, engines, configs, meta);
  const result = summarizeRuns(runs, configs, loadBytes);
  const md = markdown({ meta, loadBytes, ...result, configs, engineRows });
  const published = readmeTables({ meta, loadBytes, ...result, configs, engineRows });
  for (const text of [md, published]) {
    const lines = text.split('\n');
    assert.ok(lines.includes('| engine | WebGL renderer | frames during the turns | frame interval, median (ms) | frame interval, p95 (ms) '
      + '| turn duration in the page / asked duration, mean over the turns | navigation to first rendered book (ms) |'), text);
    assert.ok(lines.includes('| Chromium (Chromium 0) | SwiftShader | 40 vs 50 (0.80x) | 15.0 vs 12.0 (1.25x) | 15.0 vs 12.0 (1.25x) '
      + '| 1.050 vs 1.017 (1.03x) | 900 vs 600 (1.50x) |'), text);
    assert.ok(lines.includes('| Firefox (firefox/153.0, 1 run failed) | llvmpipe, or similar | 23 (15–30) vs 40 (20–60) (0.63x) '
      + '| 30.0 (20.0–40.0) vs 20.0 (10.0–30.0) (1.67x) | 30.0 (20.0–40.0) vs 20.0 (10.0–30.0) (1.67x) '
      + '| 1.375 (1.100–1.650) vs 1.250 (1.000–1.500) (1.10x) | 1750 (1500–2000) vs 750 (500–1000) (2.50x) |'), text);
    assert.ok(lines.includes('| WebKit | not installed: no WebKitGTK MiniBrowser: run `bash scripts/setup.sh` | – | – | – | – | – |'), text);
    assert.match(text, /in double-20 \(Two-page spread, 1600x1100, 20 pages\)/);
    assert.match(text, /llvmpipe, Mesa's software rasteriser: what a reader without a GPU/);
  }
  assert.match(md, /^## Three engines$/m);
  // Without engine rows (a report from before them), no such section.
  assert.doesNotMatch(markdown({ meta, loadBytes, ...result, configs }), /Three engines|WebGL renderer/);
});
