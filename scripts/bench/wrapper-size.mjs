// What a page loads up front for a book through each entry of the package (Vite production build,
// minified, gzip -9): conecurl's Flipbook, the element, and the React and Vue components, React and Vue
// themselves not counted (the app has them anyway). Usage: node scripts/bench/wrapper-size.mjs [outDir]
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { gzipSize, upFrontFiles, viteBuild } from './bundle.mjs';

const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
const ENTRIES = {
  flipbook: `export { Flipbook } from ${JSON.stringify(path.join(root, 'web/src/book/flipbook.js'))};`,
  element: `import ${JSON.stringify(path.join(root, 'web/src/element.js'))};`,
  react: `export { Flipbook, useFlipbook } from ${JSON.stringify(path.join(root, 'web/src/react.js'))};`,
  vue: `export { Flipbook } from ${JSON.stringify(path.join(root, 'web/src/vue.js'))};`,
};
const FRAMEWORKS = ['react', 'react-dom', 'react/jsx-runtime', 'vue'];

const outDir = path.resolve(process.argv[2] || fs.mkdtempSync(path.join(os.tmpdir(), 'conecurl-wrappers-')));
const sizes = {};
for (const [name, code] of Object.entries(ENTRIES)) {
  const plugin = { name: 'entry', resolveId: (id) => (id === 'entry:' ? '\0entry' : null), load: (id) => (id === '\0entry' ? code : null) };
  const dir = path.join(outDir, name);
  const files = upFrontFiles(await viteBuild({ [name]: 'entry:' }, dir, [plugin], FRAMEWORKS));
  let js = 0;
  for (const file of files) if (file.endsWith('.js')) js += gzipSize(fs.readFileSync(path.join(dir, file)));
  sizes[name] = js;
}
for (const [name, js] of Object.entries(sizes)) {
  const over = name === 'flipbook' ? '' : ` (${((js - sizes.flipbook) / 1024).toFixed(1)} KB over Flipbook)`;
  console.log(`${name.padEnd(9)} JS up front ${(js / 1024).toFixed(1)} KB gzip -9${over}; plus the wasm`);
}
