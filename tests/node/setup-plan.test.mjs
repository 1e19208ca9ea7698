// Node tests of scripts/setup.sh --plan: on a machine where nothing is installed the plan holds every
// Debian package the README's commands need, and with everything present it is empty. Runs the real
// script with a PATH of shims and an empty file-system root, so it holds even on a machine (like CI's)
// where everything is installed already. Needs bash only.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repositoryRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

// What `npm start` and `npm test` need on a fresh Debian 12 machine, by Debian package name.
const NEEDED = ['emscripten', 'libglm-dev', 'chromium', 'fonts-dejavu-core', 'cmake', 'g++', 'make',
  'libgtest-dev', 'firefox-esr', 'xvfb', 'webkit2gtk-driver', 'libwebkit2gtk-4.1-0', 'speech-dispatcher', 'espeak-ng',
  'nodejs', 'npm'];
// What `npm run bench` adds (setup.sh --bench): the tools publish-rate.mjs measures conecurl publish against.
const BENCH_NEEDED = ['poppler-utils', 'mupdf-tools', 'webp'];
const BENCH_COMMANDS = ['pdftoppm', 'mutool', 'cwebp'];
const COMMANDS = ['em++', 'chromium', 'cmake', 'g++', 'make', 'firefox-esr', 'Xvfb', 'WebKitWebDriver',
  'speech-dispatcher', 'espeak-ng', 'node', 'npm'];
const FILES = ['usr/include/glm/glm.hpp', 'usr/include/gtest/gtest.h', 'usr/share/fonts/truetype/dejavu/DejaVuSans.ttf',
  'usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser'];

function writeExecutable(file, body) {
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, `#!/bin/bash\n${body}\n`, { mode: 0o755 });
}

/**
 * A throw-away project holding a copy of setup.sh and the lock file, a bin/ of shims that will be
 * the whole PATH, and an empty root/ for headers and fonts. `installed` says what is present.
 */
function sandbox({ installed }) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-setup-'));
  fs.mkdirSync(path.join(dir, 'scripts'));
  fs.copyFileSync(path.join(repositoryRoot, 'scripts/setup.sh'), path.join(dir, 'scripts/setup.sh'));
  fs.copyFileSync(path.join(repositoryRoot, 'package-lock.json'), path.join(dir, 'package-lock.json'));
  const bin = path.join(dir, 'bin');
  // dpkg-query as Debian's answers for a package it does not know, or one that is installed.
  writeExecutable(path.join(bin, 'dpkg-query'), installed
    ? 'echo -n "install ok installed"'
    : 'echo "dpkg-query: no packages found matching ${@: -1}" >&2; exit 1');
  if (installed) {
    for (const name of [...COMMANDS, ...BENCH_COMMANDS]) writeExecutable(path.join(bin, name), 'exit 0');
    for (const file of FILES) {
      fs.mkdirSync(path.join(dir, 'root', path.dirname(file)), { recursive: true });
      fs.writeFileSync(path.join(dir, 'root', file), '');
    }
    fs.mkdirSync(path.join(dir, 'node_modules'));
    const lock = path.join(dir, 'node_modules/.package-lock.json');
    fs.writeFileSync(lock, '{}');
    const later = new Date(Date.now() + 60_000);
    fs.utimesSync(lock, later, later);
  }
  fs.mkdirSync(path.join(dir, 'root'), { recursive: true });
  return { dir, bin, root: path.join(dir, 'root') };
}

/** Runs the copied setup.sh --plan with only the shims on PATH; returns its steps, one per line. */
function plan(box, extraEnv = {}, extraArgs = []) {
  const env = { PATH: box.bin, HOME: box.dir, SETUP_ROOT: box.root, ...extraEnv };
  const result = spawnSync('/bin/bash', [path.join(box.dir, 'scripts/setup.sh'), '--plan', ...extraArgs], { env, encoding: 'utf8' });
  assert.equal(result.status, 0, `setup.sh --plan failed: ${result.stderr}`);
  return result.stdout.split('\n').filter(Boolean);
}

const aptPackages = (steps) => {
  const line = steps.find((step) => step.startsWith('apt-get install '));
  return line ? line.slice('apt-get install '.length).split(' ') : [];
};

test('node: setup --plan on a machine with nothing installed lists every package the README commands need, then npm ci (needs bash)', () => {
  const box = sandbox({ installed: false });
  try {
    const steps = plan(box);
    const packages = aptPackages(steps);
    for (const name of NEEDED) assert.ok(packages.includes(name), `the plan misses ${name}: ${steps.join(' | ')}`);
    assert.deepEqual(packages.toSorted(), NEEDED.toSorted(), 'the plan installs something nobody needs');
    assert.ok(steps.includes('npm ci'), 'no npm ci in the plan');
  } finally {
    fs.rmSync(box.dir, { recursive: true, force: true });
  }
});

test('node: setup --plan --bench on a machine with nothing installed adds the benchmark\'s tools, and only with --bench (needs bash)', () => {
  const box = sandbox({ installed: false });
  try {
    assert.deepEqual(aptPackages(plan(box, {}, ['--bench'])).toSorted(), [...NEEDED, ...BENCH_NEEDED].toSorted());
    for (const name of BENCH_NEEDED) assert.ok(!aptPackages(plan(box)).includes(name), `plain setup installs the bench-only ${name}`);
  } finally {
    fs.rmSync(box.dir, { recursive: true, force: true });
  }
});

test('node: setup --plan with everything present is empty (needs bash)', () => {
  const box = sandbox({ installed: true });
  try {
    assert.deepEqual(plan(box), []);
    assert.deepEqual(plan(box, {}, ['--bench']), []);
    fs.rmSync(path.join(box.bin, 'mutool'));
    assert.deepEqual(aptPackages(plan(box, {}, ['--bench'])), ['mupdf-tools']);
    assert.deepEqual(plan(box), [], 'plain setup asks for a bench tool');
  } finally {
    fs.rmSync(box.dir, { recursive: true, force: true });
  }
});

test('node: setup --plan does not take CHROMIUM_PATH naming a missing file as an installed browser (needs bash)', () => {
  const box = sandbox({ installed: true });
  try {
    fs.rmSync(path.join(box.bin, 'chromium'));
    assert.deepEqual(aptPackages(plan(box, { CHROMIUM_PATH: '/usr/bin/chromium-that-is-not-there' })), ['chromium']);
    assert.deepEqual(aptPackages(plan(box)), ['chromium']);
    // A CHROMIUM_PATH that names a real executable is the user's own browser: nothing to install.
    writeExecutable(path.join(box.dir, 'my-chromium'), 'exit 0');
    assert.deepEqual(plan(box, { CHROMIUM_PATH: path.join(box.dir, 'my-chromium') }), []);
  } finally {
    fs.rmSync(box.dir, { recursive: true, force: true });
  }
});

test('node: the README names every package setup installs (needs nothing)', () => {
  const readme = fs.readFileSync(path.join(repositoryRoot, 'README.md'), 'utf8');
  const section = readme.slice(readme.indexOf('## Two commands'), readme.indexOf('## The demo'));
  for (const name of NEEDED) assert.ok(section.includes(`\`${name}\``), `README's "Two commands" does not name \`${name}\``);
});
