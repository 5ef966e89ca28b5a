// The Leaflet demo in a real browser: builds demo/dist, serves it on 127.0.0.1, opens it in
// headless Chromium and checks what a user would see: the statistics, the map, the errors.
// Screenshots go to test-output/. Set GEOCDT_DEMO_NO_BUILD=1 to test an existing demo/dist.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { buildDemo, distDir } from '../../demo/scripts/build-demo.mjs';
import { serveDirectory } from '../../demo/scripts/static-server.mjs';
import { projectLonLat } from '../../demo/src/mercator.js';

const OUTPUT = fileURLToPath(new URL('../../test-output/', import.meta.url));
const READY_TIMEOUT = 180_000;

let server;
let context;
let page;
let userDataDir;
const consoleErrors = [];

before(async () => {
  if (!process.env.GEOCDT_DEMO_NO_BUILD) await buildDemo();
  mkdirSync(OUTPUT, { recursive: true });
  const served = await serveDirectory(distDir, { port: 0 });
  server = served.server;
  userDataDir = mkdtempSync(join(tmpdir(), 'geocdt-demo-chromium-'));
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run',
    ],
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on('console', (m) => m.type() === 'error' && consoleErrors.push(m.text()));
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
  const started = Date.now();
  await page.goto(served.url);
  await waitForStatus(['ready', 'failed']);
  console.log(`# page load to first triangulation drawn: ${Date.now() - started} ms`);
});

after(async () => {
  await context?.close();
  server?.close();
  if (userDataDir) rmSync(userDataDir, { recursive: true, force: true });
});

async function waitForStatus(statuses, timeout = READY_TIMEOUT) {
  await page.waitForFunction((s) => s.includes(document.body.dataset.status), statuses,
    { timeout });
}

// Waits until the page has handled the change that `action` starts.
async function settle(action, statuses = ['ready']) {
  await page.evaluate(() => { document.body.dataset.status = 'waiting-for-test'; });
  await action();
  await waitForStatus(statuses.concat('failed'));
}

async function readStats() {
  return page.evaluate(() => {
    const number = (id) => Number(document.getElementById(id).textContent.replace(/[^\d.]/g, ''));
    const errorBox = document.getElementById('error');
    return {
      status: document.body.dataset.status,
      points: number('stat-points'),
      constraints: number('stat-constraints'),
      crossings: number('stat-crossings'),
      vertices: number('stat-vertices'),
      triangles: number('stat-triangles'),
      inside: number('stat-inside'),
      triangulateMs: number('stat-triangulate-ms'),
      totalMs: number('stat-total-ms'),
      renderer: document.getElementById('stat-renderer').textContent,
      error: errorBox.hidden ? null : errorBox.textContent,
      raw: window.geocdtDemo.stats,
    };
  });
}

