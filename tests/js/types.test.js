// The TypeScript declarations accept real use and reject wrong use (tsc on types/usage.ts,
// resolving 'geocdt' and 'geocdt/worker' through the exports map's `types`).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { fileURLToPath } from 'node:url';

test('tsc --noEmit on a program that uses the public API', () => {
  const tsc = createRequire(import.meta.url).resolve('typescript/bin/tsc');
  const project = fileURLToPath(new URL('./types/tsconfig.json', import.meta.url));
  const p = spawnSync(process.execPath, [tsc, '-p', project], { encoding: 'utf8' });
  assert.equal(p.status, 0, p.stdout + p.stderr);
});
