// The package users get: npm pack, install the tarball into an empty folder, import it from
// Node; then bundle a page with Vite and run it in headless Chromium, worker included.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import {
  copyFileSync, existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync,
} from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import * as geocdt from 'geocdt';
import { checkProgressEvents } from './support/progress.js';
import { runWarmUp } from '../../web/warm-up.js';

const root = fileURLToPath(new URL('../../', import.meta.url));
const here = fileURLToPath(new URL('./pack/', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'geocdt-pack-'));
after(() => rmSync(dir, { recursive: true, force: true }));

const npm = (args, cwd) => execFileSync('npm',
  [...args, '--no-audit', '--no-fund', '--loglevel=error'],
  { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });

let installed = false;

test('npm pack ships the wasm and the sources, nothing else', () => {
  assert.ok(existsSync(join(root, 'web/dist/geocdt.wasm')), 'build the wasm first: npm run build');
  const [{ filename, files }] =
    JSON.parse(npm(['pack', '--json', '--pack-destination', dir], root));
  const paths = files.map((f) => f.path);
  for (const needed of ['package.json', 'web/dist/geocdt.wasm', 'web/dist/geocdt.mjs',
    'web/dist/geocdt-threads.wasm', 'web/dist/geocdt-threads.mjs',
    'web/dist/geocdt-threads.worker.js', 'web/pthread-worker.node.js', 'web/index.node.js',
    'web/index.browser.js', 'web/index.d.ts', 'web/worker.d.ts', 'web/cli.js']) {
    assert.ok(paths.includes(needed), `${needed} is in the tarball`);
  }
  assert.ok(paths.includes('LICENSE'), 'the licence text is in the tarball');
  assert.ok(paths.every((p) => p === 'package.json' || /^(web\/|README|LICENSE)/.test(p)),
    `unexpected files: ${paths}`);

  const app = join(dir, 'app');
  execFileSync('mkdir', ['-p', app]);
  writeFileSync(join(app, 'package.json'),
    JSON.stringify({ name: 'app', private: true, type: 'module' }));
  npm(['install', join(dir, filename)], app);
  installed = true;
  // MIT asks for the licence text to travel with every copy.
  const licence = readFileSync(join(app, 'node_modules/geocdt/LICENSE'), 'utf8');
  assert.match(licence, /^MIT License\n\nCopyright \(c\) the geocdt authors\n/);
});

test('the installed package runs in Node, worker and CLI included', () => {
  assert.ok(installed);
  const app = join(dir, 'app');
  copyFileSync(join(here, 'node-check.js'), join(app, 'node-check.js'));
  const out = JSON.parse(
    execFileSync(process.execPath, ['node-check.js'], { cwd: app, encoding: 'utf8' }));
  assert.deepEqual(out, { triangles: 4, features: 1, workerTriangles: 4 });
  const bin = join(app, 'node_modules/.bin/geocdt');
  assert.match(execFileSync(bin, ['--help'], { encoding: 'utf8' }), /Usage: geocdt/);
  // The threaded build, from the installed files; the process ends by itself.
  const threads = execFileSync(process.execPath, ['--input-type=module', '-e', `
    import { init, triangulate } from 'geocdt';
    await init({ threads: 2 });
    const points = new Float64Array(2 * 100000).map((_, i) => (Math.sin(i) * 43758.5453) % 1);
    console.log(triangulate({ points }).stats.threads);`], { cwd: app, encoding: 'utf8' });
  assert.equal(threads.trim(), '2');
});

const MIME = {
  '.html': 'text/html',
  '.js': 'text/javascript',
  '.mjs': 'text/javascript',
  '.wasm': 'application/wasm',
};

