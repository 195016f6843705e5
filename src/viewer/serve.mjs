// serve.mjs - serve a folder (the repository, by default) on 127.0.0.1,
// for the viewer page: browsers load ES modules (three.js) only over
// HTTP.  node src/viewer/serve.mjs [ROOT] [PORT], then open the URL it prints
// and drop a .glb on the page, or add ?glb=PATH of one under ROOT.
// Read-only, and nothing outside ROOT.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript',
  '.mjs': 'text/javascript', '.json': 'application/json',
  '.glb': 'model/gltf-binary', '.png': 'image/png', '.svg': 'image/svg+xml',
  '.css': 'text/css', '.wasm': 'application/wasm',
  '.cfg': 'text/plain; charset=utf-8',
};

// A server of root's files; resolves to it once it listens.
export function serve(root, port = 0) {
  root = path.resolve(root);
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://127.0.0.1');
    const file = path.join(root, decodeURIComponent(url.pathname));
    if (req.method !== 'GET' || !file.startsWith(root + path.sep)) {
      res.writeHead(403).end();
      return;
    }
    fs.stat(file, (err, st) => {
      if (err || !st.isFile()) {
        res.writeHead(404).end();
        return;
      }
      res.writeHead(200, { 'Content-Type': types[path.extname(file)] ||
        'application/octet-stream', 'Content-Length': st.size,
        'Cache-Control': 'no-store' });
      fs.createReadStream(file).pipe(res);
    });
  });
  return new Promise((resolve, reject) => {
    server.on('error', reject);
    server.listen(port, '127.0.0.1', () => resolve(server));
  });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const here = path.dirname(fileURLToPath(import.meta.url));
  const root = process.argv[2] || path.join(here, '..', '..');
  const server = await serve(root, Number(process.argv[3] || 8035));
  const page = path.relative(path.resolve(root), path.join(here, 'viewer.html'));
  console.log(`http://127.0.0.1:${server.address().port}/${page.split(path.sep).join('/')}`);
}
