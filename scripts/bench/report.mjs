// Turns the raw runs of `npm run bench` into the summary (medians with ranges, ratios of conecurl to every
// other contender from the same repetition, the targets against the floor and the peers, before and after
// when a baseline checkout was measured too, the drawing buffers, conecurl against the WebGL floor in each engine),
// a Markdown table and an SVG chart of frame intervals.
import { firstTurnAgainstLater, summarize } from './metrics.mjs';

export const LIBRARY_NAMES = {
  conecurl: 'conecurl', 'page-flip': 'page-flip 2.0.7', turnjs: 'turn.js 1.0.5 + jQuery 1.12.0',
  'floor-webgl': 'WebGL floor (scripts/bench/libraries/floor-webgl.js)', 'floor-2d': '2D-canvas floor (scripts/bench/libraries/floor-2d.js)',
};
// Column heads of the per-configuration tables.
const SHORT_NAMES = { conecurl: 'conecurl', 'page-flip': 'page-flip', turnjs: 'turn.js', 'floor-webgl': 'WebGL floor', 'floor-2d': '2D floor' };
const PEERS = ['page-flip', 'turnjs'];
// The baseline contender (`--baseline <dir>`): conecurl as another checkout has it, an older commit. It is
// a contender only in runs that measured it; its names carry its commit (meta.baseline).
export const BASELINE = 'conecurl-baseline';
const baselineCommit = (meta) => meta?.baseline?.commit ?? '?';
const longName = (lib, meta) => LIBRARY_NAMES[lib] ?? meta?.baseline?.label ?? `conecurl (before, ${baselineCommit(meta)})`;
const shortName = (lib, meta) => SHORT_NAMES[lib] ?? `before (${baselineCommit(meta)})`;
const ratioHead = (lib) => (lib === BASELINE ? 'conecurl / before' : `conecurl / ${SHORT_NAMES[lib]}`);
const MB = 1024 * 1024;

const maxTextures = (r) => Math.max(...(r.turnStats || []).map((s) => s.pageTextures ?? NaN), r.stats.pageTextures ?? NaN);

// Scalar figures per run, lower is better for all of them. [key, label, unit, decimals, from result]
export const METRICS = [
  ['firstFrameMs', 'navigation to first rendered book', 'ms', 0, (r) => r.firstFrameMs],
  ['turnSeconds', 'wall time per turn (animation set to the same duration)', 's', 2, (r) => r.turnSeconds / r.turns.length],
  ['frameMedianMs', 'frame interval, median', 'ms', 1, (r) => summarize(r.intervals).median],
  ['frameP95Ms', 'frame interval, p95', 'ms', 1, (r) => summarize(r.intervals).p95],
  ['frameMaxMs', 'frame interval, max', 'ms', 1, (r) => summarize(r.intervals).max],
  ['maxOverMedian', 'max / median frame interval', 'x', 2, (r) => summarize(r.intervals).max / summarize(r.intervals).median],
  ['framesOver20', 'frames over 20 ms', '', 0, (r) => r.intervals.filter((i) => i > 20).length],
  ['firstTurnMaxMs', 'frame interval, max, of the first turn after load', 'ms', 1, (r) => firstTurnAgainstLater(r).first.max],
  ['laterTurnsMaxMs', 'frame interval, max, of the later turns', 'ms', 1, (r) => firstTurnAgainstLater(r).later.max],
  ['frames', 'frames during the turns', '', 0, (r) => r.frames],
  ['turnOverAsked', 'turn duration in the page / asked duration, mean over the turns', 'x', 3,
    (r) => r.turns.reduce((sum, t) => sum + t.end - t.start, 0) / r.turns.length / r.askedTurnMs],
  ['mainThreadMsPerFrame', 'main-thread busy per frame (TaskDuration, wall time of tasks)', 'ms', 2, (r) => r.perFrame.mainThreadMs],
  ['mainThreadMsTurns', 'main-thread busy over the turns (TaskDuration)', 'ms', 0, (r) => r.perFrame.mainThreadMs * r.frames],
  ['rendererCpuMsPerFrame', 'renderer process CPU per frame', 'ms', 2, (r) => r.perFrame.rendererCpuMs],
  ['gpuCpuMsPerFrame', 'GPU process CPU per frame', 'ms', 1, (r) => r.perFrame.gpuCpuMs],
  ['idleCpuPercent', 'idle CPU, renderer + GPU (% of a core)', '', 1, (r) => r.idle.totalCpuPercent],
  ['idleMainThreadPercent', 'idle main-thread busy (% of the time)', '', 2, (r) => r.idle.mainThreadPercent],
  ['jsHeapMB', 'JS heap after GC', 'MB', 2, (r) => r.memory.jsHeapBytes / MB],
  ['rendererPssMB', 'renderer process memory (PSS)', 'MB', 0, (r) => (r.memory.rendererPssBytes ?? NaN) / MB],
  ['gpuPssMB', 'GPU process memory (PSS)', 'MB', 0, (r) => (r.memory.gpuPssBytes ?? NaN) / MB],
  ['wasmHeapMB', 'wasm heap (conecurl)', 'MB', 1, (r) => (r.stats.wasmHeapBytes ?? NaN) / MB],
  ['pageTextures', 'page textures resident after the turns (conecurl)', '', 0, (r) => r.stats.pageTextures ?? NaN],
  ['pageTexturesMax', 'page textures resident, most after any turn (conecurl)', '', 0, (r) => maxTextures(r)],
];
// Ratios conecurl / other contender are shown for these (the others are conecurl-only or ratios already).
const RATIO_METRICS = ['firstFrameMs', 'turnSeconds', 'frameMedianMs', 'frameP95Ms', 'frameMaxMs', 'frames', 'mainThreadMsPerFrame',
  'mainThreadMsTurns', 'rendererCpuMsPerFrame', 'gpuCpuMsPerFrame', 'idleCpuPercent', 'jsHeapMB', 'rendererPssMB', 'gpuPssMB'];