// headers: more response headers (cross-origin isolation).
function serve(folder, headers = {}) {
  const server = createServer((req, res) => {
    const pathname = new URL(req.url, 'http://localhost').pathname;
    const path = join(folder, pathname.replace(/\/$/, '/index.html'));
    if (!path.startsWith(folder) || !existsSync(path)) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200,
      { 'content-type': MIME[extname(path)] ?? 'application/octet-stream', ...headers });
    res.end(readFileSync(path));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

// Serves folder (with headers) and opens it in headless Chromium until the page's #result
// is written; use({ page, text, result, workers }) runs before the browser closes. The page
// must raise no error and its result none either.
async function inChromium(folder, headers, use) {
  const server = await serve(folder, headers);
  const { chromium } = await import('playwright-core');
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
  });
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    const logged = [];  // (a 404 for the favicon among them: said only on a timeout)
    page.on('console', (m) => m.type() === 'error' && logged.push(m.text()));
    const workers = [];
    page.on('worker', (w) => workers.push(w.url()));
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    await page.waitForFunction(
      () => document.getElementById('result').textContent !== 'running', null,
      { timeout: 60_000 }).catch((e) => assert.fail(`${e.message}: ${errors} ${logged}`));
    const text = await page.textContent('#result');
    assert.deepEqual(errors, []);
    const result = JSON.parse(text.startsWith('{') ? text : JSON.stringify({ error: text }));
    assert.equal(result.error, undefined, text);
    await use({ page, text, result, workers });
  } finally {
    await browser.close();
    server.close();
  }
}

test('a Vite bundle runs in headless Chromium, with the worker', async () => {
  assert.ok(installed);
  const app = join(dir, 'app');
  for (const f of ['index.html', 'main.js']) copyFileSync(join(here, f), join(app, f));
  const { build } = await import('vite');
  await build(
    { root: app, logLevel: 'error', build: { outDir: join(app, 'dist'), target: 'es2022' } });
  const assets = readdirSync(join(app, 'dist/assets'));
  assert.ok(assets.some((f) => f.endsWith('.wasm')), `the wasm is emitted as an asset: ${assets}`);

  await inChromium(join(app, 'dist'), {}, async ({ page, text, result, workers }) => {
    assert.ok(result.triangles > 1_900, text);
    assert.equal(result.workerTriangles, result.triangles);
    assert.equal(result.transferred, true);
    assert.equal(result.located, 'face');
    // onProgress in the page and through the module Web Worker.
    checkProgressEvents(result.syncProgress);
    checkProgressEvents(result.workerProgress);
    assert.deepEqual(result.syncProgress.at(-1), { phase: 'export', fraction: 1 });
    assert.deepEqual(result.workerProgress.at(-1), { phase: 'export', fraction: 1 });
    // init()'s warm-up worker, as bundled: it runs on a compiled module it is sent and makes
    // what the same warm-up makes in Node.
    const warmUp = workers.find((url) => /warm-up/.test(url));
    assert.ok(warmUp, `init() started its warm-up worker: ${workers}`);
    // The single-threaded build's wasm (the threaded build's is emitted too).
    const wasm = `/assets/${assets.find((f) => f.endsWith('.wasm')
      && !f.startsWith('geocdt-threads-'))}`;
    const triangles = await page.evaluate(async ([url, wasmUrl]) => {
      const module = await WebAssembly.compileStreaming(fetch(wasmUrl));
      const worker = new Worker(url, { type: 'module' });
      const reply = new Promise((done, fail) => {
        worker.onmessage = (event) => done(event.data.triangles);
        worker.onerror = (event) => fail(new Error(event.message));
      });
      worker.postMessage({ module });
      return reply;
    }, [warmUp, wasm]);
    await geocdt.init({ warmUp: false });
    assert.equal(triangles, runWarmUp(geocdt));
  });
});

test('the threaded build in Chromium, on a cross-origin isolated page', async () => {
  assert.ok(installed);
  const app = join(dir, 'app', 'threads');  // under the app: its node_modules resolve
  execFileSync('mkdir', ['-p', app]);
  for (const f of ['index.html', 'main.js']) {
    copyFileSync(join(here, 'threads', f), join(app, f));
  }
  const { build } = await import('vite');
  await build(
    { root: app, logLevel: 'error', build: { outDir: join(app, 'dist'), target: 'es2022' } });
  const isolated = {
    'cross-origin-opener-policy': 'same-origin', 'cross-origin-embedder-policy': 'require-corp',
  };
  await inChromium(join(app, 'dist'), isolated, ({ text, result }) => {
    assert.equal(result.isolated, true);
    assert.equal(result.threads, 2, text);
    assert.ok(result.triangles > 2 * result.vertices - 100, text);
  });
});
