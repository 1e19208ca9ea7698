// A small static server for the demo and the browser tests: serves the repository read-only on
// loopback with the MIME types wasm and ES modules need. Usage: node scripts/serve.mjs [--port N]
// The consumer tests import serveDirectory() to serve a built app or an unpacked package the same way.
// No CORS headers, so a page on 127.0.0.1 reading from localhost meets a real cross-origin refusal;
// a request with the query `cors=1` gets Access-Control-Allow-Origin: * (tests' positive control), and so
// does every request to a server made with `cors` (a CDN, as the consumer tests serve the package).
// With `compress` (the Lighthouse bench), text is sent brotli- or gzip-compressed and ranges are answered, as a CDN does.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';

const repositoryRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const host = '127.0.0.1';
const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json',
  '.png': 'image/png', '.jpg': 'image/jpeg', '.svg': 'image/svg+xml', '.ico': 'image/x-icon',
  '.webp': 'image/webp', '.avif': 'image/avif', '.pdf': 'application/pdf', '.webmanifest': 'application/manifest+json',
};
// What a CDN compresses (images and PDFs are compressed already), and each file's encodings, made once.
const COMPRESSIBLE = new Set(['.html', '.js', '.mjs', '.css', '.json', '.webmanifest', '.svg', '.wasm', '.txt', '.vtt']);
const ENCODERS = {
  br: (data) => zlib.brotliCompressSync(data, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } }),
  gzip: (data) => zlib.gzipSync(data, { level: 9 }),
};
const encoded = new Map();  // `${encoding} ${file} ${mtime}` -> the body

/** The encoding to send `file` in for `accept` (an Accept-Encoding header): 'br', 'gzip' or null. */
function encodingFor(file, accept = '') {
  if (!COMPRESSIBLE.has(path.extname(file))) return null;
  return ['br', 'gzip'].find((name) => new RegExp(`\\b${name}\\b`).test(accept)) ?? null;
}

/**
 * Serves `root` on 127.0.0.1:`port` (0: any free port). `home` is where '/' redirects, if anywhere.
 * `headHtml`, if given, goes first into every HTML page's <head> (tests put a listener there that must
 * run before the page's own scripts). `compress`: text files go brotli- or gzip-compressed when the browser
 * accepts it (Vary: Accept-Encoding), and a Range request gets its bytes (206), as a CDN serves a site.
 * `cors`: every response may be read from any origin (Access-Control-Allow-Origin: *), as a CDN's.
 * Resolves with { server, url } once listening.
 */
export function serveDirectory(root, { port = 0, home = null, headHtml = '', compress = false, cors = false } = {}) {
  root = path.resolve(root);
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, `http://${host}`);
    if (url.pathname === '/' && home) {
      res.writeHead(302, { Location: home });
      return res.end();
    }
    let file = path.normalize(path.join(root, decodeURIComponent(url.pathname)));
    if (file !== root && !file.startsWith(root + path.sep)) {  // no escaping the root with ../
      res.writeHead(403);
      return res.end('forbidden');
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) {
        res.writeHead(404, { 'Content-Type': 'text/plain' });
        return res.end(`not found: ${url.pathname}`);
      }
      const headers = {
        'Content-Type': types[path.extname(file)] || 'application/octet-stream',
        'Cache-Control': 'no-cache',
        ...(cors || url.searchParams.get('cors') === '1' ? { 'Access-Control-Allow-Origin': '*' } : {}),
      };
      if (compress && !headHtml) return sendCompressed(req, res, file, data, headers);
      res.writeHead(200, headers);
      const html = headHtml && path.extname(file) === '.html';
      const text = html && data.toString('utf8');
      res.end(!html ? data : /<head[^>]*>/i.test(text) ? text.replace(/<head[^>]*>/i, (head) => head + headHtml) : headHtml + text);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => resolve({ server, url: `http://${host}:${server.address().port}/` }));
  });
}

/** `data` (the whole of `file`) as a CDN sends it: the asked range of it, or compressed for the browser, or whole. */
function sendCompressed(req, res, file, data, headers) {
  const range = /^bytes=(\d*)-(\d*)$/.exec(req.headers.range ?? '');
  if (range && (range[1] || range[2])) {
    const size = data.length;
    const start = range[1] ? Number(range[1]) : Math.max(0, size - Number(range[2]));
    const end = range[1] && range[2] ? Math.min(Number(range[2]), size - 1) : size - 1;
    if (start >= size || start > end) {
      res.writeHead(416, { ...headers, 'Content-Range': `bytes */${size}` });
      return res.end();
    }
    res.writeHead(206, { ...headers, 'Accept-Ranges': 'bytes', 'Content-Range': `bytes ${start}-${end}/${size}`, 'Content-Length': end - start + 1 });
    return res.end(req.method === 'HEAD' ? undefined : data.subarray(start, end + 1));
  }
  const encoding = encodingFor(file, req.headers['accept-encoding']);
  let body = data;
  if (encoding) {
    const key = `${encoding} ${file} ${fs.statSync(file).mtimeMs}`;
    if (!encoded.has(key)) encoded.set(key, ENCODERS[encoding](data));
    body = encoded.get(key);
  }
  res.writeHead(200, {
    ...headers, 'Accept-Ranges': 'bytes', 'Content-Length': body.length,
    ...(COMPRESSIBLE.has(path.extname(file)) ? { Vary: 'Accept-Encoding' } : {}),
    ...(encoding ? { 'Content-Encoding': encoding } : {}),
  });
  return res.end(req.method === 'HEAD' ? undefined : body);
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const portArg = process.argv.indexOf('--port');
  const port = Number(portArg > 0 ? process.argv[portArg + 1] : process.env.PORT || 8080);
  const { url } = await serveDirectory(repositoryRoot, { port, home: '/web/demo/' });
  console.log(`conecurl demo: ${url}`);
}