// After / before is shown for every figure both have (the conecurl-only ones included), against the baseline.
const BASELINE_RATIO_METRICS = METRICS.map(([key]) => key).filter((key) => key !== 'maxOverMedian');

/**
 * The figures of issue 24 shown before and after (conecurl now / the baseline checkout): per
 * configuration, or `metric: 'totalGzip'` for the load up front (KB, gzip -9, all configurations).
 */
export const BEFORE_AFTER = [
  { metric: 'gpuCpuMsPerFrame', figure: 'GPU-process CPU per frame', unit: 'ms', decimals: 1 },
  { metric: 'frames', figure: 'frames during the turns', unit: '', decimals: 0 },
  { metric: 'frameMedianMs', figure: 'frame interval, median', unit: 'ms', decimals: 1 },
  { metric: 'mainThreadMsTurns', figure: 'main-thread busy over the turns', unit: 'ms', decimals: 0 },
  { metric: 'turnOverAsked', figure: 'turn duration / asked duration', unit: 'x', decimals: 3 },
  { metric: 'totalGzip', figure: 'load up front, JS + wasm, gzip -9', unit: 'KB', decimals: 1 },
];

/**
 * The targets against the floor: the one place they are written. Each compares a figure of conecurl,
 * per configuration of its `screen` (median over the repetitions), with `against`: a contender (the
 * ratio conecurl / it within each repetition), 'asked' (the figure is already over the asked duration),
 * or 'KB' (load bytes up front, gzip -9, all configurations; no screen). `most`: the figure must be at
 * most `limit`; `least`: at least. `screen` 'desktop': issue 24's targets, for the desktop configurations;
 * 'phone': issue 29's, for the phone configuration (390x844 at ratio 3, the floor drawing at the same
 * ratio), whose misses point to `why`, the section of docs/benchmark.md that says why.
 */
export const FLOOR_TARGETS = [
  { id: 'floor-gpu', screen: 'desktop', figure: 'GPU-process CPU per turning frame', metric: 'gpuCpuMsPerFrame', unit: 'ms', against: 'floor-webgl', bound: 'most', limit: 1.3 },
  { id: 'floor-frames', screen: 'desktop', figure: 'frames drawn during the turns', metric: 'frames', unit: '', against: 'floor-webgl', bound: 'least', limit: 0.8 },
  { id: 'floor-main', screen: 'desktop', figure: 'main-thread busy time over the turns', metric: 'mainThreadMsTurns', unit: 'ms', against: 'floor-webgl', bound: 'most', limit: 1.1 },
  { id: 'turn-asked', screen: 'desktop', figure: 'turn duration (in the page, mean over the turns)', metric: 'turnOverAsked', unit: '', against: 'asked', bound: 'most', limit: 1.05 },
  { id: 'load', figure: 'load up front for a book of images, JS + wasm, gzip -9', metric: 'totalGzip', unit: 'KB', against: 'KB', bound: 'most', limit: 30 },
  { id: 'phone-frames', screen: 'phone', figure: 'phone: frames drawn during the turns', metric: 'frames', unit: '', against: 'floor-webgl', bound: 'least', limit: 0.8, why: 'On a phone' },
  { id: 'phone-gpu', screen: 'phone', figure: 'phone: GPU-process CPU per turning frame', metric: 'gpuCpuMsPerFrame', unit: 'ms', against: 'floor-webgl', bound: 'most', limit: 1.5, why: 'On a phone' },
  { id: 'phone-turn-asked', screen: 'phone', figure: 'phone: turn duration (in the page, mean over the turns)', metric: 'turnOverAsked', unit: '', against: 'asked', bound: 'most', limit: 1.05, why: 'On a phone' },
  { id: 'phone-first-page', screen: 'phone', figure: 'phone: first page shown (navigation to first rendered book)', metric: 'firstFrameMs', unit: 'ms', against: 'floor-webgl', bound: 'most', limit: 1.1, why: 'On a phone' },
];

// The engine rows: conecurl against the WebGL floor drawn in the same engine, these figures of METRICS.
export const ENGINE_LIBS = ['conecurl', 'floor-webgl'];
export const ENGINE_METRICS = ['frames', 'frameMedianMs', 'frameP95Ms', 'turnOverAsked', 'firstFrameMs'];
const ENGINE_NAMES = { chromium: 'Chromium', firefox: 'Firefox', webkit: 'WebKit' };

/** The screen a configuration is judged as: 'desktop' unless it says otherwise. */
export const screenOf = (config) => config.screen ?? 'desktop';

/** How a floor target's limit reads: "<= 1.3x the WebGL floor", ">= 0.8x ...", "<= 30 KB". */
export function floorLimitText({ against, bound, limit }) {
  const sign = bound === 'most' ? '<=' : '>=';
  if (against === 'KB') return `${sign} ${limit} KB`;
  if (against === 'asked') return `${sign} ${limit}x the asked duration`;
  return `${sign} ${limit}x the ${SHORT_NAMES[against]}'s`;
}

/**
 * FLOOR_TARGETS measured: [{ id, screen, name, limit, values: [{ config, value, detail }], holds, why }] where
 * `value` is the ratio (or KB), `detail` the figures it comes from, and `holds` true, false, or null
 * when nothing was measured (no configuration of its screen, or the contender it compares with, in the run).
 */
