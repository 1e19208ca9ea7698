// A small static server for the demo and the browser tests: serves the repository read-only on
// loopback with the MIME types wasm and ES modules need. Usage: node scripts/serve.mjs [--port N]
// The consumer tests import serveDirectory() to serve a built app or an unpacked package the same way.
// No CORS headers, so a page on 127.0.0.1 reading from localhost meets a real cross-origin refusal;
// a request with the query `cors=1` gets Access-Control-Allow-Origin: * (tests' positive control).
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repositoryRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const host = '127.0.0.1';
const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.css': 'text/css', '.json': 'application/json',
  '.png': 'image/png', '.jpg': 'image/jpeg', '.svg': 'image/svg+xml', '.ico': 'image/x-icon',
  '.webp': 'image/webp', '.avif': 'image/avif', '.pdf': 'application/pdf',
};

/**
 * Serves `root` on 127.0.0.1:`port` (0: any free port). `home` is where '/' redirects, if anywhere.
 * `headHtml`, if given, goes first into every HTML page's <head> (tests put a listener there that must
 * run before the page's own scripts). Resolves with { server, url } once listening.
 */
export function serveDirectory(root, { port = 0, home = null, headHtml = '' } = {}) {
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
      res.writeHead(200, {
        'Content-Type': types[path.extname(file)] || 'application/octet-stream',
        'Cache-Control': 'no-cache',
        ...(url.searchParams.get('cors') === '1' ? { 'Access-Control-Allow-Origin': '*' } : {}),
      });
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

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const portArg = process.argv.indexOf('--port');
  const port = Number(portArg > 0 ? process.argv[portArg + 1] : process.env.PORT || 8080);
  const { url } = await serveDirectory(repositoryRoot, { port, home: '/web/demo/' });
  console.log(`conecurl demo: ${url}`);
}
