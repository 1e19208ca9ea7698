// Lighthouse, as the people who run sites judge them (issue 38): each PDF published with `conecurl publish`
// and served compressed (brotli/gzip, ranges) as a CDN serves it, and the same PDF in the package's
// reader.html#file=, run through Lighthouse's mobile preset (its default: a phone, simulated 4x CPU and slow 4G)
// in Debian's Chromium. Prints the four category scores, FCP, LCP, TBT and the request count (medians of
// --reps runs, each in a fresh browser), and what costs each category its points; writes lighthouse.json, and
// lighthouse-<pdf>-<road>.report.json (the whole report of the run nearest the median) beside it.
// Usage: node scripts/bench/lighthouse.mjs [--pdf book.pdf]... [--reps 3] [--out bench-results] [--republish]
//        [--sites <folder> (published sites to reuse: <folder>/<name>/index.html; default <out>/lighthouse)]
//        [--roads published,reader] [--port 8150 (and the next three)] [--quiet-load 3 (1.5 a core; wait, up to 2 minutes a run,
//        for the 1-minute load average to fall under this: TBT is main-thread time x4, a busy machine's shows in it)]
//        [--baseline <dir> (a checkout of an older commit, its node_modules and dist/ in place; its reader.html#file=
//        is measured too, with the PDF at the same path under it)] [--baseline-sites <folder> (sites that commit
//        published, <folder>/<name>/)]: before and after in one run, the roads alternated.
// Without --pdf: the PDFs publish-rate.mjs leaves in build/bench-pdf/ (gnuplot.pdf, magazine-40.pdf).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import lighthouse from 'lighthouse';
import puppeteer from 'puppeteer-core';
import { CHROMIUM_ARGS, chromiumExecutable } from '../chromium.mjs';
import { serveDirectory } from '../serve.mjs';
import { summarize } from './metrics.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const args = process.argv.slice(2);
const arg = (name, fallback) => {
  const i = args.indexOf(name);
  if (i >= 0 && i + 1 >= args.length) throw new Error(`lighthouse: ${name} needs a value`);
  return i >= 0 ? args[i + 1] : fallback;
};
const known = new Set(['--pdf', '--reps', '--out', '--republish', '--sites', '--roads', '--port', '--quiet-load', '--baseline', '--baseline-sites']);
for (const [i, a] of args.entries()) {
  if (a.startsWith('--') && !known.has(a)) throw new Error(`lighthouse: unknown argument ${a} (known: ${[...known].join(' ')})`);
  if (a === '--republish') continue;
  if (a.startsWith('--') && i + 1 >= args.length) throw new Error(`lighthouse: ${a} needs a value`);
}
const given = args.flatMap((a, i) => (a === '--pdf' ? [path.resolve(args[i + 1])] : []));
const pdfs = given.length ? given
  : ['gnuplot.pdf', 'magazine-40.pdf'].map((name) => path.join(root, 'build/bench-pdf', name)).filter((file) => fs.existsSync(file));
const reps = Number(arg('--reps', '3'));
const out = path.resolve(root, arg('--out', 'bench-results'));
const sitesDir = path.resolve(root, arg('--sites', path.join(out, 'lighthouse')));
const roads = arg('--roads', 'published,reader').split(',');
const port = Number(arg('--port', '8150'));
const quietLoad = Number(arg('--quiet-load', String(1.5 * os.cpus().length)));
const baselineRoot = args.includes('--baseline') ? path.resolve(arg('--baseline')) : null;
const baselineSites = args.includes('--baseline-sites') ? path.resolve(arg('--baseline-sites')) : null;
if (!Number.isInteger(reps) || reps < 1) throw new Error(`lighthouse: --reps must be a whole number from 1, got ${reps}`);
if (roads.some((road) => !['published', 'reader'].includes(road))) throw new Error(`lighthouse: --roads takes published and reader, got ${roads}`);
if (pdfs.length === 0) {
  console.error('lighthouse: no PDF: give --pdf book.pdf, or run publish-rate.mjs first (it puts its PDFs in build/bench-pdf/)');
  process.exit(2);
}

const CATEGORIES = ['performance', 'accessibility', 'best-practices', 'seo'];
const METRICS = { fcp: 'first-contentful-paint', lcp: 'largest-contentful-paint', tbt: 'total-blocking-time', si: 'speed-index', cls: 'cumulative-layout-shift' };