function evaluateFloorTargets(allConfigs, summary, ratios, loadBytes) {
  return FLOOR_TARGETS.map((target) => {
    const { metric, against, unit } = target;
    const configs = target.screen ? allConfigs.filter((c) => screenOf(c) === target.screen) : allConfigs;
    const decimals = METRICS.find(([key]) => key === metric)?.[3] ?? 1;
    const figure = (lib, c) => fmt(summary[c.id][lib]?.[metric]?.median, decimals);
    let values;
    if (against === 'KB') {
      const bytes = loadBytes?.conecurl;
      values = [{ config: 'all', value: bytes ? bytes.totalGzip / 1024 : NaN,
        detail: bytes ? `JS ${(bytes.jsGzip / 1024).toFixed(1)} KB + wasm ${(bytes.wasmGzip / 1024).toFixed(1)} KB` : '' }];
    } else if (against === 'asked') {
      values = configs.map((c) => ({ config: c.id, value: summary[c.id].conecurl[metric]?.median ?? NaN, detail: '' }));
    } else {
      values = configs.map((c) => ({
        config: c.id,
        value: ratios[c.id][metric]?.[against]?.median ?? NaN,
        detail: `${figure('conecurl', c)} vs ${figure(against, c)}${unit ? ` ${unit}` : ''}`,
      }));
    }
    const measured = values.filter((v) => Number.isFinite(v.value));
    const within = (v) => (target.bound === 'most' ? v <= target.limit : v >= target.limit);
    const holds = measured.length === 0 ? null : measured.length === values.length && measured.every((v) => within(v.value));
    return { id: target.id, screen: target.screen ?? 'all', name: target.figure, limit: floorLimitText(target), values, holds,
      ...(target.why ? { why: target.why } : {}) };
  });
}

const range = (values) => {
  const finite = values.filter(Number.isFinite);
  if (finite.length === 0) return null;
  const s = summarize(finite);
  return { median: s.median, min: s.min, max: s.max, n: finite.length };
};

/** Medians and ranges per configuration and library, ratios from the same repetition, targets. */
export function summarizeRuns(runs, configs, loadBytes) {
  const summary = {};
  const ratios = {};
  const withBaseline = runs.some((r) => r.lib === BASELINE);
  const contenders = [...Object.keys(LIBRARY_NAMES), ...(withBaseline ? [BASELINE] : [])];
  const others = contenders.filter((lib) => lib !== 'conecurl');
  for (const config of configs) {
    summary[config.id] = {};
    ratios[config.id] = {};
    const ok = runs.filter((r) => r.config === config.id && r.result);
    for (const lib of contenders) {
      const mine = ok.filter((r) => r.lib === lib);
      summary[config.id][lib] = Object.fromEntries(METRICS.map(([key, , , , get]) => [key, range(mine.map((r) => get(r.result)))]));
      summary[config.id][lib].failed = runs.filter((r) => r.config === config.id && r.lib === lib && r.error).length;
      summary[config.id][lib].drawing = mine.find((r) => r.result.drawing)?.result.drawing ?? null;
    }
    const reps = [...new Set(ok.map((r) => r.rep))];
    const ratioMetrics = withBaseline ? BASELINE_RATIO_METRICS : RATIO_METRICS;
    for (const [key, , , , get] of METRICS.filter(([key]) => ratioMetrics.includes(key))) {
      // The baseline is the only contender for the conecurl-only figures.
      const against = RATIO_METRICS.includes(key) ? others : [BASELINE];
      const perPeer = RATIO_METRICS.includes(key) ? { bestPeer: [] } : {};
      for (const other of against) perPeer[other] = [];
      for (const rep of reps) {
        const value = (lib) => { const run = ok.find((r) => r.rep === rep && r.lib === lib); return run ? get(run.result) : NaN; };
        const mine = value('conecurl');
        for (const other of against) perPeer[other].push(mine / value(other));
        if (!perPeer.bestPeer) continue;
        const peerValues = PEERS.map(value);
        const finitePeers = peerValues.filter(Number.isFinite);
        perPeer.bestPeer.push(finitePeers.length ? mine / Math.min(...finitePeers) : NaN);
      }
      ratios[config.id][key] = Object.fromEntries(Object.entries(perPeer).map(([k, v]) => [k, range(v)]));
    }
  }
  return {
    summary, ratios, targets: evaluateTargets(runs, configs, summary, ratios, loadBytes),
    floorTargets: evaluateFloorTargets(configs, summary, ratios, loadBytes),
    beforeAfter: withBaseline ? evaluateBeforeAfter(configs, summary, ratios, loadBytes) : null,
  };
}

/**
 * One engine's figures from its runs in one configuration: per figure of ENGINE_METRICS, conecurl's and the
 * floor's medians over the repetitions (with ranges), and conecurl / floor within a repetition.
 */
export function engineFigures(runs) {
  const ok = runs.filter((r) => r.result);
  const reps = [...new Set(ok.map((r) => r.rep))];
  return Object.fromEntries(ENGINE_METRICS.map((key) => {
    const get = METRICS.find(([k]) => k === key)[4];
    const value = (lib, rep) => { const run = ok.find((r) => r.lib === lib && r.rep === rep); return run ? get(run.result) : NaN; };
    const [mine, floor] = ENGINE_LIBS.map((lib) => range(ok.filter((r) => r.lib === lib).map((r) => get(r.result))));
    return [key, { conecurl: mine, floor, ratio: range(reps.map((rep) => value('conecurl', rep) / value('floor-webgl', rep))) }];
  }));
}

