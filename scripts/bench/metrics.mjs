// What the benchmark reads from Chromium and the OS: CPU time per process (CDP SystemInfo), main-thread
// task time (CDP Performance), JS heap after GC (CDP HeapProfiler/Runtime), and process memory (PSS
// from /proc, Linux), plus the order statistics the report is built from.
import fs from 'node:fs';

/** CPU seconds per process: [{ pid, type, cpu }]. `browserSession` is a browser-level CDP session. */
export async function processCpu(browserSession) {
  const { processInfo } = await browserSession.send('SystemInfo.getProcessInfo');
  return processInfo.map((p) => ({ pid: p.id, type: p.type, cpu: p.cpuTime }));
}

/** CPU seconds spent between two processCpu() samples, per process that exists in both. */
export function cpuDelta(before, after) {
  const earlier = new Map(before.map((p) => [p.pid, p.cpu]));
  return after.filter((p) => earlier.has(p.pid)).map((p) => ({ ...p, cpu: p.cpu - earlier.get(p.pid) }));
}

/** CPU seconds of the page's renderer (by pid), the GPU process and the browser process in a delta. */
export function rendererAndGpu(delta, rendererPid) {
  const renderer = delta.find((p) => p.pid === rendererPid);
  const gpu = delta.filter((p) => p.type === 'GPU').reduce((sum, p) => sum + p.cpu, 0);
  const browser = delta.filter((p) => p.type === 'browser').reduce((sum, p) => sum + p.cpu, 0);
  return { renderer: renderer ? renderer.cpu : 0, gpu, browser };
}

/**
 * The page's renderer: the renderer process that used the most CPU in `delta` (the turns), so spare
 * renderers and utility processes do not count.
 */
export function busiestRenderer(delta) {
  const renderers = delta.filter((p) => p.type === 'renderer').sort((a, b) => b.cpu - a.cpu);
  if (renderers.length === 0) throw new Error('bench metrics: no renderer process in SystemInfo.getProcessInfo');
  return renderers[0].pid;
}

/** Main-thread metrics of the page (seconds): TaskDuration, ScriptDuration, LayoutDuration, ... */
export async function mainThread(pageSession) {
  const { metrics } = await pageSession.send('Performance.getMetrics');
  return Object.fromEntries(metrics.map((m) => [m.name, m.value]));
}

/** Bytes of JS heap in use after a full garbage collection. */
export async function heapAfterGc(pageSession) {
  await pageSession.send('HeapProfiler.collectGarbage');
  await pageSession.send('HeapProfiler.collectGarbage');
  const { usedSize } = await pageSession.send('Runtime.getHeapUsage');
  return usedSize;
}

/** Proportional set size of a process in bytes (shared pages split among their users), or null. */
export function pssBytes(pid) {
  try {
    const text = fs.readFileSync(`/proc/${pid}/smaps_rollup`, 'utf8');
    const match = /^Pss:\s+(\d+) kB/m.exec(text);
    return match ? Number(match[1]) * 1024 : null;
  } catch {
    return null;
  }
}

/** Order statistics of a list of numbers (nearest rank). */
export function summarize(values) {
  if (values.length === 0) return { n: 0, median: NaN, p95: NaN, max: NaN, min: NaN };
  const sorted = [...values].sort((a, b) => a - b);
  const rank = (q) => sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil(q * sorted.length) - 1))];
  const mid = sorted.length / 2;
  const median = sorted.length % 2 ? sorted[Math.floor(mid)] : (sorted[mid - 1] + sorted[mid]) / 2;
  return { n: sorted.length, median, p95: rank(0.95), max: sorted[sorted.length - 1], min: sorted[0] };
}

/**
 * The frame intervals of each turn apart (`result` as measureOnce returns it: `intervals` between the
 * sampled animation frames, `turns` with start and end ms from the first sample): the first turn after load
 * against the later ones, whose frames a warm browser draws. { first, later }, each summarize()'s.
 */
export function firstTurnAgainstLater(result) {
  const stamps = [0];
  for (const interval of result.intervals) stamps.push(stamps.at(-1) + interval);
  const within = ({ start, end }) => result.intervals.filter((_, i) => stamps[i + 1] > start && stamps[i] < end);
  const [first, ...later] = result.turns;
  return { first: summarize(first ? within(first) : []), later: summarize(later.flatMap(within)) };
}
