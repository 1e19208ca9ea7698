// `conecurl publish <book.pdf> --out <folder>`: reads the PDF, renders its pages on worker threads, and
// writes the static site (index.html, book/ as format.js defines it, the reader under conecurl/).
// Returns the exit code: 0 done, 1 bad input, 2 bad usage, 3 a site whose failed pages are listed.
import fs from 'node:fs';
import path from 'node:path';
import { ALT_CHARS, MANIFEST, altText, checkManifest, encodeTextGroup, makeManifest, pagePath, planTextGroups } from '../../web/src/document/format.js';
import { pdfOutline } from '../../web/src/document/pdf-document.js';
import { DEFAULTS, FORMATS, HELP, parsePublishArgs } from './args.mjs';
import { HEADERS, embedSrc, headersFile, iframeSnippet } from './embed.mjs';
import { EXIT, inputError, report, usageError } from './errors.mjs';
import { indexHtml } from './index-html.mjs';
import { readNarration } from './narration.mjs';
import { loadRenderer, openPdf, readPdf } from './open-pdf.mjs';
import { claimOutFolder, settleOutFolder } from './out-folder.mjs';
import { progress } from './progress.mjs';
import { COVER } from './render-page.mjs';
import { startPool } from './render-pool.mjs';
import { remapLinks, remapOutline } from './remap.mjs';
import { PACKAGE_ROOT, runtimeFiles } from './runtime-files.mjs';
import { summary } from './summary.mjs';
import { ICON_SIDES, SERVICE_WORKER, WEB_MANIFEST, iconFile, writeWebApp } from './web-app.mjs';

const BOOK = 'book';
const RUNTIME = 'conecurl';
/** The folder, inside book/, of the pages' narration: NNNN.<audio ext> and NNNN.vtt or .json, as the pages' images are numbered. */
const NARRATION = 'narration';

/** The runtime files, or an input error naming what is missing. */
function runtime() {
  try {
    return runtimeFiles(PACKAGE_ROOT);
  } catch (error) {
    throw Object.assign(inputError(error.message), { cause: error });
  }
}

export async function main(argv) {
  let debug = argv.includes('--debug');
  try {
    const options = parsePublishArgs(argv);
    debug = options.debug;
    if (options.help) {
      process.stdout.write(HELP);
      return 0;
    }
    return await publish(options);
  } catch (error) {
    return report(error, debug);
  }
}

/**
 * Where a run's time went, for scripts/bench/publish-rate.mjs: written as JSON to the file that the
 * environment variable CONECURL_PUBLISH_STEPS names (nothing when unset). Phases in ms from the process's
 * start; `pages` sums each page's steps (render-page.js) over all workers.
 */
function stepRecorder() {
  const phases = { start: performance.now() };  // Node's start and this CLI's modules, up to here
  let mark = phases.start;
  const lap = (phase) => {
    const now = performance.now();
    phases[phase] = now - mark;
    mark = now;
  };
  const pages = {};
  return {
    lap,
    page(steps) { for (const [step, ms] of Object.entries(steps ?? {})) pages[step] = (pages[step] ?? 0) + ms; },
    save(extra) {
      const file = process.env.CONECURL_PUBLISH_STEPS;
      if (file) fs.writeFileSync(file, `${JSON.stringify({ phases, pages, ...extra })}\n`);
    },
  };
}

