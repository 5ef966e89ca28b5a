// The terrain page in headless Chromium: the bundled DEM meshed in the worker, the statistics
// a user reads (the error within the slider's bound, the smallest angle once minAngle is on),
// the sliders and breaklines changing the mesh, a breakline drawn by clicking, no console
// errors. Screenshots go to test-output/. The demo is built into a folder of its own (the other
// demo test builds demo/dist, maybe at the same time); GEOCDT_DEMO_NO_BUILD=1 tests an
// existing demo/dist instead.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { buildDemo, distDir } from '../../demo/scripts/build-demo.mjs';
import { serveDirectory } from '../../demo/scripts/static-server.mjs';

const OUTPUT = fileURLToPath(new URL('../../test-output/', import.meta.url));
const TIMEOUT = 120_000;

let server;
let context;
let page;
let userDataDir;
let builtDir;
const consoleErrors = [];

before(async () => {
  if (!process.env.GEOCDT_DEMO_NO_BUILD) {
    builtDir = mkdtempSync(join(tmpdir(), 'geocdt-terrain-demo-'));
    await buildDemo(builtDir);
  }
  mkdirSync(OUTPUT, { recursive: true });
  const served = await serveDirectory(builtDir ?? distDir, { port: 0 });
  server = served.server;
  userDataDir = mkdtempSync(join(tmpdir(), 'geocdt-terrain-chromium-'));
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
  await page.goto(new URL('terrain.html', served.url).href);
  await waitFor(['ready', 'failed']);
});

after(async () => {
  await context?.close();
  server?.close();
  if (userDataDir) rmSync(userDataDir, { recursive: true, force: true });
  if (builtDir) rmSync(builtDir, { recursive: true, force: true });
});

async function waitFor(statuses) {
  await page.waitForFunction((s) => s.includes(document.body.dataset.status), statuses,
    { timeout: TIMEOUT });
}

// Runs action, then waits for the page to have meshed again.
async function remeshed(action) {
  await page.evaluate(() => { document.body.dataset.status = 'waiting-for-test'; });
  await action();
  await waitFor(['ready', 'failed']);
}

async function stats() {
  return page.evaluate(() => {
    const text = (id) => document.getElementById(id).textContent;
    const number = (id) => Number(text(id).replace(/[^\d.]/g, ''));
    return {
      status: document.body.dataset.status,
      triangles: number('stat-triangles'),
      vertices: number('stat-vertices'),
      maxError: Number(text('stat-max-error').split(' ')[0]),
      bound: Number(/bound ([\d.]+)/.exec(text('stat-max-error'))?.[1]),
      angle: parseFloat(text('stat-min-angle')),
      below: Number(/\(([\d,]+) triangles below\)/.exec(text('stat-min-angle'))?.[1]
        .replace(/,/g, '') ?? 0),
      steiner: number('stat-steiner'),
      decimated: number('stat-decimated'),
      constrained: number('stat-constrained'),
      error: document.getElementById('error').hidden ? '' : text('error'),
    };
  });
}

async function setSlider(id, value) {
  await remeshed(() => page.evaluate(([i, v]) => {
    const input = document.getElementById(i);
    input.value = String(v);
    input.dispatchEvent(new Event('input'));
  }, [id, value]));
}

test('the DEM is meshed within the bound, breaklines constrained', async () => {
  const s = await stats();
  assert.equal(s.status, 'ready', s.error);
  assert.ok(s.triangles > 1000, `${s.triangles} triangles`);
  assert.ok(s.maxError <= s.bound, `${s.maxError} within ${s.bound}`);
  // Two breaklines of three segments each, crossing once: eight constrained edges at least.
  assert.ok(s.constrained >= 8, `the default breaklines are constrained edges (${s.constrained})`);
  const painted = await page.evaluate(() => {
    const c = document.getElementById('terrain');
    const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let opaque = 0;
    for (let i = 3; i < data.length; i += 4) opaque += data[i] === 255;
    return opaque / (data.length / 4);
  });
  assert.ok(painted > 0.95, `the shaded mesh covers the canvas (${painted})`);
  await page.screenshot({ path: join(OUTPUT, 'terrain.png') });
});

