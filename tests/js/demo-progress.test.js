// The demo's progress bar in headless Chromium: the demo is built into a temporary folder
// (not demo/dist, which tests/demo builds), the 1:10m dataset is loaded, and the bar must
// show geocdt's phases in order, its fraction never going back, then disappear.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serveDirectory } from '../../demo/scripts/static-server.mjs';
import { checkProgressEvents } from './support/progress.js';

const CONFIG = fileURLToPath(new URL('../../demo/vite.config.js', import.meta.url));

test('the demo shows a progress bar while a large set triangulates', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'geocdt-demo-progress-'));
  const { build } = await import('vite');
  await build({ configFile: CONFIG, logLevel: 'error', build: { outDir: dir, emptyOutDir: true } });
  const { server, url } = await serveDirectory(dir, { port: 0 });
  const { chromium } = await import('playwright-core');
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu'],
  });
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(url);
    const ready = () => page.waitForFunction(
      () => ['ready', 'failed', 'error'].includes(document.body.dataset.status), null,
      { timeout: 180_000 });
    await ready();
    // Watch the bar from the page itself: was it ever visible with a value, and is it hidden
    // once the triangulation is drawn?
    await page.evaluate(() => {
      window.barSeen = [];
      const box = document.getElementById('progress');
      new MutationObserver(() => {
        if (!box.hidden) window.barSeen.push(box.querySelector('progress').value);
      }).observe(box, { attributes: true, subtree: true, childList: true, characterData: true });
      window.geocdtDemo.progress.length = 0;
    });
    await page.selectOption('#dataset', 'world-10m');
    await page.waitForFunction(() => document.body.dataset.status === 'working');
    await ready();
    const { status, events, seen, hidden } = await page.evaluate(() => ({
      status: document.body.dataset.status,
      events: window.geocdtDemo.progress,
      seen: window.barSeen,
      hidden: document.getElementById('progress').hidden,
    }));
    assert.equal(status, 'ready');
    assert.deepEqual(errors, []);
    checkProgressEvents(events);
    assert.ok(events.some((e) => e.phase === 'constraints'), JSON.stringify(events));
    assert.ok(seen.length > 0, 'the bar was shown');
    assert.ok(hidden, 'the bar is hidden once the mesh is drawn');
  } finally {
    await browser.close();
    server.close();
    rmSync(dir, { recursive: true, force: true });
  }
});