/** What a category loses points on: its audits that weigh in it and did not pass, with what Lighthouse says they cost. */
function misses(lhr, category) {
  return lhr.categories[category].auditRefs
    .filter((ref) => ref.weight > 0 || category === 'performance')
    .map((ref) => ({ ref, audit: lhr.audits[ref.id] }))
    .filter(({ audit }) => audit && audit.score !== null && audit.score < 1
      && !['notApplicable', 'manual', 'informative'].includes(audit.scoreDisplayMode))
    .map(({ ref, audit }) => ({
      id: ref.id, weight: ref.weight, score: audit.score, title: audit.title,
      ...(audit.displayValue ? { value: audit.displayValue } : {}),
      ...(audit.details?.overallSavingsMs ? { savingsMs: Math.round(audit.details.overallSavingsMs) } : {}),
      ...(audit.details?.overallSavingsBytes ? { savingsBytes: Math.round(audit.details.overallSavingsBytes) } : {}),
      // Where: the first few of what the audit names (a URL, or a node's label), for the report to say what to fix.
      items: (Array.isArray(audit.details?.items) ? audit.details.items : []).slice(0, 5).map((item) => item.url ?? item.node?.nodeLabel ?? item.source?.url ?? item.description ?? null)
        .filter((where) => typeof where === 'string'),
    }));
}

/** The requests counted by the folder of their path (book/thumbs, conecurl/web/src/book, …): where a page's requests go. */
function byFolder(requests) {
  const counts = {};
  for (const { url } of requests) {
    let folder;
    try {
      const parsed = new URL(url);
      folder = parsed.protocol.startsWith('http') ? parsed.pathname.replace(/\/[^/]*$/, '/') || '/' : `${parsed.protocol}`;
    } catch {
      folder = '?';
    }
    counts[folder] = (counts[folder] ?? 0) + 1;
  }
  return Object.fromEntries(Object.entries(counts).sort((a, b) => b[1] - a[1]));
}

// The Chromium of the audit under way. Lighthouse keeps the process alive through a plain kill (SIGTERM)
// or Ctrl-C while it audits: stopping says so in one line, kills that browser and exits.
let auditing = null;
for (const [signal, status] of [['SIGINT', 130], ['SIGTERM', 143]]) {
  process.on(signal, () => {
    console.error(`lighthouse: stopped by ${signal}; the sites published so far are kept, lighthouse.json is not written`);
    auditing?.process()?.kill('SIGKILL');
    process.exit(status);
  });
}

/** One Lighthouse run of `url` (mobile preset) in a fresh Chromium: the figures kept, and the misses. */
async function audit(url) {
  // Chromium refuses to run as root with its sandbox (Playwright's launcher adds --no-sandbox itself; puppeteer's does not).
  const sandbox = process.getuid?.() === 0 ? ['--no-sandbox'] : [];
  const browser = await puppeteer.launch({
    executablePath: chromiumExecutable(), headless: true, args: [...CHROMIUM_ARGS, ...sandbox, '--remote-debugging-port=0'],
  });
  auditing = browser;
  try {
    const debugPort = Number(new URL(browser.wsEndpoint()).port);
    const result = await lighthouse(url, { port: debugPort, output: 'json', logLevel: 'error', onlyCategories: CATEGORIES });
    const { lhr } = result;
    if (lhr.runtimeError) throw new Error(`lighthouse: ${url}: ${lhr.runtimeError.code} ${lhr.runtimeError.message}`);
    const scores = Object.fromEntries(CATEGORIES.map((c) => [c, lhr.categories[c].score === null ? null : Math.round(lhr.categories[c].score * 100)]));
    const metrics = Object.fromEntries(Object.entries(METRICS).map(([key, id]) => [key, lhr.audits[id]?.numericValue ?? null]));
    const requests = lhr.audits['network-requests']?.details?.items ?? [];
    // Where the main thread's time went (TBT's cause): Lighthouse's own breakdown by script and by kind of work.
    const top = (id, key, value) => (lhr.audits[id]?.details?.items ?? []).slice(0, 6).map((item) => [item[key], Math.round(item[value])]);
    return {
      lhr,  // the whole report: kept for the run nearest the median (written beside lighthouse.json), not in it
      mainThread: { byKind: top('mainthread-work-breakdown', 'groupLabel', 'duration'), byScript: top('bootup-time', 'url', 'total') },
      scores, metrics, requests: requests.length,
      transferBytes: requests.reduce((sum, r) => sum + (r.transferSize ?? 0), 0),
      requestsByFolder: byFolder(requests),
      // How busy the machine was (TBT is the page's main-thread time, 4x, so a shared machine's load shows in it).
      warnings: lhr.runWarnings, benchmarkIndex: lhr.environment?.benchmarkIndex, loadavg: os.loadavg()[0],
      misses: Object.fromEntries(CATEGORIES.map((c) => [c, misses(lhr, c)])),
      legibleText: lhr.audits['font-size']?.displayValue ?? null,
    };
  } finally {
    auditing = null;
    await browser.close();
  }
}