/**
 * The engine rows, all from one run, in the configuration the other engines were measured in
 * (`engines.config`, from run.mjs's measureEngines): Chromium's from its runs of that configuration, then
 * one per other engine. A row is { engine, browser, renderer, config, figures, failed } or, for an engine
 * not installed or not started, { engine, note }.
 */
export function summarizeEngines(runs, engines, configs, meta) {
  const config = configs.find((c) => c.id === engines?.config);
  if (!config) return [];
  const row = (engine, browser, mine) => ({
    engine, browser, config: config.id,
    renderer: mine.find((r) => r.result?.renderer)?.result.renderer ?? null,
    figures: engineFigures(mine),
    failed: mine.filter((r) => r.error).length,
  });
  const rows = [row('chromium', meta.chromium, runs.filter((r) => r.config === config.id && ENGINE_LIBS.includes(r.lib)))];
  for (const [engine, info] of Object.entries(engines.info)) {
    if (info.missing) rows.push({ engine, note: `not installed: ${info.missing}` });
    else if (info.failed) rows.push({ engine, note: `did not start: ${info.failed}` });
    else rows.push(row(engine, info.version, engines.runs.filter((r) => r.engine === engine)));
  }
  return rows;
}

/**
 * BEFORE_AFTER measured: [{ metric, figure, unit, decimals, values: [{ config, before, after, ratio }] }],
 * medians over the repetitions; `ratio` after / before, the median of the ratios within a repetition
 * (for the load: of the two sizes).
 */
function evaluateBeforeAfter(configs, summary, ratios, loadBytes) {
  return BEFORE_AFTER.map((figure) => {
    let values;
    if (figure.metric === 'totalGzip') {
      const before = (loadBytes?.[BASELINE]?.totalGzip ?? NaN) / 1024;
      const after = (loadBytes?.conecurl?.totalGzip ?? NaN) / 1024;
      values = [{ config: 'all', before, after, ratio: after / before }];
    } else {
      values = configs.map((c) => ({
        config: c.id,
        before: summary[c.id][BASELINE][figure.metric]?.median ?? NaN,
        after: summary[c.id].conecurl[figure.metric]?.median ?? NaN,
        ratio: ratios[c.id][figure.metric]?.[BASELINE]?.median ?? NaN,
      }));
    }
    return { ...figure, values };
  });
}

/** The before-and-after figures as a Markdown table: one row per figure and configuration. */
export function beforeAfterTable(beforeAfter, meta) {
  const after = meta?.commit ? ` (${meta.commit})` : '';
  const lines = [`| figure | configuration | before (${baselineCommit(meta)}) | after${after} | after / before |`, '|---|---|---|---|---|'];
  for (const f of beforeAfter) {
    const unit = f.unit && f.unit !== 'x' ? ` ${f.unit}` : '';
    for (const v of f.values) {
      lines.push(`| ${f.figure} | ${v.config} | ${fmt(v.before, f.decimals)}${unit} | ${fmt(v.after, f.decimals)}${unit} | ${fmt(v.ratio, 2)}x |`);
    }
  }
  return lines;
}

// The targets against the peers are issue 24's, for the desktop configurations; a phone is judged by its
// own targets against the floor (FLOOR_TARGETS).
function evaluateTargets(runs, allConfigs, summary, ratios, loadBytes) {
  const configs = allConfigs.filter((c) => screenOf(c) === 'desktop');
  const targets = [];
  const perConfig = (metric, pick) => configs.map((c) => ({ config: c.id, value: pick(c) }));
  // Nothing to judge (a run of the phone alone): null, "not measured", rather than a vacuous yes.
  const add = (id, name, limit, values, holds, note = '') => targets.push({ id, name, limit, values, holds: values.length ? holds : null, note });

  const ratioValues = (metric) => perConfig(metric, (c) => ratios[c.id][metric]?.bestPeer?.median ?? NaN);
  const mainRatios = ratioValues('mainThreadMsPerFrame');
  add('main-thread', 'main-thread time per turning frame, conecurl / best peer', '<= 0.5x', mainRatios,
    mainRatios.every((v) => v.value <= 0.5));
  const gpuRatios = ratioValues('gpuCpuMsPerFrame');
  add('gpu', 'GPU-process CPU per frame, conecurl / best peer', '<= 0.8x', gpuRatios, gpuRatios.every((v) => v.value <= 0.8));
  const turnRatios = ratioValues('turnSeconds');
  add('turn', 'wall time of one turn (the same duration asked of every library), conecurl / best peer', '<= 1.05x', turnRatios,
    turnRatios.every((v) => v.value <= 1.05));
  const memoryRatios = ratioValues('rendererPssMB');
  add('memory', 'renderer process memory (PSS), conecurl / best peer', '<= 1.0x', memoryRatios, memoryRatios.every((v) => v.value <= 1.0));
  const readyRatios = ratioValues('firstFrameMs');
  add('ready', 'navigation to first rendered book, conecurl / best peer', '<= 1.0x', readyRatios, readyRatios.every((v) => v.value <= 1.0));
  const idle = perConfig('idleCpuPercent', (c) => summary[c.id].conecurl.idleCpuPercent?.median ?? NaN);
  add('idle', 'idle CPU of conecurl, renderer + GPU process', '<= 2% of a core', idle, idle.every((v) => v.value <= 2));
  // Worst run, not the median: the target says no interval at all.
  const spikes = perConfig('maxOverMedian', (c) => summary[c.id].conecurl.maxOverMedian?.max ?? NaN);
  add('smooth', 'longest frame interval / median during the turns (worst run)', '<= 2x', spikes, spikes.every((v) => v.value <= 2));
  const bytes = loadBytes?.conecurl?.totalGzip ?? NaN;
  add('bytes', 'load bytes of conecurl, wasm + JS, gzip -9', '<= 30 KB', [{ config: 'all', value: bytes / 1024 }], bytes <= 30 * 1024,
    loadBytes?.conecurl ? `JS ${(loadBytes.conecurl.jsGzip / 1024).toFixed(1)} KB + wasm ${(loadBytes.conecurl.wasmGzip / 1024).toFixed(1)} KB` : '');

  for (const display of ['double', 'single']) {
    const small = configs.find((c) => c.display === display && c.pages === 20);
    const large = configs.find((c) => c.display === display && c.pages === 1000);
    if (!small || !large) continue;
    const pairs = [...new Set(runs.map((r) => r.rep))].map((rep) => {
      const find = (c) => runs.find((r) => r.rep === rep && r.config === c.id && r.lib === 'conecurl' && r.result)?.result;
      return [find(small), find(large)];
    }).filter(([a, b]) => a && b);
    const firstRatio = range(pairs.map(([a, b]) => b.firstFrameMs / a.firstFrameMs));
    add(`first-frame-${display}`, `first frame, 1000 pages / 20 pages (${display})`, '<= 1.5x',
      [{ config: `${large.id} / ${small.id}`, value: firstRatio?.median ?? NaN }], (firstRatio?.median ?? Infinity) <= 1.5);
    // The most resident after any turn: after the 10th turn the 20-page book is at its end, where
    // the load window is cut short, so the count there says nothing about page count.
    const textures = pairs.map(([a, b]) => [maxTextures(a), maxTextures(b)]);
    add(`textures-${display}`, `page textures resident (most after any turn), 20 vs 1000 pages (${display})`, 'equal',
      [{ config: `${small.id} vs ${large.id}`, value: textures.map(([a, b]) => `${a} vs ${b}`).join(', ') }],
      textures.length > 0 && textures.every(([a, b]) => a === b));
  }
  return targets;
}

