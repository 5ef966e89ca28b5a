// The README's first command as a new user runs it: `npm run demo` in a fresh clone of HEAD,
// with no node_modules and no build, installs what it lacks, builds the wasm and the demo,
// and serves them. Fetches the page and the wasm from the URL it prints. Commit first: the
// clone holds HEAD, not the working tree.
import assert from 'node:assert/strict';
import { execFileSync, spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, test } from 'node:test';
import { fileURLToPath } from 'node:url';

const repo = fileURLToPath(new URL('../../', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'geocdt-fresh-clone-'));
// npm ci, a wasm build from scratch and the demo's build: about a minute on 2 cores.
const SERVE_TIMEOUT = 15 * 60_000;
let demo = null;

after(() => {
  if (demo && demo.exitCode === null) process.kill(-demo.pid, 'SIGTERM');
  rmSync(dir, { recursive: true, force: true });
});

// The environment of a user's shell: none of the npm_* variables of the `npm test` around us.
function userEnvironment() {
  return Object.fromEntries(Object.entries(process.env).filter(([k]) => !/^npm_/i.test(k)));
}

// Resolves to the URL that run-demo.mjs prints; rejects if the command ends first.
function demoUrl(child) {
  let output = '';
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => {
      reject(new Error(`no URL after ${SERVE_TIMEOUT / 1000} s:\n${output.slice(-4000)}`));
    }, SERVE_TIMEOUT);
    const read = (chunk) => {
      output += chunk;
      const found = /geocdt demo: (http:\/\/\S+)/.exec(output);
      if (found) {
        clearTimeout(timer);
        resolve(found[1]);
      }
    };
    child.stdout.setEncoding('utf8').on('data', read);
    child.stderr.setEncoding('utf8').on('data', read);
    child.on('exit', (code, signal) => {
      clearTimeout(timer);
      reject(new Error(`npm run demo ended (${code ?? signal}) first:\n${output.slice(-4000)}`));
    });
  });
}

test('npm run demo, first thing in a fresh clone, serves the page and the wasm', {
  timeout: SERVE_TIMEOUT + 60_000,
}, async () => {
  const head = execFileSync('git', ['rev-parse', 'HEAD'], { cwd: repo, encoding: 'utf8' }).trim();
  execFileSync('git', ['clone', '--quiet', '--no-checkout', repo, dir]);
  execFileSync('git', ['checkout', '--quiet', '--detach', head], { cwd: dir });
  for (const absent of ['node_modules', 'web/dist', 'build-wasm', 'demo/dist']) {
    assert.ok(!existsSync(join(dir, absent)), `${absent} in a fresh clone`);
  }

  const started = Date.now();
  // Its own process group, so that the server (npm, sh, node) stops with the test.
  demo = spawn('npm', ['run', 'demo', '--', '--port', '0'], {
    cwd: dir, env: userEnvironment(), detached: true, stdio: ['ignore', 'pipe', 'pipe'],
  });
  const url = await demoUrl(demo);
  console.log(`# fresh clone to a served demo: ${Math.round((Date.now() - started) / 1000)} s`);
  assert.match(url, /^http:\/\/127\.0\.0\.1:\d+\/$/);

  const page = await fetch(url);
  assert.equal(page.status, 200);
  assert.match(page.headers.get('content-type'), /^text\/html/);
  assert.match(await page.text(), /<main id="map">/);
  // Cross-origin isolated, for the threaded build.
  assert.equal(page.headers.get('cross-origin-opener-policy'), 'same-origin');
  assert.equal(page.headers.get('cross-origin-embedder-policy'), 'require-corp');

  // Both modules the clone built from its own sources (one thread, threads), served as built.
  const wasmFiles = readdirSync(join(dir, 'demo/dist/assets')).filter((f) => f.endsWith('.wasm'));
  assert.equal(wasmFiles.length, 2, `the demo's wasm assets: ${wasmFiles}`);
  for (const built of ['geocdt', 'geocdt-threads']) {
    const file = wasmFiles.find((f) => f.startsWith(`${built}-`) && !f.slice(built.length + 1)
      .startsWith('threads'));
    assert.ok(file, `${built}.wasm among ${wasmFiles}`);
    const wasm = await fetch(new URL(`assets/${file}`, url));
    assert.equal(wasm.status, 200);
    assert.equal(wasm.headers.get('content-type'), 'application/wasm');
    const bytes = new Uint8Array(await wasm.arrayBuffer());
    assert.ok(WebAssembly.validate(bytes), `${file} is a valid module`);
    assert.deepEqual(bytes, new Uint8Array(readFileSync(join(dir, `web/dist/${built}.wasm`))));
  }
});