/** Waits (at most 2 minutes) for the machine's 1-minute load average to fall under --quiet-load. */
async function quiet() {
  const until = Date.now() + 120_000;
  while (os.loadavg()[0] >= quietLoad && Date.now() < until) await new Promise((resolve) => setTimeout(resolve, 5000));
}

/** audit(url) once the machine is quiet; a run Lighthouse itself fails (NO_FCP on a starved machine) is tried twice more. */
async function auditQuietly(url) {
  for (let attempt = 1; ; attempt++) {
    await quiet();
    try {
      return await audit(url);
    } catch (error) {
      if (attempt >= 3) throw error;
      console.log(`lighthouse: try ${attempt} failed (${String(error.message).split('\n')[0]}); again`);
    }
  }
}

const median = (values) => (values.some((v) => v === null) ? null : summarize(values).median);

/** The medians of a road's runs, and the misses of the run whose Performance is the median's (or nearest). */
function summary(runs) {
  const scores = Object.fromEntries(CATEGORIES.map((c) => [c, median(runs.map((r) => r.scores[c]))]));
  const metrics = Object.fromEntries(Object.keys(METRICS).map((key) => [key, median(runs.map((r) => r.metrics[key]))]));
  const typical = [...runs].sort((a, b) => Math.abs(a.scores.performance - scores.performance) - Math.abs(b.scores.performance - scores.performance))[0];
  const range = (c) => [Math.min(...runs.map((r) => r.scores[c])), Math.max(...runs.map((r) => r.scores[c]))];
  return {
    scores, ranges: Object.fromEntries(CATEGORIES.map((c) => [c, range(c)])), metrics,
    requests: median(runs.map((r) => r.requests)), transferBytes: median(runs.map((r) => r.transferBytes)),
    legibleText: typical.legibleText, requestsByFolder: typical.requestsByFolder, mainThread: typical.mainThread, misses: typical.misses,
    typical,
  };
}