test('a larger error gives fewer triangles; minAngle gives angles of at least it', async () => {
  const before = await stats();
  await setSlider('max-error', 75);
  const coarse = await stats();
  assert.equal(coarse.status, 'ready', coarse.error);
  assert.ok(coarse.bound > before.bound);
  assert.ok(coarse.triangles < before.triangles);
  assert.ok(coarse.maxError <= coarse.bound);
  await setSlider('min-angle', 20);
  const refined = await stats();
  assert.equal(refined.status, 'ready', refined.error);
  assert.ok(refined.steiner > 0);
  // Where breaklines meet each other or the raster's edges at a smaller angle, those corners
  // keep theirs, and the page says how many triangles they leave below (a test below draws
  // one). Without breaklines, every angle is at least 20.
  assert.equal(refined.below > 0, refined.angle < 20 - 0.05,
    `smallest angle ${refined.angle}, ${refined.below} triangles below`);
  await remeshed(() => page.click('#use-breaklines'));
  const plain = await stats();
  assert.ok(plain.angle >= 20 - 0.05, `smallest angle ${plain.angle}`);
  assert.equal(plain.below, 0);
  assert.ok(plain.maxError <= plain.bound);
  assert.equal(plain.constrained, 0);
  await page.screenshot({ path: join(OUTPUT, 'terrain-refined.png') });
});

test('decimate removes vertices and triangles, keeping the bound', async () => {
  const before = await stats();
  await remeshed(() => page.click('#decimate'));
  const decimated = await stats();
  assert.equal(decimated.status, 'ready', decimated.error);
  assert.ok(decimated.decimated > 0, `${decimated.decimated} vertices decimated`);
  assert.ok(decimated.triangles < before.triangles,
    `${decimated.triangles} triangles against ${before.triangles}`);
  assert.ok(decimated.maxError <= decimated.bound);
  await remeshed(() => page.click('#decimate'));
  const again = await stats();
  assert.equal(again.decimated, 0);
  assert.equal(again.triangles, before.triangles);
});

// Draws a breakline of three points (fractions of the canvas) as a user does: two clicks and
// a double click, which ends it; then waits for the page to have meshed again.
async function drawBreakline([[ax, ay], [bx, by], [cx, cy]]) {
  const box = await page.locator('#terrain').boundingBox();
  const at = (fx, fy) => ({ x: box.x + fx * box.width, y: box.y + fy * box.height });
  const a = at(ax, ay), b = at(bx, by), c = at(cx, cy);
  await page.mouse.click(a.x, a.y);
  await page.mouse.click(b.x, b.y);
  await remeshed(() => page.mouse.dblclick(c.x, c.y));
}

test('a breakline drawn by clicking becomes constrained edges', async () => {
  await setSlider('min-angle', 0);
  await drawBreakline([[0.2, 0.3], [0.5, 0.6], [0.8, 0.4]]);
  const s = await stats();
  assert.equal(s.status, 'ready', s.error);
  assert.ok(s.constrained >= 2, `${s.constrained} constrained edges`);
  assert.ok(s.maxError <= s.bound);
  await remeshed(() => page.click('#clear-lines'));
  assert.equal((await stats()).constrained, 0);
  assert.deepEqual(consoleErrors, []);
});

test('a breakline folding back on itself keeps its sharp corner, counted below minAngle',
  async () => {
    await setSlider('min-angle', 20);
    // Its two segments meet at the middle point at a few degrees, which refinement cannot
    // open.
    await drawBreakline([[0.2, 0.3], [0.7, 0.55], [0.2, 0.38]]);
    const sharp = await stats();
    assert.equal(sharp.status, 'ready', sharp.error);
    assert.ok(sharp.angle < 20 && sharp.below > 0,
      `smallest angle ${sharp.angle}, ${sharp.below} triangles below`);
    assert.ok(sharp.maxError <= sharp.bound);
    await remeshed(() => page.click('#clear-lines'));
    const cleared = await stats();
    assert.ok(cleared.angle >= 20 - 0.05 && cleared.below === 0,
      `smallest angle ${cleared.angle}, ${cleared.below} triangles below`);
    assert.deepEqual(consoleErrors, []);
  });