const fmt = (value, decimals) => (Number.isFinite(value) ? value.toFixed(decimals) : '–');
const cell = (r, decimals) => (r ? (r.n > 1 && r.min !== r.max ? `${fmt(r.median, decimals)} (${fmt(r.min, decimals)}–${fmt(r.max, decimals)})` : fmt(r.median, decimals)) : '–');
const verdict = (holds) => (holds === null ? 'not measured' : holds ? 'holds' : '**does not hold**');
const peerMeasured = (t) => (t.values.length === 0 ? 'no desktop configuration in the run'
  : t.values.map((v) => `${v.config}: ${typeof v.value === 'number' ? fmt(v.value, 2) : v.value}`).join('; '));
const peerVerdict = (holds) => (holds === null ? 'not measured' : holds ? 'yes' : '**no**');
// A target that says where its misses are explained points there when it does not hold.
const floorVerdict = (t) => `${verdict(t.holds)}${t.holds === false && t.why ? ` (why: "${t.why}" in docs/benchmark.md)` : ''}`;

/** The floor targets as a Markdown table: each with the measured value and whether it holds. */
export function floorTargetTable(floorTargets) {
  const lines = ['| target | limit | measured (conecurl vs the floor) | verdict |', '|---|---|---|---|'];
  for (const t of floorTargets) {
    const unit = t.id === 'load' ? ' KB' : 'x';
    const measured = t.values.length
      ? t.values.map((v) => `${v.config}: ${fmt(v.value, 2)}${unit}${v.detail ? ` (${v.detail})` : ''}`).join('; ')
      : `no ${t.screen} configuration in the run`;
    lines.push(`| ${t.name} | ${t.limit} | ${measured} | ${floorVerdict(t)} |`);
  }
  return lines;
}

/**
 * What one contender drew into: each canvas's drawing buffer with its ratio to the CSS size, "below the
 * device ratio" where it is, or that the book has no canvas (a DOM book the browser composites).
 */
export function drawingText(drawing) {
  if (!drawing) return '–';
  if (drawing.canvases.length === 0) return 'no canvas (DOM, composited by the browser)';
  const moving = drawing.movingRatio < drawing.devicePixelRatio - 0.01
    ? `, frames with a moving leaf drawn at ${fmt(drawing.movingRatio, 2)} px per CSS px after the turns (resolution 'auto')` : '';
  return drawing.canvases.map((c) => {
    const ratio = c.cssWidth > 0 ? c.width / c.cssWidth : NaN;
    const below = ratio < drawing.devicePixelRatio - 0.01 ? `, below the device's ${drawing.devicePixelRatio}` : '';
    return `${c.width}x${c.height} px for ${c.cssWidth}x${c.cssHeight} CSS px (ratio ${fmt(ratio, 2)}${below}${moving})`;
  }).join(' + ');
}

/** A configuration's drawing buffers as one line, per contender measured. */
function drawingLine(config, summary, meta) {
  const libs = Object.entries(summary[config.id]).filter(([, s]) => s.drawing);
  if (libs.length === 0) return null;
  const ratio = libs[0][1].drawing.devicePixelRatio;
  return `Drawing buffers in ${config.id} (device pixel ratio ${ratio}): `
    + `${libs.map(([lib, s]) => `${shortName(lib, meta)} ${drawingText(s.drawing)}`).join('; ')}.`;
}