// Records the time between painted frames, in the page.
function startFrameLog() {
  const log = { gaps: [], stop: false };
  window.frameLog = log;
  let last = performance.now();
  const tick = (t) => {
    log.gaps.push(t - last);
    last = t;
    if (!log.stop) requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}

function stopFrameLog() {
  window.frameLog.stop = true;
  return window.frameLog.gaps;
}

async function dropFile(name, text) {
  const buffer = Buffer.from(text);
  await page.setInputFiles('#file', { name, mimeType: 'application/geo+json', buffer });
}

test('the bundled Natural Earth dataset is triangulated and drawn', async () => {
  const s = await readStats();
  console.log('# world-50m:', JSON.stringify(s.raw));
  assert.equal(s.status, 'ready', s.error ?? 'the page did not get ready');
  assert.equal(s.error, null);
  assert.ok(s.triangles > 100_000, `triangles: ${s.triangles}`);
  assert.ok(s.constraints > 100_000, `constraints: ${s.constraints}`);
  assert.ok(s.inside > 0 && s.inside < s.triangles, `inside: ${s.inside} of ${s.triangles}`);
  assert.ok(s.vertices > 0 && s.vertices <= s.points + s.crossings, `vertices: ${s.vertices}`);
  assert.ok(s.triangulateMs > 0 && s.totalMs >= s.triangulateMs);
  assert.match(s.renderer, /^WebGL/);
  // The server isolates the page: the worker loads the threaded build, and the points of the
  // dataset (over 100,000) go in strips on every core.
  assert.equal(await page.evaluate(() => globalThis.crossOriginIsolated), true);
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  assert.equal(s.raw.threads, Math.min(cores, 8), `threads: ${s.raw.threads}`);
  assert.deepEqual(consoleErrors, []);
  await page.screenshot({ path: join(OUTPUT, 'demo-world-50m.png') });
});

test('the worker projects exactly as Leaflet\'s EPSG3857', async () => {
  const lonLats = [[0, 0], [10, 45], [-73.98, 40.75], [179.9, -85.2], [-180, 89]];
  const leaflet = await page.evaluate((ll) => {
    const crs = window.geocdtDemo.map.options.crs;
    return ll.map(([lng, lat]) => { const p = crs.project({ lat, lng }); return [p.x, p.y]; });
  }, lonLats);
  const ours = projectLonLat(lonLats.flat());
  leaflet.forEach(([x, y], i) => {
    const close = Math.abs(ours[2 * i] - x) < 1e-6 && Math.abs(ours[2 * i + 1] - y) < 1e-6;
    assert.ok(close, `at ${lonLats[i]}`);
  });
});

// A square with a square hole, two lines crossing once inside it, three loose points.
const SQUARE = {
  type: 'FeatureCollection',
  features: [
    { type: 'Feature', properties: {}, geometry: { type: 'Polygon', coordinates: [
      [[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]],
      [[6, 6], [6, 8], [8, 8], [8, 6], [6, 6]],
    ] } },
    { type: 'Feature', properties: {}, geometry: { type: 'MultiLineString', coordinates: [
      [[1, 1], [5, 5]], [[1, 5], [5, 1]],
    ] } },
    { type: 'Feature', properties: {}, geometry: {
      type: 'MultiPoint', coordinates: [[2, 8], [8, 2], [4, 4.5]],
    } },
  ],
};

test('a GeoJSON file dropped in is triangulated with its constraints and hole', async () => {
  await settle(() => dropFile('square.geojson', JSON.stringify(SQUARE)));
  const s = await readStats();
  assert.equal(s.status, 'ready', s.error);
  assert.equal(s.points, 3 + 5 + 5 + 2 + 2);
  assert.equal(s.constraints, 4 + 4 + 1 + 1);
  assert.equal(s.crossings, 1);
  assert.equal(s.vertices, 3 + 4 + 4 + 4 + 1);
  // Euler: 2n - h - 2 triangles with the 4 corners on the hull; the hole takes 2 of them.
  assert.equal(s.triangles, 2 * s.vertices - 4 - 2);
  assert.equal(s.inside, s.triangles - 2);
  assert.equal(s.renderer, 'Leaflet canvas');
  const view = await page.evaluate(() => window.geocdtDemo.map.getBounds().toBBoxString());
  const [west, south, east, north] = view.split(',').map(Number);
  assert.ok(west < 0 && south < 0 && east > 10 && north > 10 && east - west < 40, `view ${view}`);
  await page.screenshot({ path: join(OUTPUT, 'demo-dropped-file.png') });
  assert.deepEqual(consoleErrors, []);
});

test('clicks add points and constraint segments through the incremental API', async () => {
  const before = await readStats();
  await page.check('input[name="mode"][value="point"]');
  const box = await page.locator('#map').boundingBox();
  const at = (dx, dy) => ({ x: box.x + box.width / 2 + dx, y: box.y + box.height / 2 + dy });
  await settle(() => page.mouse.click(at(-150, 90).x, at(-150, 90).y));
  const afterPoint = await readStats();
  assert.equal(afterPoint.vertices, before.vertices + 1);
  assert.equal(afterPoint.triangles, before.triangles + 2);
  assert.equal(afterPoint.points, before.points + 1);

  await page.check('input[name="mode"][value="line"]');
  await page.mouse.click(at(-200, -120).x, at(-200, -120).y); // the line's first vertex
  await settle(() => page.mouse.click(at(160, 130).x, at(160, 130).y));
  const afterLine = await readStats();
  assert.equal(afterLine.constraints, before.constraints + 1);
  assert.ok(afterLine.crossings > before.crossings, 'the drawn line crosses the ring and a line');
  assert.equal(afterLine.triangles, 2 * afterLine.vertices - 4 - 2);
  await page.keyboard.press('Escape');
  await page.check('input[name="mode"][value="pan"]');
  await page.screenshot({ path: join(OUTPUT, 'demo-edited.png') });
  assert.deepEqual(consoleErrors, []);
});

test('edit mode drags a vertex, then deletes the point and the line', async () => {
  const before = await readStats();
  await page.check('input[name="mode"][value="edit"]');
  const box = await page.locator('#map').boundingBox();
  const at = (dx, dy) => ({ x: box.x + box.width / 2 + dx, y: box.y + box.height / 2 + dy });
  // The point the previous test added: picked, then dragged (the mesh follows live).
  await page.mouse.click(at(-150, 90).x, at(-150, 90).y);
  await page.waitForFunction(() => !document.getElementById('delete-point').disabled);
  await settle(async () => {
    await page.mouse.move(at(-150, 90).x, at(-150, 90).y);
    await page.mouse.down();
    await page.mouse.move(at(-120, 60).x, at(-120, 60).y, { steps: 5 });
    await page.mouse.up();
  });
  const moved = await readStats();
  assert.equal(moved.status, 'ready', moved.error);
  assert.equal(moved.vertices, before.vertices);
  assert.equal(moved.triangles, 2 * moved.vertices - 4 - 2);
  await settle(() => page.click('#delete-point'));
  const deleted = await readStats();
  assert.equal(deleted.vertices, before.vertices - 1);
  assert.equal(deleted.triangles, before.triangles - 2);
  // The drawn line's first vertex: its line goes, with the crossings it made.
  await page.mouse.click(at(-200, -120).x, at(-200, -120).y);
  await page.waitForFunction(() => !document.getElementById('delete-lines').disabled);
  await settle(() => page.click('#delete-lines'));
  const lineGone = await readStats();
  assert.equal(lineGone.status, 'ready', lineGone.error);
  assert.ok(lineGone.vertices < deleted.vertices - 2, 'its ends and crossings went');
  assert.equal(lineGone.triangles, 2 * lineGone.vertices - 4 - 2);
  await page.check('input[name="mode"][value="pan"]');
  await page.screenshot({ path: join(OUTPUT, 'demo-vertex-editing.png') });
  assert.deepEqual(consoleErrors, []);
});

// Heights on a grid of points and on a ring: the surface view colours the triangles.
function hill() {
  const coordinates = [];
  for (let i = 0; i <= 12; i++) {
    for (let j = 0; j <= 12; j++) coordinates.push([i, j, 100 * Math.sin(i / 4) + 10 * j]);
  }
  const ring = [[3.5, 3.5, 500], [9.5, 3.5, 500], [9.5, 9.5, 700], [3.5, 9.5, 700],
    [3.5, 3.5, 500]];
  return { type: 'FeatureCollection', features: [
    { type: 'Feature', properties: {}, geometry: { type: 'MultiPoint', coordinates } },
    { type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: ring } },
  ] };
}

