// Serves the walkthrough viewer for one .glb on this machine (127.0.0.1 only):
//   node scripts/viewer/serve.mjs out/room.glb [PORT]     then open the printed address.
// Also used by screenshot.mjs. Serves index.html, three.js from node_modules, and the model.
import fs from 'fs';
import http from 'http';
import path from 'path';
import { fileURLToPath } from 'url';

const here = path.dirname(fileURLToPath(import.meta.url));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.glb': 'model/gltf-binary' };

export function serve(model, port = 0) {
  const roots = { '/three/': path.join(here, 'node_modules', 'three') + '/' };
  const server = http.createServer((req, res) => {
    const url = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    let file = null;
    if (url === '/' || url === '/index.html') file = path.join(here, 'index.html');
    else if (url === '/model.glb') file = model;
    else if (url.startsWith('/three/') && !url.includes('..')) file = roots['/three/'] + url.slice(7);
    if (!file || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404);
      res.end('not found');
      return;
    }
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(port, '127.0.0.1', () => resolve(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const model = process.argv[2];
  if (!model || !fs.existsSync(model)) {
    console.error('usage: node serve.mjs FILE.glb [PORT]');
    process.exit(2);
  }
  const server = await serve(path.resolve(model), Number(process.argv[3] || 8080));
  console.log(`rayrad viewer: http://127.0.0.1:${server.address().port}/?model=model.glb (Ctrl-C stops it)`);
}
