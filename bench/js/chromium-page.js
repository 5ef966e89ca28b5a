// The benches' browser rows: a function run in a headless Chromium page that loads geocdt's
// browser entry and the peers as ES modules served from the repo (web/ and node_modules/, an
// import map naming them), with binary data at /data/NAME. The function is sent as source, so
// it must import what it uses itself; its arguments and result are JSON.
import { readFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { extname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../', import.meta.url));
const MIME = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm',
};

function serve(page, data) {
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url, 'http://x').pathname);
    let body = null, type = 'application/octet-stream';
    try {
      if (path === '/') [body, type] = [page, MIME['.html']];
      else if (path.startsWith('/data/')) body = data.get(path.slice(6)) ?? null;
      else if (path.startsWith('/web/') || path.startsWith('/node_modules/')) {
        body = readFileSync(join(root, path));
        type = MIME[extname(path)] ?? type;
      }
    } catch {
      body = null;
    }
    if (body == null) return response.writeHead(404).end();
    response.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-store' });
    return response.end(body);
  });
  return new Promise((done) => server.listen(0, '127.0.0.1', () => done(server)));
}

export const chromiumPath = () => process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';

// imports: bare specifier -> path under the repo ('geocdt' is always there); data: a Map of
// name -> Buffer. Returns what run(...args) resolves to.
export async function inChromium(run, args, { imports = {}, data = new Map() } = {}) {
  const map = JSON.stringify({ imports: { geocdt: '/web/index.browser.js', ...imports } });
  const page = `<!doctype html><script type="importmap">${map}</script><p>bench</p>`;
  const server = await serve(page, data);
  const { chromium } = await import('playwright-core');
  const browser = await chromium.launch({
    executablePath: chromiumPath(),
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
  });
  try {
    const tab = await browser.newPage();
    await tab.goto(`http://127.0.0.1:${server.address().port}/`);
    return await tab.evaluate(([source, list]) => new Function(`return (${source})`)()(...list),
      [run.toString(), args]);
  } finally {
    await browser.close();
    server.close();
  }
}
