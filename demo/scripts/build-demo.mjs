// `npm run demo:build`: builds the static demo into demo/dist (page, worker, wasm, data).
// geocdt's wasm is built first when it is missing. (`npm run demo` and `npm run demo:build`
// run scripts/ensure-deps.sh before, which also rebuilds a stale one.)
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';

const repo = fileURLToPath(new URL('../../', import.meta.url));
const wasm = new URL('../../web/dist/geocdt.wasm', import.meta.url);
export const distDir = fileURLToPath(new URL('../dist/', import.meta.url));

function ensureWasm() {
  if (existsSync(wasm)) return;
  console.log('geocdt.wasm is not built yet: running `npm run build` first');
  const r = spawnSync('npm', ['run', 'build'], { cwd: repo, stdio: 'inherit' });
  if (r.status !== 0 || !existsSync(wasm)) {
    throw new Error('could not build web/dist/geocdt.wasm (see `npm run build` above)');
  }
}

// outDir: where to build (a test that runs beside another builds into a folder of its own).
export async function buildDemo(outDir = distDir) {
  ensureWasm();
  const started = performance.now();
  await build({
    configFile: fileURLToPath(new URL('../vite.config.js', import.meta.url)),
    build: { outDir },
  });
  console.log(`demo built into ${outDir} in ${Math.round(performance.now() - started)} ms`);
  return outDir;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  buildDemo().catch((e) => {
    console.error(e.message);
    process.exit(1);
  });
}
