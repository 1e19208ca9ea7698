// Shared by the consumer tests (Node and browser): pack the repository as `npm publish` would, unpack
// the tarball, and write page images whose colours the tests can classify (pageColor of test-pages.js).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { pageColor } from '../browser/fixtures/test-pages.js';

export const repositoryRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

function npm(args, cwd) {
  return execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

function requireBuiltEngine() {
  for (const file of ['dist/conecurl-engine.mjs', 'dist/conecurl-engine.wasm']) {
    if (!fs.existsSync(path.join(repositoryRoot, file))) {
      throw new Error(`${file} is missing: build the wasm first (npm run build)`);
    }
  }
}

/** `npm pack --dry-run --json`: what the tarball would hold ({ files: [{ path, size }], size, ... }). */
export function packDryRun() {
  requireBuiltEngine();
  // --ignore-scripts: the tests use the wasm already built instead of running prepack's build.
  return JSON.parse(npm(['pack', '--dry-run', '--json', '--ignore-scripts'], repositoryRoot))[0];
}

/** Packs the repository into `directory`; returns the tarball's path. */
export function packTo(directory) {
  requireBuiltEngine();
  const [result] = JSON.parse(npm(['pack', '--json', '--ignore-scripts', '--pack-destination', directory], repositoryRoot));
  return path.join(directory, result.filename);
}

/** Unpacks a tarball's package/ folder into `directory` (as node_modules/<name> would hold it). */
export function unpackTo(tarball, directory) {
  fs.mkdirSync(directory, { recursive: true });
  execFileSync('tar', ['-xzf', tarball, '-C', directory, '--strip-components=1']);
  return directory;
}

/** `npm install <tarball>` into an app folder, offline: the package has no dependencies. */
export function installTarball(tarball, appDirectory) {
  npm(['install', '--offline', '--no-audit', '--no-fund', '--no-package-lock', tarball], appDirectory);
}

/** Writes page-0.svg ... page-(count-1).svg: the colour of pageColor(i), a corner marker, the number. */
export function writePageImages(directory, count) {
  fs.mkdirSync(directory, { recursive: true });
  for (let i = 0; i < count; i++) {
    const [r, g, b] = pageColor(i);
    fs.writeFileSync(path.join(directory, `page-${i}.svg`), `<svg xmlns="http://www.w3.org/2000/svg" width="320" height="400" viewBox="0 0 320 400">
  <rect width="320" height="400" fill="rgb(${r},${g},${b})"/>
  <rect x="19" y="20" width="64" height="64" fill="#111"/>
  <text x="160" y="260" font-family="DejaVu Sans, sans-serif" font-weight="bold" font-size="120" fill="#fff" text-anchor="middle">${i}</text>
</svg>
`);
  }
}

/** Copies a template folder (e.g. tests/consumers/vite-app) to `destination`. */
export function copyTemplate(name, destination) {
  fs.cpSync(path.join(repositoryRoot, 'tests/consumers', name), destination, { recursive: true });
  return destination;
}
