// The repository's own files as the Node rule tests read them (source-rules, test-rules, book-box):
// every file below a folder with one of the given endings, leaving out installed and generated folders.
import { readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';

export const root = new URL('../..', import.meta.url).pathname;
const SKIP = new Set(['node_modules', 'references', 'test-results', 'dist', 'build']);

export function filesUnder(dir, extensions) {
  const found = [];
  for (const name of readdirSync(dir)) {
    if (SKIP.has(name)) continue;
    const path = join(dir, name);
    if (statSync(path).isDirectory()) found.push(...filesUnder(path, extensions));
    else if (extensions.some((ext) => name.endsWith(ext))) found.push(path);
  }
  return found;
}