test('a GeoJSON with z gets the surface view', async () => {
  await settle(() => dropFile('hill.geojson', JSON.stringify(hill())));
  const s = await readStats();
  assert.equal(s.status, 'ready', s.error);
  assert.equal(await page.isDisabled('#show-surface'), false);
  assert.match(await page.textContent('#surface-range'), /\(0 to 7\d\d/);
  await page.check('#show-surface');
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(resolve)));
  await page.screenshot({ path: join(OUTPUT, 'demo-surface.png') });
  await settle(() => dropFile('square.geojson', JSON.stringify(SQUARE)));
  assert.equal(await page.isDisabled('#show-surface'), true, 'no z, no surface');
  assert.equal(await page.isChecked('input[name="show"][value="all"]'), true);
  assert.deepEqual(consoleErrors, []);
});

// The panel's minimum angle: the loaded input triangulated again and refined.
async function setMinAngle(degrees) {
  await settle(() => page.$eval('#min-angle', (input, value) => {
    input.value = String(value);
    input.dispatchEvent(new Event('input', { bubbles: true }));
    input.dispatchEvent(new Event('change', { bubbles: true }));
  }, degrees));
}

test('the minimum-angle slider refines the mesh and shows Steiner points and angles', async () => {
  await settle(() => dropFile('square.geojson', JSON.stringify(SQUARE)));
  const plain = await readStats();
  assert.equal(await page.textContent('#stat-steiner'), '–');
  await setMinAngle(28);
  const refined = await readStats();
  assert.equal(refined.status, 'ready', refined.error);
  assert.equal(await page.textContent('#min-angle-value'), '28°');
  const steiner = Number((await page.textContent('#stat-steiner')).replace(/[^\d]/g, ''));
  assert.ok(steiner > 0, 'Steiner points were added');
  assert.equal(refined.vertices, plain.vertices + steiner);
  assert.equal(refined.points, plain.points, 'the input is the same');
  // Every angle meets 28 degrees unless the panel owns up to triangles left below it.
  const angle = await page.textContent('#stat-min-angle');
  const smallest = Number(angle.match(/^([\d.]+)°/)[1]);
  assert.ok(smallest >= 28 - 0.05 || /below/.test(angle), angle);
  assert.equal(refined.raw.refine.steinerPoints, steiner);
  await page.screenshot({ path: join(OUTPUT, 'demo-refined.png') });
  // Off again: the plain triangulation comes back.
  await setMinAngle(0);
  const again = await readStats();
  assert.equal(again.vertices, plain.vertices);
  assert.equal(await page.textContent('#stat-steiner'), '–');
  assert.equal(await page.textContent('#min-angle-value'), 'off');
  assert.deepEqual(consoleErrors, []);
});

