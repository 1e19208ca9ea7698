// Shared by the `conecurl publish` Node tests: runs the real command (node cli/conecurl.mjs publish …) in a
// child process, in temp folders.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
/** A published index.html's <script> of the reader's entry chunk (a hashed name): a page imports it for `book`. */
export const READER_ENTRY = 'script[type="module"][src^="conecurl/"]';

/** Runs `conecurl publish ...args`; resolves { code, stdout, stderr } (code 'hung' if it ran past `limitMs`: a guard, not a timing). */
export function publish(args, env = {}, limitMs = 300_000) {
  return new Promise((resolve) => {
    const child = spawn(process.execPath, [path.join(root, 'cli/conecurl.mjs'), 'publish', ...args], {
      cwd: root, env: { ...process.env, ...env }, stdio: ['ignore', 'pipe', 'pipe'],
    });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (d) => { stdout += d; });
    child.stderr.on('data', (d) => { stderr += d; });
    const guard = setTimeout(() => child.kill('SIGKILL'), limitMs);
    child.on('close', (code, signal) => {
      clearTimeout(guard);
      resolve({ code: signal === 'SIGKILL' ? 'hung' : code, stdout, stderr });
    });
  });
}

/** A new temp folder for one test, removed by the returned function. */
export function tempDir(t) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-publish-'));
  t.after(() => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

export const readJson = (file) => JSON.parse(fs.readFileSync(file, 'utf8'));

/** The test PDF (tests/fixtures/document-pdf.mjs) written to DIR/book.pdf; its path. */
export async function writeTestPdf(dir) {
  const { makeDocumentPdf } = await import('../fixtures/document-pdf.mjs');
  const pdf = path.join(dir, 'book.pdf');
  fs.writeFileSync(pdf, Buffer.from((await makeDocumentPdf()).base64, 'base64'));
  return pdf;
}

/** A publish run that failed as a CLI should: exit `code`, one line on stderr naming `file` and matching `what`, no stack. */
export function assertOneLine(run, code, file, what) {
  assert.equal(run.code, code, `exit code; stderr: ${run.stderr}`);
  const lines = run.stderr.trim().split('\n');
  assert.equal(lines.length, 1, `one line: ${run.stderr}`);
  if (file) assert.ok(lines[0].includes(file), `names ${file}: ${lines[0]}`);
  assert.match(lines[0], what);
  assert.doesNotMatch(run.stderr, /\n\s+at /, 'no stack trace');
}
