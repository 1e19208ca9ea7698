// The one place that says which Chromium the tests, benchmark and measurements launch and how:
// Debian's (never a downloaded one), found where it really is, with WebGL2 on SwiftShader.
import { accessSync, constants, statSync } from 'node:fs';
import { delimiter, join } from 'node:path';

export const CHROMIUM_ARGS = [
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--no-first-run',
];

/** Whether `path` is a file this process may run (the browsers' launchers check with this, not by a guess). */
export const isExecutableFile = (path) => {
  try {
    accessSync(path, constants.X_OK);
    return statSync(path).isFile();
  } catch {
    return false;
  }
};

/**
 * CHROMIUM_PATH when it names an executable file, else the first `chromium` on PATH. Throws an
 * error saying how to install it when there is none (instead of a launch failure on a guessed path).
 */
export function chromiumExecutable(env = process.env) {
  if (env.CHROMIUM_PATH) {
    if (isExecutableFile(env.CHROMIUM_PATH)) return env.CHROMIUM_PATH;
    throw new Error(`CHROMIUM_PATH=${env.CHROMIUM_PATH} is not an executable file`);
  }
  const found = findOnPath('chromium', env);
  if (found) return found;
  throw new Error('no chromium on PATH: run `bash scripts/setup.sh` (installs Debian\'s chromium) or set CHROMIUM_PATH');
}

/** The first executable `name` on env's PATH, or undefined. */
export const findOnPath = (name, env = process.env) => (env.PATH || '').split(delimiter)
  .map((dir) => dir && join(dir, name)).find((path) => path && isExecutableFile(path));

/** Options for playwright's chromium.launch(). */
export const chromiumLaunchOptions = () => ({ executablePath: chromiumExecutable(), args: CHROMIUM_ARGS });
