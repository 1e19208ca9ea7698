// Node tests of the npm package as users get it: what `npm pack` puts in the tarball, that the exports
// map points at packed files, and that TypeScript consumers typecheck against the packed typings.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { copyTemplate, installTarball, packDryRun, packTo, repositoryRoot } from '../consumers/package-tools.mjs';

const manifest = JSON.parse(fs.readFileSync(path.join(repositoryRoot, 'package.json'), 'utf8'));
let dryRun = null;
const packed = () => (dryRun ??= packDryRun());  // one `npm pack --dry-run` for the tests that read it

/** Every file a user needs, and nothing else: the engine and its constants, the web/src modules and typings, the reader page, the command, docs. */
function allowedFiles() {
  const sources = fs.readdirSync(path.join(repositoryRoot, 'web/src'), { recursive: true })
    .filter((name) => name.endsWith('.js') || name.endsWith('.d.ts'))
    .map((name) => `web/src/${name}`);
  // The `conecurl` command (bin): cli/conecurl.mjs and its subcommands' modules.
  const cli = fs.readdirSync(path.join(repositoryRoot, 'cli'), { recursive: true })
    .filter((name) => name.endsWith('.mjs'))
    .map((name) => `cli/${name}`);
  // The reader page (web/reader/): a published site's, and reader.html#file= for a PDF at run time.
  const reader = fs.readdirSync(path.join(repositoryRoot, 'web/reader')).map((name) => `web/reader/${name}`);
  // The bundles scripts/build-bundles.mjs makes: the published reader and the CDN module with its wasm.
  const bundles = ['dist/reader', 'dist/cdn'].flatMap((dir) => fs.readdirSync(path.join(repositoryRoot, dir)).map((name) => `${dir}/${name}`));
  return ['package.json', 'README.md', 'LICENSE', 'dist/conecurl-engine.mjs', 'dist/conecurl-engine.wasm',
    'dist/engine-constants.js', ...sources, ...cli, ...reader, ...bundles].sort();
}

/** Every string an exports entry points at, with the condition path that leads to it. */
function exportTargets(entry, where) {
  if (typeof entry === 'string') return [{ where, target: entry }];
  return Object.entries(entry).flatMap(([condition, value]) => exportTargets(value, `${where} ${condition}`));
}

test('node: npm pack holds exactly the engine, the bundles, the web/src modules and typings, the reader page, the cli/ command, README, LICENSE and package.json (needs the wasm built)', () => {
  const files = packed().files.map((file) => file.path).sort();
  assert.deepEqual(files, allowedFiles());
  for (const file of files) assert.doesNotMatch(file, /(^|\/)(tests?|demo|cpp|shaders|scripts)\//);
  const wasm = packed().files.find((file) => file.path === 'dist/conecurl-engine.wasm');
  assert.ok(wasm.size > 10_000, `the packed wasm is ${wasm.size} bytes: not a real build`);
});

test('node: every exports target is in the tarball, and each entry lists its types before its code', () => {
  const files = new Set(packed().files.map((file) => file.path));
  const targets = Object.entries(manifest.exports).flatMap(([subpath, entry]) => exportTargets(entry, subpath));
  assert.ok(targets.length >= 7, 'exports map unexpectedly small');
  for (const { where, target } of targets) {
    assert.ok(target.startsWith('./'), `${where}: '${target}' must start with ./`);
    assert.ok(files.has(target.slice(2)), `${where}: '${target}' is not in the tarball`);
  }
  for (const subpath of ['.', './element', './engine', './cdn']) {
    const conditions = Object.keys(manifest.exports[subpath]);
    assert.deepEqual(conditions, ['types', 'default'], `exports['${subpath}'] conditions`);
  }
  assert.ok(files.has(manifest.types.slice(2)), 'the top-level types field points at a packed file');
  // element.js and the CDN module define the custom element on import: bundlers must not drop them as unused.
  assert.deepEqual(manifest.sideEffects, [manifest.exports['./element'].default, manifest.exports['./cdn'].default]);
});

test('node: every relative import in the packed modules and typings resolves to a packed file', () => {
  const files = new Set(packed().files.map((file) => file.path));
  const modules = [...files].filter((file) => /\.(m?js|d\.ts)$/.test(file) && file.startsWith('web/'));
  let imports = 0;
  for (const file of modules) {
    const text = fs.readFileSync(path.join(repositoryRoot, file), 'utf8');
    for (const [, specifier] of text.matchAll(/(?:from|import)\s*\(?\s*'(\.{1,2}\/[^']+)'/g)) {
      const target = path.posix.normalize(path.posix.join(path.posix.dirname(file), specifier));
      const typingsTwin = target.replace(/\.js$/, '.d.ts');  // `from './x.js'` in a .d.ts means x.d.ts
      assert.ok(files.has(target) || (file.endsWith('.d.ts') && files.has(typingsTwin)),
        `${file} imports '${specifier}', which is not packed`);
      imports++;
    }
  }
  assert.ok(imports >= 10, `only ${imports} relative imports found: the pattern missed them`);
});

// Installs the packed package into a copy of tests/consumers/<template> made in a folder under
// `parent`, and runs strict tsc on it with bundler and node16 resolution.
function typecheckConsumer(template, parent) {
  const work = fs.mkdtempSync(path.join(parent, `conecurl-${template}-`));
  try {
    const app = copyTemplate(template, path.join(work, 'app'));
    installTarball(packTo(work), app);
    const tsc = path.join(repositoryRoot, 'node_modules/.bin/tsc');
    for (const config of ['tsconfig.bundler.json', 'tsconfig.node16.json']) {
      try {
        execFileSync(tsc, ['-p', config, '--noEmit', '--strict'], { cwd: app, encoding: 'utf8', stdio: 'pipe' });
      } catch (error) {
        assert.fail(`tsc -p ${config} failed:\n${error.stdout}${error.stderr}`);
      }
    }
  } finally {
    fs.rmSync(work, { recursive: true, force: true });
  }
}

test('node: strict TypeScript (bundler and node16 resolution) typechecks a consumer of the packed conecurl, conecurl/element and conecurl/viewer', () => {
  typecheckConsumer('typescript', os.tmpdir());
});

test('node: strict TypeScript (bundler and node16 resolution) typechecks a consumer of the packed conecurl/react and conecurl/vue, with React\'s and Vue\'s own types', () => {
  // Inside the repository (build/ is ignored), so that react, @types/react and vue resolve from its node_modules.
  fs.mkdirSync(path.join(repositoryRoot, 'build'), { recursive: true });
  typecheckConsumer('typescript-frameworks', path.join(repositoryRoot, 'build'));
});