test('bad files are reported on the page, and the map keeps the last good mesh', async () => {
  const before = await readStats();
  const broken = '{"type": "FeatureCollection", "features": [';
  await settle(() => dropFile('broken.geojson', broken), ['error']);
  let s = await readStats();
  assert.match(s.error, /broken\.geojson: not valid JSON/);
  assert.equal(s.triangles, before.triangles);

  const badPosition = {
    type: 'Feature', geometry: { type: 'LineString', coordinates: [[0, 0], ['a', 1]] },
  };
  await settle(() => dropFile('bad.geojson', JSON.stringify(badPosition)), ['error']);
  s = await readStats();
  assert.match(s.error, /a position is not two finite numbers/);

  const projected = { type: 'Point', coordinates: [500000, 4649776] };
  await settle(() => dropFile('utm.geojson', JSON.stringify(projected)), ['error']);
  s = await readStats();
  assert.match(s.error, /is not lon\/lat in degrees/);
  await page.screenshot({ path: join(OUTPUT, 'demo-error.png') });
  consoleErrors.length = 0; // the failed loads are expected to leave nothing in the console
});

test('an input over the demo\'s size limit is refused with a message', async () => {
  const before = await readStats();
  // 3,000,001 points: one more than the demo accepts (a short file: all the same point).
  const text = `{"type":"MultiPoint","coordinates":[${'[0,0],'.repeat(3_000_000)}[0,0]]}`;
  await settle(() => dropFile('huge.geojson', text), ['error']);
  const s = await readStats();
  assert.match(s.error, /huge\.geojson: too big for the demo: more than 3,000,000 points/);
  assert.equal(s.triangles, before.triangles);
  consoleErrors.length = 0;
});

