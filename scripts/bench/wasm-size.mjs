// Where the bytes of a .wasm go: section sizes, and code size per function and per C++ namespace
// from the name section (build with --profiling-funcs to have one). A twiggy-style breakdown without
// extra tools. Usage: node scripts/bench/wasm-size.mjs file.wasm [--top 40]
import fs from 'node:fs';
import zlib from 'node:zlib';

const SECTION_NAMES = ['custom', 'type', 'import', 'function', 'table', 'memory', 'global', 'export',
  'start', 'element', 'code', 'data', 'datacount'];

function readU32(bytes, offset) {
  let result = 0;
  let shift = 0;
  for (;;) {
    const byte = bytes[offset++];
    result += (byte & 0x7f) * 2 ** shift;
    shift += 7;
    if (!(byte & 0x80)) return [result, offset];
  }
}

function readName(bytes, offset) {
  const [length, start] = readU32(bytes, offset);
  return [Buffer.from(bytes.subarray(start, start + length)).toString('utf8'), start + length];
}

/** Parses the module's sections, function body sizes and function names. */
export function analyzeWasm(bytes) {
  if (bytes.readUInt32LE(0) !== 0x6d736100) throw new Error('wasm-size: not a wasm module (bad magic)');
  const sections = [];
  const bodies = [];       // [size] per defined function, in order
  const names = new Map(); // function index -> name
  let importedFunctions = 0;
  let offset = 8;
  while (offset < bytes.length) {
    const id = bytes[offset];
    const [size, start] = readU32(bytes, offset + 1);
    const end = start + size;
    let label = SECTION_NAMES[id] || `unknown(${id})`;
    if (id === 0) {
      const [name] = readName(bytes, start);
      label = `custom "${name}"`;
      if (name === 'name') readNameSection(bytes, start, end, names);
    } else if (id === 2) {
      let [count, p] = readU32(bytes, start);
      for (let i = 0; i < count; i++) {
        [, p] = readName(bytes, p);
        [, p] = readName(bytes, p);
        const kind = bytes[p++];
        if (kind === 0) { importedFunctions++; [, p] = readU32(bytes, p); }
        else if (kind === 1) { p += 1; const flags = bytes[p++]; [, p] = readU32(bytes, p); if (flags & 1) [, p] = readU32(bytes, p); }
        else if (kind === 2) { const flags = bytes[p++]; [, p] = readU32(bytes, p); if (flags & 1) [, p] = readU32(bytes, p); }
        else if (kind === 3) p += 2;
        else throw new Error(`wasm-size: unknown import kind ${kind}`);
      }
    } else if (id === 10) {
      let [count, p] = readU32(bytes, start);
      for (let i = 0; i < count; i++) {
        const [bodySize, bodyStart] = readU32(bytes, p);
        bodies.push(bodySize + (bodyStart - p));
        p = bodyStart + bodySize;
      }
    }
    sections.push({ id, label, bytes: end - offset });
    offset = end;
  }
  const functions = bodies.map((size, i) => ({
    index: importedFunctions + i,
    name: names.get(importedFunctions + i) || `func[${importedFunctions + i}]`,
    bytes: size,
  }));
  return { total: bytes.length, sections, functions };
}

function readNameSection(bytes, start, end, names) {
  let [, p] = readName(bytes, start);
  while (p < end) {
    const kind = bytes[p];
    const [size, contentStart] = readU32(bytes, p + 1);
    if (kind === 1) {
      let [count, q] = readU32(bytes, contentStart);
      for (let i = 0; i < count; i++) {
        let index;
        let name;
        [index, q] = readU32(bytes, q);
        [name, q] = readName(bytes, q);
        names.set(index, name);
      }
    }
    p = contentStart + size;
  }
}

/** A coarse owner for a (demangled) function name: our code, Embind, libc++, libc, malloc... */
export function ownerOf(name) {
  if (/conecurl|embind_init|EMSCRIPTEN_BINDINGS|js_values/.test(name)) {
    return /emscripten::|embind/i.test(name) ? 'conecurl bindings (Embind glue)' : 'conecurl';
  }
  if (/emscripten::|_embind_|embind/.test(name)) return 'Embind (emscripten::)';
  if (/std::|__cxxabiv1|__cxa_|operator new|operator delete/.test(name)) return 'libc++/libc++abi';
  if (/malloc|free|emmalloc|sbrk/.test(name)) return 'allocator';
  if (/glm::/.test(name)) return 'glm';
  if (/^(mem|str|__|f?printf|v?sn?printf|fmt|pop_arg|pad|out|wctomb|frexp|sin|cos|tan|asin|acos|atan|exp|log|pow|sqrt|scalbn)/.test(name)) return 'libc/libm';
  if (/^func\[/.test(name)) return '(unnamed)';
  return 'other';
}

function kb(bytes) { return `${(bytes / 1024).toFixed(1)} KB`; }

if (import.meta.url === `file://${process.argv[1]}`) {
  const file = process.argv[2];
  if (!file) {
    console.error('usage: node scripts/bench/wasm-size.mjs file.wasm [--top N]');
    process.exit(2);
  }
  const topIndex = process.argv.indexOf('--top');
  const top = topIndex > 0 ? Number(process.argv[topIndex + 1]) : 40;
  const bytes = fs.readFileSync(file);
  const { total, sections, functions } = analyzeWasm(bytes);
  console.log(`${file}: ${kb(total)} raw, ${kb(zlib.gzipSync(bytes, { level: 9 }).length)} gzip -9`);
  console.log('\nsections:');
  for (const s of sections) console.log(`  ${s.label.padEnd(28)} ${String(s.bytes).padStart(8)}`);
  const byOwner = new Map();
  for (const f of functions) byOwner.set(ownerOf(f.name), (byOwner.get(ownerOf(f.name)) || 0) + f.bytes);
  console.log(`\ncode by owner (${functions.length} functions):`);
  for (const [owner, size] of [...byOwner].sort((a, b) => b[1] - a[1])) {
    console.log(`  ${owner.padEnd(34)} ${String(size).padStart(8)}`);
  }
  console.log(`\nlargest ${top} functions:`);
  for (const f of [...functions].sort((a, b) => b.bytes - a.bytes).slice(0, top)) {
    console.log(`  ${String(f.bytes).padStart(6)}  ${f.name.slice(0, 150)}`);
  }
}
