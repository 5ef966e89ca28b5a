// The tiles page (demo/tiles.html) in headless Chromium: the real-world vector tiles filled by
// triangulatePolygons(), the toggle to earcut, earcut's wrong polygons counted and outlined.
// Builds demo/dist unless a build newer than the page's sources is there (demo.test.mjs builds
// it just before in `npm test`); GEOCDT_DEMO_NO_BUILD=1 never builds. Screenshots go to
// test-output/.
import assert from 'node:assert/strict';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { buildDemo, distDir } from '../../demo/scripts/build-demo.mjs';
import { serveDirectory } from '../../demo/scripts/static-server.mjs';

const here = (path) => fileURLToPath(new URL(path, import.meta.url));
const OUTPUT = here('../../test-output/');
const READY_TIMEOUT = 240_000;

let server;
let context;
let page;
let userDataDir;
let url;
const consoleErrors = [];

// Whether demo/dist holds a tiles page built after every source it depends on.
function builtAfterSources() {
  const built = join(distDir, 'tiles.html');
  if (!existsSync(built)) return false;
  const time = statSync(built).mtimeMs;
  const sources = [here('../../demo/tiles.html'), here('../../web/dist/geocdt.wasm'),
    ...readdirSync(here('../../demo/src')).map((f) => here(`../../demo/src/${f}`)),
    ...readdirSync(here('../../demo/scripts')).map((f) => here(`../../demo/scripts/${f}`))];
  return sources.every((f) => statSync(f).mtimeMs < time);
}

before(async () => {
  if (!process.env.GEOCDT_DEMO_NO_BUILD && !builtAfterSources()) await buildDemo();
  mkdirSync(OUTPUT, { recursive: true });
  const served = await serveDirectory(distDir, { port: 0 });
  server = served.server;
  url = new URL('tiles.html', served.url).href;
  userDataDir = mkdtempSync(join(tmpdir(), 'geocdt-tiles-chromium-'));
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on('console', (m) => m.type() === 'error' && consoleErrors.push(m.text()));
  page.on('pageerror', (e) => consoleErrors.push(String(e)));
});

after(async () => {
  await context?.close();
  server?.close();
  if (userDataDir) rmSync(userDataDir, { recursive: true, force: true });
});

async function waitForReady() {
  await page.waitForFunction(() => ['ready', 'failed'].includes(document.body.dataset.status),
    null, { timeout: READY_TIMEOUT });
}

function readStats() {
  return page.evaluate(() => {
    const number = (id) => Number(document.getElementById(id).textContent.replace(/[^\d.]/g, ''));
    const error = document.getElementById('error');
    return {
      status: document.body.dataset.status,
      error: error.hidden ? null : error.textContent,
      tiles: number('stat-tiles'),
      polygons: number('stat-polygons'),
      vertices: number('stat-vertices'),
      geocdtMs: number('stat-geocdt-ms'),
      earcutMs: number('stat-earcut-ms'),
      geocdtTriangles: number('stat-geocdt-triangles'),
      earcutTriangles: number('stat-earcut-triangles'),
      crossings: number('stat-crossings'),
      wrong: number('stat-wrong'),
      listed: document.querySelectorAll('#wrong-list li').length,
      threads: number('stat-threads'),
    };
  });
}

test('the first region: every polygon filled by geocdt, earcut wrong on two', async () => {
  const started = Date.now();
  await page.goto(url);
  await waitForReady();
  const s = await readStats();
  console.log(`# nepal, page load to drawn: ${Date.now() - started} ms: ${JSON.stringify(s)}`);
  assert.equal(s.status, 'ready', s.error ?? 'the page did not get ready');
  assert.equal(s.tiles, 60);
  assert.equal(s.polygons, 51930);
  assert.equal(s.vertices, 1328172);
  assert.equal(s.crossings, 0);
  assert.ok(s.geocdtTriangles > 1_000_000, `geocdt triangles: ${s.geocdtTriangles}`);
  assert.ok(s.geocdtMs > 0 && s.earcutMs > 0);
  // earcut's two wrong polygons of the tiles are here (bench/js/polygons.js counts them).
  assert.equal(s.wrong, 2);
  assert.equal(s.listed, 2);
  assert.ok(s.threads >= 1);
  await page.screenshot({ path: join(OUTPUT, 'tiles-nepal-geocdt.png') });
});

// Red pixels on the outlines' canvas.
function outlinePixels() {
  return page.evaluate(() => {
    const canvas = document.getElementById('overlay');
    const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    let red = 0;
    for (let i = 0; i < data.length; i += 4) red += data[i + 3] > 0 && data[i] > 150 ? 1 : 0;
    return red;
  });
}

test('toggling to earcut and back: earcut visibly wrong where it is counted', async () => {
  const setFill = async (which) => {
    await page.evaluate(() => { document.body.dataset.status = 'waiting-for-test'; });
    await page.check(`input[name="fill"][value="${which}"]`);
    await waitForReady();
  };
  // Zoomed onto the first wrong polygon: its outline drawn, or not.
  await page.click('#wrong-list li:first-child a');
  console.log(`# ${await page.textContent('#wrong-list li:first-child')}`);
  assert.ok(await outlinePixels() > 100, 'the wrong polygon is outlined');
  await page.uncheck('#highlight');
  assert.equal(await outlinePixels(), 0);
  // Fills are translucent: where earcut's triangles overlap, the colour deepens.
  const geocdtShot = await page.locator('#stage').screenshot();
  await setFill('earcut');
  const e = await readStats();
  assert.equal(e.status, 'ready');
  assert.ok(e.earcutTriangles > 1_000_000, `earcut triangles: ${e.earcutTriangles}`);
  const earcutShot = await page.locator('#stage').screenshot({
    path: join(OUTPUT, 'tiles-nepal-earcut-wrong.png') });
  assert.ok(!earcutShot.equals(geocdtShot), 'earcut\'s fill of the polygon differs from geocdt\'s');
  await setFill('geocdt');
  assert.ok((await page.locator('#stage').screenshot()).equals(geocdtShot),
    'back to geocdt, the same picture');
  await page.check('#highlight');
  await page.check('#edges');
  await page.locator('#stage').screenshot({ path: join(OUTPUT, 'tiles-nepal-geocdt-wrong.png') });
  assert.deepEqual(consoleErrors, []);
});

test('another region: no wrong polygon, the counts follow', async () => {
  await page.evaluate(() => { document.body.dataset.status = 'waiting-for-test'; });
  await page.selectOption('#region', 'chicago');
  await waitForReady();
  const s = await readStats();
  assert.equal(s.status, 'ready', s.error ?? '');
  assert.equal(s.tiles, 30);
  assert.equal(s.polygons, 5608);
  assert.equal(s.wrong, 0);
  assert.equal(s.listed, 0);
  await page.screenshot({ path: join(OUTPUT, 'tiles-chicago.png') });
  assert.deepEqual(consoleErrors, []);
});