async function publish(options) {
  const steps = stepRecorder();
  const site = runtime();
  const bytes = readPdf(options.input);
  // The first render worker starts now, loading pdf.js and opening the PDF while this thread does the same
  // (or as many as --pages needs); the others once the page count is known. They write nothing until given pages.
  const pool = startPool({
    jobs: Math.min(options.jobs, options.pages?.length ?? 1),
    workerData: {
      bytes, file: options.input, password: options.password, bookDir: path.join(options.out, BOOK),
      options: { ...DEFAULTS, format: options.format, quality: options.quality, height: options.height, scale: options.scale, zoom: options.zoom },
    },
  });
  let doc;
  try {
    const { pdfjs } = await loadRenderer();
    doc = await openPdf(pdfjs, bytes, options.input, options.password);
  } catch (error) {
    pool.close();
    throw error;
  }
  try {
    const count = doc.numPages;
    const numbers = options.pages ?? Array.from({ length: count }, (_, i) => i + 1);
    const beyond = numbers.find((n) => n > count);
    if (beyond) throw usageError(`--pages: ${options.input} has ${count} pages, so there is no page ${beyond}`);
    pool.grow(Math.min(options.jobs, numbers.length));
    const { info } = await doc.getMetadata().catch(() => ({ info: {} }));
    const name = path.basename(options.input).replace(/\.pdf$/i, '');
    const title = (options.title ?? String(info?.Title ?? '').trim()) || name;
    const lang = String(info?.Language ?? '').trim();
    const outline = remapOutline(await pdfOutline(doc), numbers);
    const download = options.download ? `${name.replace(/[^\w.-]+/g, '-') || 'book'}.pdf` : null;
    // Recorded narration, read and checked before anything is written (a bad file changes nothing).
    const narration = options.narration ? checkNarration(options, count, numbers) : new Map();

    // Every file this run may write, so the out folder can be checked before anything is.
    const ext = FORMATS[options.format];
    const kinds = ['pages', 'thumbs', 'text', ...(options.zoom > 0 ? ['zoom'] : [])];
    const pageFiles = numbers.flatMap((_, i) => kinds.map((kind) => `${BOOK}/${pagePath(kind, i, kind === 'text' ? 'json' : ext)}`));
    const textGroups = planTextGroups(numbers.length);  // the text files again, a group of pages to a file: what search reads
    const groupFiles = textGroups.map(({ src }) => `${BOOK}/${src}`);
    const icons = ICON_SIDES.map((side) => ({ src: `${BOOK}/${iconFile(side)}`, side }));
    const fixed = ['index.html', HEADERS, `${BOOK}/${MANIFEST}`, `${BOOK}/${COVER}`, ...(download ? [`${BOOK}/${download}`] : []),
      WEB_MANIFEST, SERVICE_WORKER, ...icons.map(({ src }) => src),
      ...site.files.map((file) => `${RUNTIME}/${file}`), ...[...narration.values()].flatMap(({ src, words }) => [`${BOOK}/${src}`, `${BOOK}/${words}`])];
    const { previous } = claimOutFolder(options.out, [...fixed, ...pageFiles, ...groupFiles]);
    steps.lap('open');  // pdf.js loaded, the PDF opened, its outline read, the out folder checked

    const bookDir = path.join(options.out, BOOK);
    for (const kind of kinds) fs.mkdirSync(path.join(bookDir, kind), { recursive: true });
    const written = new Map();  // relative path -> { bytes, kind }
    for (const file of site.files) {
      // The reader's bundle as built (minified, content-hashed): copied, never changed.
      const to = path.join(options.out, RUNTIME, file);
      fs.mkdirSync(path.dirname(to), { recursive: true });
      fs.copyFileSync(path.join(site.dir, file), to);
      written.set(`${RUNTIME}/${file}`, { bytes: fs.statSync(to).size, kind: 'runtime' });
    }
    if (download) {
      fs.writeFileSync(path.join(bookDir, download), bytes);
      written.set(`${BOOK}/${download}`, { bytes: bytes.length, kind: 'pdf' });
    }

    steps.lap('runtime');  // the reader's files copied
    const results = new Array(numbers.length);
    const failures = [];
    const bar = progress(process.stdout, numbers.length);
    process.stdout.write(`Publishing ${numbers.length} pages of ${options.input} into ${options.out} (${options.jobs} workers)\n`);
    const { workerStartMs } = await pool.render({
      pages: numbers.map((number, index) => ({ number, index })),
      onPage: (result) => {
        results[result.index] = result;
        if (result.failed) failures.push(result);
        steps.page(result.steps);
        for (const file of result.files ?? []) written.set(`${BOOK}/${file.path}`, file);
        bar.page(!result.failed);
      },
    });
    const seconds = bar.end();
    pool.close();
    steps.lap('pages');

    // Each rendered page's narration, copied as it was given (a page that failed is not shown: nor its narration).
    for (const [index, { page, src, words }] of narration) {
      if (results[index].failed) continue;
      fs.mkdirSync(path.join(bookDir, NARRATION), { recursive: true });
      for (const [from, to] of [[page.audio.file, src], [page.words.file, words]]) {
        fs.copyFileSync(from, path.join(bookDir, to));
        written.set(`${BOOK}/${to}`, { bytes: fs.statSync(from).size, kind: 'narration' });
      }
    }

    const pages = [];
    for (const [index, result] of results.entries()) {
      if (result.failed) {
        pages.push({ ...(await pageSize(doc, numbers[index], results)), failed: result.failed });
        continue;
      }
      const text = pagePath('text', index, 'json');
      pages.push({
        width: result.width, height: result.height, src: pagePath('pages', index, ext),
        ...(result.zoomed ? { zoomSrc: pagePath('zoom', index, ext) } : {}),
        // Where the image limits (render-page.js) made this page's images smaller than asked: docs/publish.md.
        ...(result.limited ? { limited: result.limited } : {}),
        // No alt: the reader takes it from the page's text file (most readers read the text layer instead).
        thumbSrc: pagePath('thumbs', index, ext), text,
        // The first spread's tiny placeholder, inline (render-page.mjs PLACEHOLDER): drawn while the reading image loads.
        ...(result.placeholder ? { placeholder: result.placeholder } : {}),
        links: remapLinks(result.links, numbers),
        ...(narration.has(index) ? { narration: { src: narration.get(index).src, words: narration.get(index).words } } : {}),
      });
    }
    // Each group from its pages' text files as written (a page that failed has none: null).
    for (const { first, count, src } of textGroups) {
      const files = Array.from({ length: count }, (_, k) => (results[first + k].failed ? null
        : fs.readFileSync(path.join(bookDir, pagePath('text', first + k, 'json')), 'utf8')));
      const group = encodeTextGroup(first, files);
      fs.writeFileSync(path.join(bookDir, src), group);
      written.set(`${BOOK}/${src}`, { bytes: Buffer.byteLength(group), kind: 'text' });
    }
    const manifest = checkManifest(makeManifest({ title, lang, pages, outline, download, textGroups }), MANIFEST);
    const manifestText = `${JSON.stringify(manifest)}\n`;
    fs.writeFileSync(path.join(bookDir, MANIFEST), manifestText);
    written.set(`${BOOK}/${MANIFEST}`, { bytes: manifestText.length, kind: 'text' });

    const html = indexHtml({
      title, lang, manifest: `${BOOK}/${MANIFEST}`, cover: `${BOOK}/${COVER}`, url: options.url, runtime: site, prefix: RUNTIME,
      touchIcon: written.has(icons[0].src) ? icons[0].src : null,
      pages: pages.map((page, i) => (page.failed ? page : {
        src: `${BOOK}/${page.src}`, imageWidth: results[i].imageWidth, imageHeight: results[i].imageHeight,
        alt: altText(i, results[i].text, ALT_CHARS), text: results[i].text,
      })),
    });
    fs.writeFileSync(path.join(options.out, 'index.html'), html);
    written.set('index.html', { bytes: Buffer.byteLength(html), kind: 'text' });
    const headers = headersFile({ download });
    fs.writeFileSync(path.join(options.out, HEADERS), headers);
    written.set(HEADERS, { bytes: Buffer.byteLength(headers), kind: 'text' });
    // Last: the web app manifest, and the service worker whose version hashes every file written above.
    // Precached at install: the page, the reader, book.json, the manifest and its icons, and the text groups
    // (every page's text, a few requests: search reads them all, and a page's text layer offline too); the
    // images and a page's own text file as they are read.
    const shellFiles = ['index.html', `${BOOK}/${MANIFEST}`, WEB_MANIFEST, ...icons.map(({ src }) => src), ...groupFiles];
    writeWebApp({ out: options.out, title, lang, written, icons, skip: [HEADERS],
      shell: (file, { kind }) => kind === 'runtime' || shellFiles.includes(file) });
    settleOutFolder(options.out, previous, [...written.keys()]);
    steps.lap('finish');  // narration, book.json, index.html, _headers, the web app files, the out folder settled
    steps.save({ jobs: options.jobs, pageCount: numbers.length, workerStartMs });

    for (const failure of failures.sort((a, b) => a.index - b.index)) {
      process.stderr.write(`conecurl publish: page ${numbers[failure.index]} of ${options.input} could not be rendered (${failure.failed}); `
        + 'the other pages are published and the book shows it as missing\n');
      if (options.debug && failure.stack) process.stderr.write(`${failure.stack}\n`);
    }
    process.stdout.write(summary({ out: options.out, pages: numbers.length, failed: failures.length, seconds, written: [...written.values()],
      embed: iframeSnippet({ src: embedSrc({ out: options.out, url: options.url }), title }) }));
    return failures.length > 0 ? EXIT.incomplete : 0;
  } finally {
    pool.close();
    await doc.loadingTask.destroy();
  }
}