const results = [];
for (const pdf of pdfs) {
  const name = path.basename(pdf, '.pdf').replace(/[^\w.-]+/g, '-');
  const site = path.join(sitesDir, name);
  if (roads.includes('published') && (args.includes('--republish') || !fs.existsSync(path.join(site, 'index.html')))) {
    if (!site.startsWith(out + path.sep)) throw new Error(`lighthouse: ${site} has no site; publishing goes only into --out's folder (${out})`);
    console.log(`lighthouse: publishing ${pdf} into ${path.relative(root, site)}`);
    fs.rmSync(site, { recursive: true, force: true });  // our own folder under --out
    execFileSync(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', pdf, '--out', site], { stdio: ['ignore', 'ignore', 'inherit'] });
  }
  // The site at its own origin's root, as a host serves it; the reader from the repository, the PDF beside it.
  const servers = [];
  const urls = {};
  try {
    if (roads.includes('published')) {
      const { server, url } = await serveDirectory(site, { port, compress: true });
      servers.push(server);
      urls.published = url;
    }
    const pdfDir = path.relative(root, path.dirname(pdf));
    const pdfPath = [...pdfDir.split(path.sep), path.basename(pdf)].map(encodeURIComponent).join('/');
    const readerOf = async (tree, at) => {
      if (pdfDir.startsWith('..')) throw new Error(`lighthouse: ${pdf} must be inside the repository (the reader's server serves it)`);
      if (!fs.existsSync(path.join(tree, pdfDir, path.basename(pdf)))) throw new Error(`lighthouse: ${tree} has no ${path.join(pdfDir, path.basename(pdf))}`);
      const { server, url } = await serveDirectory(tree, { port: at, compress: true });
      servers.push(server);
      // The bundled reader.html where the tree has one (dist/reader/, from build-bundles.mjs), else its source page.
      const reader = fs.existsSync(path.join(tree, 'dist/reader/reader.html')) ? 'dist/reader/reader.html' : 'web/reader/reader.html';
      return `${url}${reader}#file=/${pdfPath}`;
    };
    if (roads.includes('reader')) urls.reader = await readerOf(root, port + 1);
    if (roads.includes('published') && baselineSites) {
      const { server, url } = await serveDirectory(path.join(baselineSites, name), { port: port + 2, compress: true });
      servers.push(server);
      urls['published-before'] = url;
    }
    if (roads.includes('reader') && baselineRoot) urls['reader-before'] = await readerOf(baselineRoot, port + 3);
    const measured = Object.keys(urls);
    const runs = Object.fromEntries(measured.map((road) => [road, []]));
    for (let rep = 0; rep < reps; rep++) {
      for (const road of rep % 2 ? [...measured].reverse() : measured) {
        const t0 = Date.now();
        const run = await auditQuietly(urls[road]);
        runs[road].push(run);
        const s = run.scores;
        console.log(`[${name} ${rep + 1}/${reps}] ${road}: Performance ${s.performance}, Accessibility ${s.accessibility}, Best Practices ${s['best-practices']}, `
          + `SEO ${s.seo}; FCP ${(run.metrics.fcp / 1000).toFixed(1)} s, LCP ${(run.metrics.lcp / 1000).toFixed(1)} s, TBT ${Math.round(run.metrics.tbt)} ms, `
          + `${run.requests} requests, ${(run.transferBytes / 1024).toFixed(0)} KB; legible text ${run.legibleText ?? '-'}; `
          + `CPU benchmark index ${Math.round(run.benchmarkIndex)}, load ${run.loadavg.toFixed(1)} (${((Date.now() - t0) / 1000).toFixed(0)} s)`);
      }
    }
    for (const road of measured) {
      const { typical, ...figures } = summary(runs[road]);
      // The typical run's whole report, for what the summary leaves out (open it in the Lighthouse viewer).
      fs.mkdirSync(out, { recursive: true });
      const report = path.join(out, `lighthouse-${name}-${road}.report.json`);
      fs.writeFileSync(report, JSON.stringify(typical.lhr));
      results.push({ pdf: path.basename(pdf), road, url: urls[road], reps, report: path.relative(root, report), ...figures,
        runs: runs[road].map(({ lhr, ...run }) => run) });
    }
  } finally {
    for (const server of servers) server.close();
  }
}

fs.mkdirSync(out, { recursive: true });
const file = path.join(out, 'lighthouse.json');
fs.writeFileSync(file, `${JSON.stringify({
  date: new Date().toISOString(), lighthouse: JSON.parse(fs.readFileSync(path.join(root, 'node_modules/lighthouse/package.json'), 'utf8')).version,
  chromium: chromiumExecutable(), cpus: os.cpus().length, loadavg: os.loadavg(), results,
}, null, 1)}\n`);

const ROAD = { published: 'published site', reader: 'reader.html#file=', 'published-before': 'published site, before', 'reader-before': 'reader.html#file=, before' };
console.log(`\nLighthouse ${JSON.parse(fs.readFileSync(path.join(root, 'node_modules/lighthouse/package.json'), 'utf8')).version}, mobile preset, served compressed; medians of ${reps}:`);
console.log('| PDF | road | Performance | Accessibility | Best Practices | SEO | FCP | LCP | TBT | requests |');
console.log('|---|---|---|---|---|---|---|---|---|---|');
for (const r of results) {
  const score = (c) => (r.ranges[c][0] === r.ranges[c][1] ? `${r.scores[c]}` : `${r.scores[c]} (${r.ranges[c][0]}–${r.ranges[c][1]})`);
  console.log(`| ${r.pdf} | ${ROAD[r.road]} | ${score('performance')} | ${score('accessibility')} | ${score('best-practices')} | ${score('seo')} `
    + `| ${(r.metrics.fcp / 1000).toFixed(1)} s | ${(r.metrics.lcp / 1000).toFixed(1)} s | ${Math.round(r.metrics.tbt)} ms | ${r.requests} |`);
}
console.log('\nWhat costs the points (the run nearest the median Performance):');
for (const r of results) {
  console.log(`${r.pdf}, ${ROAD[r.road]}:`);
  console.log(`  main thread: ${r.mainThread.byKind.map(([kind, ms]) => `${kind} ${ms} ms`).join(', ')}`);
  console.log(`  by script: ${r.mainThread.byScript.map(([url, ms]) => `${url.replace(/^https?:\/\/[^/]+/, '')} ${ms} ms`).join(', ')}`);
  console.log(`  requests by folder: ${Object.entries(r.requestsByFolder).slice(0, 8).map(([folder, n]) => `${folder} ${n}`).join(', ')}`);
  for (const c of CATEGORIES) {
    for (const m of r.misses[c]) {
      if (c === 'performance' && m.weight === 0 && !m.savingsMs) continue;  // diagnostics with no time to win
      console.log(`  ${c}: ${m.title}${m.value ? ` (${m.value})` : ''}${m.weight ? `, weight ${m.weight}, score ${m.score}` : ''}`
        + `${m.savingsMs ? `, saves ~${m.savingsMs} ms` : ''}${m.savingsBytes ? `, ${(m.savingsBytes / 1024).toFixed(0)} KB` : ''}`
        + `${m.items.length ? `: ${m.items.map((where) => where.replace(/^https?:\/\/[^/]+/, '').slice(0, 80)).join(', ')}` : ''}`);
    }
  }
}
console.log(`(written to ${path.relative(root, file)})`);
