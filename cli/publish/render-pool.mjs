// The render workers of `conecurl publish`: one worker thread per job, each handed the next page as soon
// as it is idle (pages differ a lot in cost), until every page has a result or a failure.
import { Worker } from 'node:worker_threads';

const WORKER = new URL('./render-worker.mjs', import.meta.url);

/**
 * Renders `pages` ([{ number, index }]) on `jobs` workers; `onPage(result | { index, failed })` is
 * called as each finishes. Resolves, when all are done, to { workerStartMs }: how long each worker took
 * from its start to ready (pdf.js loaded, the PDF opened). A worker that dies fails its page and is replaced.
 */
export function renderAll({ pages, jobs, workerData, onPage }) {
  const queue = [...pages];
  let pending = pages.length;
  let replacements = 0;
  const gate = new SharedArrayBuffer(4);  // the megapixels the workers are drawing now (render-worker.js)
  const workerStartMs = [];
  return new Promise((resolve, reject) => {
    if (pending === 0) { resolve({ workerStartMs }); return; }
    const workers = new Set();
    const finish = () => {
      for (const worker of workers) worker.terminate();
      resolve({ workerStartMs });
    };
    const settle = (outcome) => {
      onPage(outcome);
      pending -= 1;
      if (pending === 0) finish();
    };
    const start = () => {
      const started = performance.now();
      const worker = new Worker(WORKER, { workerData: { ...workerData, gate } });
      let current = null;
      const next = () => {
        current = queue.shift() ?? null;
        if (current) worker.postMessage(current);
      };
      workers.add(worker);
      worker.on('message', (message) => {
        if (message.type === 'ready') { workerStartMs.push(performance.now() - started); next(); return; }
        if (message.type === 'page') settle(message.result);
        else settle({ index: message.index, failed: message.message, stack: message.stack });
        next();
      });
      worker.on('error', (error) => {
        workers.delete(worker);
        // A worker that cannot even open the PDF fails the same way for all: give up with its error.
        if (current === null) { for (const other of workers) other.terminate(); reject(error); return; }
        const lost = current;
        current = null;
        settle({ index: lost.index, failed: `the renderer crashed (${String(error?.message ?? error).split('\n')[0]})`, stack: error?.stack });
        if (pending > 0 && queue.length > 0 && replacements++ < pages.length) start();
      });
    };
    for (let i = 0; i < Math.min(jobs, pages.length); i++) start();
  });
}