/** What the engine rows are, in words: which configuration, how each engine was driven, what draws Firefox's WebGL. */
function engineText(engineRows, configs) {
  const config = configs.find((c) => c.id === engineRows[0].config);
  return `conecurl against the WebGL floor drawn in the same engine, in ${config ? `${config.id} (${config.label})` : 'one configuration'}: `
    + 'the same harness page, book and turns in each, the figures read by the same code in the page (requestAnimationFrame '
    + 'timestamps for the frames, the turn from its start to its landing, navigation start to the book\'s first drawn frame). '
    + 'Chromium\'s row is from the runs above (a fresh headless browser per measurement). Firefox and WebKit run through '
    + 'scripts/engines.mjs on an Xvfb display, one browser per engine for all its measurements, after one visit that is not measured, '
    + 'order alternated per repetition. Firefox\'s WebGL2 draws on llvmpipe, Mesa\'s software rasteriser: what a reader without '
    + 'a GPU (or whose GPU the browser will not use) really meets. Cells: conecurl vs the floor, medians over the repetitions '
    + '(range), then conecurl / floor within a repetition, median. CPU and memory are Chromium\'s figures (CDP) and are not read in the others.';
}

/** The engine rows as a Markdown table: per figure "conecurl vs floor (conecurl / floor)"; an engine not measured says why. */
export function engineTable(engineRows) {
  const heads = ENGINE_METRICS.map((key) => { const [, label, unit] = METRICS.find(([k]) => k === key); return unit && unit !== 'x' ? `${label} (${unit})` : label; });
  const lines = [`| engine | WebGL renderer | ${heads.join(' | ')} |`, `|---|---|${heads.map(() => '---').join('|')}|`];
  for (const row of engineRows) {
    const name = ENGINE_NAMES[row.engine] ?? row.engine;
    if (row.note) {
      lines.push(`| ${name} | ${row.note} | ${heads.map(() => '–').join(' | ')} |`);
      continue;
    }
    const cells = ENGINE_METRICS.map((key) => {
      const decimals = METRICS.find(([k]) => k === key)[3];
      const f = row.figures[key];
      return `${cell(f.conecurl, decimals)} vs ${cell(f.floor, decimals)} (${fmt(f.ratio?.median, 2)}x)`;
    });
    const failed = row.failed ? `, ${row.failed} run${row.failed > 1 ? 's' : ''} failed` : '';
    lines.push(`| ${name} (${row.browser}${failed}) | ${row.renderer ?? '–'} | ${cells.join(' | ')} |`);
  }
  return lines;
}

/** The Markdown report: setting, targets (against the floor, then the peers), then one table per configuration. */
export function markdown({ meta, loadBytes, summary, ratios, targets, floorTargets = [], beforeAfter = null, configs, engineRows = [] }) {
  const lines = [];
  lines.push(`# conecurl benchmark`);
  lines.push('');
  lines.push(`${meta.date} · ${meta.chromium} (SwiftShader WebGL2, headless) · ${meta.cpus} CPUs · ${meta.reps} repetitions in fresh browsers, order alternated · `
    + `${meta.turns} turns of ${meta.turnDurationMs} ms animation · idle ${meta.idleMs / 1000} s · run took ${Math.round(meta.wallSeconds)} s`);
  lines.push('');
  lines.push(`Load average (1/5/15 min): start ${meta.loadavgStart.map((v) => v.toFixed(2)).join(' / ')}, `
    + `end ${meta.loadavgEnd.map((v) => v.toFixed(2)).join(' / ')} — the machine is shared, so absolute times vary from run to run; `
    + 'ratios come from the same repetition.');
  lines.push('');
  lines.push('Cells: median over repetitions (range). Ratios: conecurl / other contender in the same repetition, median (range).');
  lines.push('');
  lines.push('## Targets against the floor');
  lines.push('');
  lines.push('The floors are the smallest books that turn a page on this platform, measured in the same run: the WebGL floor '
    + '(a viewport-sized canvas, the open pages as textures, three textured quads per frame, the leaf rotated about the spine) '
    + 'and the same book on a 2D canvas. Ratios are conecurl / WebGL floor within a repetition, median over the repetitions. '
    + 'The desktop configurations are judged by the targets of issue 24, the phone configuration by those of issue 29 (rows "phone: ...").');
  lines.push('');
  lines.push(...floorTargetTable(floorTargets));
  lines.push('');
  if (engineRows.length) {
    lines.push('## Three engines');
    lines.push('');
    lines.push(engineText(engineRows, configs));
    lines.push('');
    lines.push(...engineTable(engineRows));
    lines.push('');
  }
  if (beforeAfter) {
    lines.push('## Before and after');
    lines.push('');
    lines.push(`conecurl in this tree (after) against ${longName(BASELINE, meta)} from ${meta?.baseline?.dir ?? 'a baseline checkout'}, `
      + 'measured in the same run with the same workload. Medians over the repetitions; after / before is taken within a repetition '
      + '(lower is better, but for frames).');
    lines.push('');
    lines.push(...beforeAfterTable(beforeAfter, meta));
    lines.push('');
  }
  lines.push('## Targets against the peers');
  lines.push('');
  lines.push('| target | limit | measured | holds |');
  lines.push('|---|---|---|---|');
  for (const t of targets) {
    const measured = peerMeasured(t);
    lines.push(`| ${t.name} | ${t.limit} | ${measured}${t.note ? ` (${t.note})` : ''} | ${peerVerdict(t.holds)} |`);
  }
  lines.push('');
  lines.push('## Load bytes (Vite production build of each library alone, minified)');
  lines.push('');
  lines.push('What a page loads up front; chunks loaded only on demand (pdf.js, for PDF books) are in the last column.');
  lines.push('');
  lines.push('| library | JS min | JS gzip -9 | wasm | wasm gzip -9 | total gzip -9 | on demand, gzip -9 |');
  lines.push('|---|---|---|---|---|---|---|');
  for (const [lib, b] of Object.entries(loadBytes)) {
    const kb = (v) => `${(v / 1024).toFixed(1)} KB`;
    const lazy = b.lazy?.files.length ? `${kb(b.lazy.jsGzip)} (${b.lazy.files.map((f) => f.replace(/-[\w-]{8}\.js$/, '.js')).join(', ')})` : '–';
    lines.push(`| ${longName(lib, meta)} | ${kb(b.js)} | ${kb(b.jsGzip)} | ${b.wasm ? kb(b.wasm) : '–'} | ${b.wasm ? kb(b.wasmGzip) : '–'} | **${kb(b.totalGzip)}** | ${lazy} |`);
  }
  for (const config of configs) {
    lines.push('');
    lines.push(`## ${config.label}`);
    lines.push('');
    const libs = Object.keys(summary[config.id]);
    const others = libs.filter((lib) => lib !== 'conecurl');
    lines.push(`| metric | ${libs.map((lib) => shortName(lib, meta)).join(' | ')} | ${others.map(ratioHead).join(' | ')} |`);
    lines.push(`|---|${libs.map(() => '---').join('|')}|${others.map(() => '---').join('|')}|`);
    for (const [key, label, unit, decimals] of METRICS) {
      const s = summary[config.id];
      const r = ratios[config.id][key];
      const name = unit && unit !== 'x' ? `${label} (${unit})` : label;
      lines.push(`| ${name} | ${libs.map((lib) => cell(s[lib][key], decimals)).join(' | ')} | `
        + `${others.map((lib) => (r ? cell(r[lib], 2) : '')).join(' | ')} |`);
    }
    const drawn = drawingLine(config, summary, meta);
    if (drawn) lines.push('', drawn);
    const failed = Object.entries(summary[config.id]).filter(([, s]) => s.failed).map(([lib, s]) => `${lib}: ${s.failed}`);
    if (failed.length) lines.push(`\nFailed runs (see the JSON for the errors): ${failed.join(', ')}`);
  }
  lines.push('');
  return lines.join('\n');
}

