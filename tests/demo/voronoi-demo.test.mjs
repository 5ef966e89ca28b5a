// The demo's Voronoi page in headless Chromium: random sites' cells clipped to the Natural Earth
// land, a clicked site, Lloyd's relaxation, another clip, and a dropped GeoJSON; each time the
// page must show cells whose areas sum to the domain's. The demo is built into a folder of its
// own (demo.test.mjs builds demo/dist at the same time). Screenshots go to test-output/.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { build } from 'vite';
import { serveDirectory } from '../../demo/scripts/static-server.mjs';

const OUTPUT = fileURLToPath(new URL('../../test-output/', import.meta.url));
const READY_TIMEOUT = 180_000;

let server;
let context;
let page;
let outDir;
let userDataDir;
const consoleErrors = [];

before(async () => {
  outDir = mkdtempSync(join(tmpdir(), 'geocdt-voronoi-demo-'));
  await build({
    configFile: fileURLToPath(new URL('../../demo/vite.config.js', import.meta.url)),
    build: { outDir, emptyOutDir: true },
  });
  mkdirSync(OUTPUT, { recursive: true });
  const served = await serveDirectory(outDir, { port: 0 });
  server = served.server;
  userDataDir = mkdtempSync(join(tmpdir(), 'geocdt-voronoi-chromium-'));
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'],
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on('console', (m) => m.type() === 'error' && consoleErrors.push(m.text()));
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  await page.goto(`${served.url}voronoi.html`);
  await readyWith((s) => s?.sites > 0);
});

after(async () => {
  await context?.close();
  server?.close();
  for (const dir of [userDataDir, outDir]) if (dir) rmSync(dir, { recursive: true, force: true });
});

// Waits until the page is ready (or failed) with statistics that pass `check`.
async function readyWith(check) {
  await page.waitForFunction(() => ['ready', 'failed', 'error'].includes(document.body.dataset
    .status) && window.geocdtVoronoiDemo?.stats !== null, null, { timeout: READY_TIMEOUT });
  const s = await stats();
  assert.equal(s.status, 'ready', s.error ?? 'the page did not get ready');
  assert.ok(check(s.raw), JSON.stringify(s.raw));
  return s;
}

async function act(action) {
  await page.evaluate(() => { document.body.dataset.status = 'waiting-for-test'; });
  await action();
}

async function stats() {
  return page.evaluate(() => ({
    status: document.body.dataset.status,
    error: document.getElementById('error').hidden ? null
      : document.getElementById('error').textContent,
    raw: window.geocdtVoronoiDemo.stats,
  }));
}

// The cells tile the domain: their area is the domain's.
function tiles(s) {
  return Math.abs(s.area - s.domainArea) <= 1e-9 * s.domainArea;
}

test('random sites: cells clipped to the land', async () => {
  const { raw } = await stats();
  assert.equal(raw.sites, 1000);
  assert.ok(raw.cells > 100 && raw.cells < 1000, `cells with area: ${raw.cells}`);
  assert.ok(raw.clipped > 100 && raw.crossings > 100);
  assert.ok(tiles(raw), `area ${raw.area} against ${raw.domainArea}`);
  await page.screenshot({ path: join(OUTPUT, 'voronoi-land.png') });
});

test('a click adds a site; Lloyd relaxes; other clips', async () => {
  await act(() => page.mouse.click(700, 400));
  await readyWith((s) => s.sites === 1001 && tiles(s));
  await act(() => page.click('#relax'));
  const relaxed = await readyWith((s) => s.lloyd?.iterations === 10 && tiles(s));
  assert.ok(relaxed.raw.lloyd.movement > 0);
  await act(() => page.selectOption('#clip', 'hull'));
  await readyWith((s) => s.cells === s.sites && tiles(s));
  await act(() => page.selectOption('#clip', 'box'));
  await readyWith((s) => s.clipped > 0 && tiles(s));
  await page.screenshot({ path: join(OUTPUT, 'voronoi-box.png') });
  await act(() => page.selectOption('#clip', 'rings'));
  await readyWith(tiles);
});

test('a dropped GeoJSON: its points are the sites, its polygon the domain', async () => {
  const geojson = {
    type: 'FeatureCollection',
    features: [
      { type: 'Feature', properties: {},
        geometry: { type: 'Polygon', coordinates: [[[0, 0], [20, 0], [20, 20], [0, 20], [0, 0]],
          [[5, 5], [5, 15], [15, 15], [15, 5], [5, 5]]] } },
      { type: 'Feature', properties: {},
        geometry: { type: 'MultiPoint', coordinates: [[2, 2], [18, 18], [10, 10], [40, 40]] } },
    ],
  };
  await act(() => page.setInputFiles('#file', { name: 'sites.geojson',
    mimeType: 'application/geo+json', buffer: Buffer.from(JSON.stringify(geojson)) }));
  const s = await readyWith((r) => r.sites === 4 && tiles(r));
  assert.ok(s.raw.cells >= 2 && s.raw.cells <= 3, `cells: ${s.raw.cells}`);
  assert.deepEqual(consoleErrors, []);
});
