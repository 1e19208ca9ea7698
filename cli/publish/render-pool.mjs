// The render workers of `conecurl publish`: started before the main thread has opened the PDF (each worker
// loads pdf.js and opens the PDF itself, the dearest part of a short run), then each handed the next page
// as soon as it is idle (pages differ a lot in cost), until every page has a result or a failure.
import { Worker } from 'node:worker_threads';

const WORKER = new URL('./render-worker.mjs', import.meta.url);

/**
 * Starts `jobs` render workers now (more with grow(n)); they wait, ready, for pages. render({ pages, onPage })
 * renders `pages` ([{ number, index }]), calling `onPage(result | { index, failed })` as each finishes, and
 * resolves, when all are done, to { workerStartMs }: how long each worker took from its start to ready
 * (pdf.js loaded, the PDF opened). A worker that dies on a page fails that page and is replaced; one that
 * dies before any page (it cannot open the PDF) makes render() reject with its error. close() ends them all.
 */
export function startPool({ jobs, workerData }) {
  const gate = new SharedArrayBuffer(4);  // the megapixels the workers are drawing now (render-worker.js)
  const workerStartMs = [];
  const workers = new Set();
  const idle = [];
  let job = null;  // the render() under way: { queue, pending, onPage, resolve, reject, replacements }
  let failure = null;

  const fail = (error) => {
    failure = error;
    for (const worker of workers) worker.terminate();
    workers.clear();
    job?.reject(error);
  };
  const settle = (outcome) => {
    job.onPage(outcome);
    job.pending -= 1;
    if (job.pending === 0) job.resolve({ workerStartMs });
  };
  const hand = (worker) => {
    worker.current = job?.queue.shift() ?? null;
    if (worker.current) worker.postMessage(worker.current);
    else idle.push(worker);
  };
  const start = () => {
    const started = performance.now();
    const worker = new Worker(WORKER, { workerData: { ...workerData, gate } });
    worker.current = null;
    workers.add(worker);
    worker.on('message', (message) => {
      if (message.type === 'ready') {
        workerStartMs.push(performance.now() - started);
        hand(worker);
        return;
      }
      if (message.type === 'page') settle(message.result);
      else settle({ index: message.index, failed: message.message, stack: message.stack });
      hand(worker);
    });
    worker.on('error', (error) => {
      workers.delete(worker);
      if (idle.includes(worker)) idle.splice(idle.indexOf(worker), 1);
      // A worker that cannot even open the PDF fails the same way for all: give up with its error.
      if (worker.current === null) { fail(error); return; }
      const lost = worker.current;
      worker.current = null;
      settle({ index: lost.index, failed: `the renderer crashed (${String(error?.message ?? error).split('\n')[0]})`, stack: error?.stack });
      if (job.pending > 0 && job.queue.length > 0 && job.replacements++ < job.total) start();
    });
  };
  const grow = (n) => {
    while (failure === null && workers.size < n) start();
  };
  grow(jobs);

  return {
    grow,
    render({ pages, onPage }) {
      return new Promise((resolve, reject) => {
        if (failure) { reject(failure); return; }
        job = { queue: [...pages], pending: pages.length, total: pages.length, onPage, resolve, reject, replacements: 0 };
        if (pages.length === 0) { resolve({ workerStartMs }); return; }
        if (workers.size === 0) grow(1);
        while (idle.length > 0 && job.queue.length > 0) hand(idle.shift());
      });
    },
    close() {
      for (const worker of workers) worker.terminate();
      workers.clear();
    },
  };
}
