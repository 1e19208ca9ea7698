// Progress of a long `conecurl publish`: on a terminal one line redrawn in place (bar, pages done of all,
// pages per second, time left); otherwise (a log, CI) a plain line at each tenth of the work.

const duration = (seconds) => (seconds >= 90 ? `${Math.floor(seconds / 60)} min ${Math.round(seconds % 60)} s` : `${Math.max(0, Math.round(seconds))} s`);

/** A progress reporter writing to `stream` for `total` pages; `now` gives milliseconds. */
export function progress(stream, total, now = () => performance.now()) {
  const start = now();
  let done = 0;
  let failed = 0;
  let lastTenth = 0;
  const tty = Boolean(stream.isTTY);
  const line = () => {
    const seconds = (now() - start) / 1000;
    const rate = seconds > 0 ? done / seconds : 0;
    const left = rate > 0 ? duration((total - done) / rate) : '…';
    const fails = failed ? `, ${failed} failed` : '';
    return { rate, text: `${done}/${total} pages${fails}, ${rate.toFixed(1)} pages/s, ${left} left` };
  };
  return {
    page(ok) {
      done += 1;
      if (!ok) failed += 1;
      if (tty) {
        const width = 24;
        const filled = Math.round((done / total) * width);
        stream.write(`\r[${'#'.repeat(filled)}${'-'.repeat(width - filled)}] ${line().text}\x1b[K`);
      } else {
        const tenth = Math.floor((done / total) * 10);
        if (tenth > lastTenth || done === total) {
          lastTenth = tenth;
          stream.write(`${Math.round((done / total) * 100)}%: ${line().text}\n`);
        }
      }
    },
    /** Ends the redrawn line; returns the seconds since start. */
    end() {
      if (tty && done > 0) stream.write('\n');
      return (now() - start) / 1000;
    },
  };
}