// The short version docs/benchmark.md shows: one row per configuration and library, then the targets.
const README_COLUMNS = [
  ['firstFrameMs', 'first frame ms', 0], ['turnSeconds', 's / turn', 2], ['frameMedianMs', 'frame median ms', 0],
  ['frameP95Ms', 'p95 ms', 0], ['maxOverMedian', 'max / median', 1], ['frames', 'frames', 0], ['mainThreadMsPerFrame', 'main ms / frame', 1],
  ['mainThreadMsTurns', 'main ms over the turns', 0],
  ['gpuCpuMsPerFrame', 'GPU ms / frame', 0], ['idleCpuPercent', 'idle CPU %', 1], ['jsHeapMB', 'JS heap MB', 1],
  ['rendererPssMB', 'renderer MB', 0],
];

export function readmeTables({ meta, loadBytes, summary, targets, floorTargets = [], beforeAfter = null, configs, engineRows = [] }) {
  const lines = [];
  lines.push(`Run of ${meta.date.slice(0, 10)}: ${meta.reps} repetitions, ${meta.turns} turns of ${meta.turnDurationMs} ms, ${meta.cpus} CPUs, `
    + `load average ${meta.loadavgStart[0].toFixed(1)} at the start and ${meta.loadavgEnd[0].toFixed(1)} at the end, ${Math.round(meta.wallSeconds / 60)} min. `
    + 'Medians over the repetitions; full tables with ranges and ratios in [docs/bench/latest.md](docs/bench/latest.md).');
  lines.push('');
  lines.push(`| configuration | library | ${README_COLUMNS.map(([, label]) => label).join(' | ')} |`);
  lines.push(`|---|---|${README_COLUMNS.map(() => '---').join('|')}|`);
  for (const config of configs) {
    for (const lib of Object.keys(summary[config.id])) {
      const s = summary[config.id][lib];
      lines.push(`| ${config.id} | ${lib === BASELINE ? `conecurl before (${baselineCommit(meta)})` : lib} | ${README_COLUMNS.map(([key, , d]) => fmt(s[key]?.median, d)).join(' | ')} |`);
    }
  }
  lines.push('');
  // Where the device draws at a ratio above 1 (the phone), what each contender drew into.
  const dense = configs.map((c) => [c, Object.values(summary[c.id]).find((s) => s.drawing)?.drawing])
    .filter(([, d]) => d && d.devicePixelRatio !== 1);
  for (const [config] of dense) lines.push(drawingLine(config, summary, meta), '');
  if (engineRows.length) {
    lines.push(engineText(engineRows, configs));
    lines.push('');
    lines.push(...engineTable(engineRows));
    lines.push('');
  }
  lines.push(`Load bytes, gzip -9: ${Object.entries(loadBytes).map(([lib, b]) => `${lib === BASELINE ? `conecurl before (${baselineCommit(meta)})` : lib} `
    + `${(b.totalGzip / 1024).toFixed(1)} KB`).join(', ')}.`);
  lines.push('');
  if (beforeAfter) {
    lines.push(`Before and after: conecurl against ${longName(BASELINE, meta)}, in the same run:`);
    lines.push('');
    lines.push(...beforeAfterTable(beforeAfter, meta));
    lines.push('');
  }
  lines.push('Targets against the WebGL floor (the smallest WebGL book that turns a page, in the same run):');
  lines.push('');
  lines.push(...floorTargetTable(floorTargets));
  lines.push('');
  lines.push('Targets against the peers:');
  lines.push('');
  lines.push('| target | limit | measured | holds |');
  lines.push('|---|---|---|---|');
  for (const t of targets) {
    const measured = peerMeasured(t);
    lines.push(`| ${t.name} | ${t.limit} | ${measured} | ${peerVerdict(t.holds)} |`);
  }
  return lines.join('\n');
}

