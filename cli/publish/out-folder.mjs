// The --out folder of `conecurl publish` and the ledger of what it wrote there (.conecurl-publish.json):
// it writes only into a new or empty folder or one it published before, never over a file it did not
// write, and on a re-publish removes only its own files that the new site no longer has.
import fs from 'node:fs';
import path from 'node:path';
import { inputError } from './errors.mjs';

export const LEDGER = '.conecurl-publish.json';
const TOOL = 'conecurl publish';

/** The files a previous publish recorded in `out` (relative paths), or null when it is not conecurl's. */
function readLedger(out) {
  try {
    const ledger = JSON.parse(fs.readFileSync(path.join(out, LEDGER), 'utf8'));
    return ledger?.tool === TOOL && Array.isArray(ledger.files) ? ledger.files.filter((f) => typeof f === 'string') : null;
  } catch {
    return null;
  }
}

function writeLedger(out, files) {
  fs.writeFileSync(path.join(out, LEDGER), `${JSON.stringify({ tool: TOOL, note: 'the files conecurl publish wrote here; it replaces and removes only these', files: [...files].sort() }, null, 1)}\n`);
}

/** A relative path inside `out`, or an error (a ledger naming ../ files is not followed). */
const inside = (out, relative) => {
  const full = path.resolve(out, relative);
  return full.startsWith(out + path.sep) ? full : null;
};

/**
 * Checks `out` before anything is written and claims it: `planned` are the relative paths this run
 * will write. Returns { previous } (the last run's files, [] for a new folder).
 */
export function claimOutFolder(out, planned) {
  let entries;
  try {
    entries = fs.readdirSync(out);
  } catch (error) {
    if (error.code === 'ENOTDIR') throw inputError(`--out ${out} is a file, not a folder: choose a folder name`);
    if (error.code !== 'ENOENT') throw Object.assign(inputError(`--out ${out} cannot be read (${error.code}): choose another folder`), { cause: error });
    entries = [];
  }
  const previous = entries.length === 0 ? [] : readLedger(out);
  if (previous === null) {
    throw inputError(`--out ${out} is not empty and was not written by conecurl publish: choose a new or empty folder (nothing was changed)`);
  }
  const own = new Set(previous);
  const foreign = planned.filter((file) => !own.has(file) && fs.existsSync(path.join(out, file)));
  if (foreign.length > 0) {
    throw inputError(`--out ${out} holds ${foreign[0]}, which conecurl did not write: move it away or choose another folder (nothing was changed)`);
  }
  fs.mkdirSync(out, { recursive: true });
  // Recorded before writing, so that a run cut short can still be replaced by the next one.
  writeLedger(out, new Set([...previous, ...planned]));
  return { previous };
}

/** After a run: removes the previous run's files the new one did not write, and records `written`. */
export function settleOutFolder(out, previous, written) {
  const keep = new Set(written);
  for (const file of previous) {
    const full = keep.has(file) ? null : inside(out, file);
    if (!full) continue;
    fs.rmSync(full, { force: true });
    // Folders left empty by that (book/zoom after --zoom 0), up to out itself.
    for (let dir = path.dirname(full); dir.startsWith(out + path.sep); dir = path.dirname(dir)) {
      try { fs.rmdirSync(dir); } catch { break; }
    }
  }
  writeLedger(out, keep);
}
