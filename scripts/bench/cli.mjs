// How a bench script that a developer runs reads its arguments and fails, the same in each: a bad argument named in one line before
// anything is served or written (exit 2), a failed run in one line (exit 1), its stack only with --stack;
// and the served repository with a Chromium that the profiling aids share.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** The value given after `--name` on the command line, else `fallback`. */
export function arg(name, fallback) {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
}

/** Says what is wrong with the arguments, as `tool: message`, and exits 2. */
export function usage(tool, message) {
  console.error(`${tool}: ${message}`);
  process.exit(2);
}

/** Runs `main` (async); a failure prints its message in one line (its stack with --stack) and exits 1. */
export function runMain(tool, main) {
  main().catch((error) => {
    const message = String(error?.message ?? error);
    // A message that names its tool already (bundle.mjs's say `bench: `) is printed as it is.
    console.error(process.argv.includes('--stack') ? error : /^[\w-]+: /.test(message) ? message : `${tool}: ${message}`);
    process.exit(1);
  });
}

/**
 * Serves the repository on `port` (in this process, ready once listening) and launches Chromium, then runs
 * `work(browser)` and closes both however it ends; a browser that cannot start closes the server too.
 */
export async function withServedChromium(port, work) {
  const [{ serveDirectory }, { chromium }, { chromiumLaunchOptions }] = await Promise.all([
    import('../serve.mjs'), import('@playwright/test'), import('../chromium.mjs')]);
  const { server } = await serveDirectory(path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..'), { port });
  let browser;
  try {
    browser = await chromium.launch(chromiumLaunchOptions());
    return await work(browser);
  } finally {
    await browser?.close().catch(() => {});
    server.close();
  }
}