const COLORS = { conecurl: '#d6336c', 'page-flip': '#1c7ed6', turnjs: '#37b24d', 'floor-webgl': '#495057', 'floor-2d': '#f08c00', [BASELINE]: '#ae3ec9' };

/** An SVG of the rAF frame intervals over the turns, one panel per configuration, log-scale ms (median repetition). */
export function frameChart(runs, configs) {
  const contenders = [...Object.keys(LIBRARY_NAMES), ...(runs.some((r) => r.lib === BASELINE) ? [BASELINE] : [])];
  const panelW = 520;
  const panelH = 230;
  const margin = { left: 52, right: 12, top: 28, bottom: 34 };
  const cols = 2;
  const rows = Math.ceil(configs.length / cols);
  const width = cols * panelW;
  const height = rows * panelH + 30;
  const yTicks = [10, 20, 50, 100, 200, 500, 1000, 2000, 5000];
  const yOf = (ms) => { const v = Math.log10(Math.min(Math.max(ms, 10), 5000)); return (1 - (v - 1) / (Math.log10(5000) - 1)); };
  // x: turn number, each turn stretched to the same width, so libraries whose turns last different
  // wall times line up turn by turn.
  const turnPosition = (turns, t) => {
    for (let k = 0; k < turns.length; k++) {
      const { start, end } = turns[k];
      if (t <= end || k === turns.length - 1) return k + Math.min(1, Math.max(0, (t - start) / Math.max(1, end - start)));
    }
    return 0;
  };
  const parts = [`<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="DejaVu Sans, sans-serif" font-size="11">`,
    `<rect width="100%" height="100%" fill="#fff"/>`];
  configs.forEach((config, index) => {
    const x0 = (index % cols) * panelW;
    const y0 = Math.floor(index / cols) * panelH;
    const w = panelW - margin.left - margin.right;
    const h = panelH - margin.top - margin.bottom;
    const ox = x0 + margin.left;
    const oy = y0 + margin.top;
    // The repetition whose median frame interval is the median, per library.
    const chosen = contenders.map((lib) => {
      const mine = runs.filter((r) => r.config === config.id && r.lib === lib && r.result)
        .sort((a, b) => summarize(a.result.intervals).median - summarize(b.result.intervals).median);
      return mine.length ? { lib, run: mine[Math.floor((mine.length - 1) / 2)] } : null;
    }).filter(Boolean);
    const turnCount = Math.max(1, ...chosen.map(({ run }) => run.result.turns.length));
    parts.push(`<text x="${ox}" y="${y0 + 18}" font-weight="bold">${config.label}</text>`);
    for (const t of yTicks) {
      const y = oy + h * yOf(t);
      parts.push(`<line x1="${ox}" x2="${ox + w}" y1="${y}" y2="${y}" stroke="${t === 20 ? '#999' : '#eee'}" ${t === 20 ? 'stroke-dasharray="4 3"' : ''}/>`);
      parts.push(`<text x="${ox - 6}" y="${y + 4}" text-anchor="end" fill="#555">${t}</text>`);
    }
    for (let k = 0; k <= turnCount; k++) {
      const x = ox + (w * k) / turnCount;
      if (k > 0 && k < turnCount) parts.push(`<line x1="${x}" x2="${x}" y1="${oy}" y2="${oy + h}" stroke="#f3f3f3"/>`);
      parts.push(`<text x="${x}" y="${oy + h + 16}" text-anchor="middle" fill="#555">${k}</text>`);
    }
    parts.push(`<text x="${ox + w / 2}" y="${oy + h + 30}" text-anchor="middle" fill="#555">turns (each stretched to the same width)</text>`);
    parts.push(`<text transform="translate(${x0 + 14} ${oy + h / 2}) rotate(-90)" text-anchor="middle" fill="#555">frame interval (ms)</text>`);
    parts.push(`<rect x="${ox}" y="${oy}" width="${w}" height="${h}" fill="none" stroke="#ccc"/>`);
    for (const { lib, run } of chosen) {
      let t = 0;
      const points = run.result.intervals.map((ms) => {
        t += ms;
        const x = ox + (w * turnPosition(run.result.turns, t)) / turnCount;
        return `${x.toFixed(1)},${(oy + h * yOf(ms)).toFixed(1)}`;
      });
      parts.push(`<polyline fill="none" stroke="${COLORS[lib]}" stroke-width="1.3" points="${points.join(' ')}"/>`);
    }
  });
  let lx = 12;
  const legend = { ...LIBRARY_NAMES, 'floor-webgl': SHORT_NAMES['floor-webgl'], 'floor-2d': SHORT_NAMES['floor-2d'] };
  if (contenders.includes(BASELINE)) legend[BASELINE] = 'conecurl before';
  for (const [lib, name] of Object.entries(legend)) {
    parts.push(`<rect x="${lx}" y="${height - 20}" width="14" height="4" fill="${COLORS[lib]}"/><text x="${lx + 20}" y="${height - 14}">${name}</text>`);
    lx += 40 + name.length * 7;
  }
  parts.push(`<text x="${width - 12}" y="${height - 14}" text-anchor="end" fill="#555">dashed: 20 ms</text>`);
  parts.push('</svg>');
  return parts.join('\n');
}