test('a failing worker (here: the wasm cannot be fetched) is reported on the page', async () => {
  const broken = await context.newPage();
  const errors = [];
  broken.on('pageerror', (e) => errors.push(String(e)));
  await broken.route('**/*.wasm', (route) => route.abort());
  await broken.goto(page.url());
  await broken.waitForFunction(() => document.body.dataset.status === 'failed', null,
    { timeout: 60_000 });
  const message = await broken.locator('#error').textContent();
  assert.match(message, /the triangulation (failed|worker crashed)/);
  assert.ok(await broken.locator('#error').isVisible());
  assert.deepEqual(errors, [], 'no uncaught exception in the page');
  await broken.screenshot({ path: join(OUTPUT, 'demo-worker-failure.png') });
  await broken.close();
});

test('Natural Earth 10m (500k+ triangles) loads with WebGL and stays pannable', async () => {
  // Frames of the page while the worker triangulates: the map must keep painting.
  await page.evaluate(startFrameLog);
  await settle(() => page.selectOption('#dataset', 'world-10m'));
  const s = await readStats();
  const gaps = await page.evaluate(stopFrameLog);
  console.log('# world-10m:', JSON.stringify(s.raw));
  const longestGap = Math.round(Math.max(...gaps));
  console.log(`# frames while loading 10m: ${gaps.length}, longest gap ${longestGap} ms`);
  assert.equal(s.status, 'ready', s.error);
  assert.ok(s.triangles > 500_000, `triangles: ${s.triangles}`);
  // The worker triangulates off the main thread: the page kept painting meanwhile.
  const loadSeconds = gaps.reduce((a, b) => a + b, 0) / 1000;
  assert.ok(gaps.length > 10 * loadSeconds,
    `${gaps.length} frames in ${loadSeconds.toFixed(1)} s of loading`);
  assert.match(s.renderer, /^WebGL/);

  // Drag the map by hand: the frames painted meanwhile are the user's experience of panning.
  await page.evaluate(() => window.geocdtDemo.map.setView([47, 8], 5, { animate: false }));
  const box = await page.locator('#map').boundingBox();
  const x0 = box.x + box.width / 2;
  const y0 = box.y + box.height / 2;
  await page.evaluate(startFrameLog);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  for (let i = 1; i <= 40; i++) await page.mouse.move(x0 - 8 * i, y0 + 3 * i);
  const dragFrames = await page.evaluate(stopFrameLog);
  await page.evaluate(startFrameLog);
  await page.mouse.up(); // the layer redraws once the move ends
  await page.evaluate(() => new Promise((r) => setTimeout(r, 500)));
  const afterFrames = await page.evaluate(stopFrameLog);
  const sorted = [...dragFrames].sort((a, b) => a - b);
  const median = sorted[sorted.length >> 1];
  const longest = (frames) => Math.max(...frames).toFixed(0);
  console.log(`# dragging the 10m mesh: ${dragFrames.length} frames, ` +
    `median ${median.toFixed(1)} ms, longest ${longest(dragFrames)} ms; ` +
    `redraw after the drag: longest frame ${longest(afterFrames)} ms`);
  assert.ok(dragFrames.length >= 10, `only ${dragFrames.length} frames painted while dragging`);
  assert.ok(median < 100, `median frame while dragging: ${median} ms`);
  const moved = await page.evaluate(() => window.geocdtDemo.map.getCenter());
  assert.ok(moved.lng > 8 && moved.lat > 47, `the map did not pan: ${JSON.stringify(moved)}`);
  await page.screenshot({ path: join(OUTPUT, 'demo-world-10m.png') });
  assert.deepEqual(consoleErrors, []);
});