/**
 * The narration of the pages published (options.narration's files, checked, with progress): a Map from a
 * page's index in the site to { page (readNarration's), src, words (their paths in book/) }.
 */
function checkNarration(options, pageCount, numbers) {
  let bar = null;
  const found = readNarration(options.narration, {
    pageCount, numbers, input: options.input,
    onPage: (done, total) => {
      if (!bar) {
        process.stdout.write(`Checking the narration of ${total} pages in ${options.narration}\n`);
        bar = progress(process.stdout, total);
      }
      bar.page(true);
    },
  });
  bar?.end();
  if (found.unpublished.length > 0) {
    process.stdout.write(`Narration of page${found.unpublished.length > 1 ? 's' : ''} ${found.unpublished.join(', ')} left out with the page (--pages)\n`);
  }
  if (found.ignored.length > 0) {
    process.stdout.write(`Narration folder: passed over ${found.ignored.join(', ')} (not page-N.<audio> or page-N.vtt/.json)\n`);
  }
  const byIndex = new Map();
  numbers.forEach((number, index) => {
    const page = found.pages.get(number);
    if (!page) return;
    const stem = `${NARRATION}/${String(index + 1).padStart(4, '0')}`;
    byIndex.set(index, { page, src: `${stem}.${page.audio.ext}`, words: `${stem}.${page.words.ext}` });
  });
  return byIndex;
}

/** A failed page's size in page units: from the PDF if it can say, else the size of a page that rendered. */
async function pageSize(doc, number, results) {
  try {
    const { width, height } = (await doc.getPage(number)).getViewport({ scale: 1 });
    return { width, height };
  } catch {
    const other = results.find((result) => result && !result.failed);
    return other ? { width: other.width, height: other.height } : { width: 612, height: 792 };
  }
}
