// The threaded build in Node against the single-threaded one, alternating in one process:
// uniform points (1M, 4M) and constrained real data (Natural Earth 10m rings, the GSHHG Asia
// region when build/data or --data has it). Prints each one's median time, the ratio and
// stats.threads. The wall clock: the process CPU clock would add the threads up.
//   node --expose-gc bench/js/threads.js [--threads 2] [--rounds 5] [--data DIR] [--quick]
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { init, triangulate } from 'geocdt';
import createGeocdtModule from '../../web/dist/geocdt.mjs';
import { createApi } from '../../web/api.js';
import { instantiateCompiled } from '../../web/warm-up.js';
import { countryRings, readGpl, uniformLehmer } from './datasets.js';
import { alternate } from './timing.js';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 ? args[i + 1] : fallback;
};
const threads = Number(option('threads', '2'));
const rounds = Number(option('rounds', '5'));
const dataDir = option('data', 'build/data');
const quick = args.includes('--quick');

await init({ threads });
const single = createApi(async () => {
  const bytes = readFileSync(new URL('../../web/dist/geocdt.wasm', import.meta.url));
  return { wasm: await instantiateCompiled(createGeocdtModule, await WebAssembly.compile(bytes)),
    threads: 1 };
});
await single.init({ warmUp: false });

const inputs = [{ name: '1M uniform points', input: { points: uniformLehmer(1_000_000) } }];
if (!quick) {
  inputs.push({ name: '4M uniform points', input: { points: uniformLehmer(4_000_000, 7) } });
}
const rings = countryRings('10m').polylines;
inputs.push({ name: 'Natural Earth 10m rings', input: { polylines: rings } });
const asia = join(dataDir, 'gshhg_asia.gpl');
if (!quick && existsSync(asia)) {
  inputs.push({ name: 'GSHHG Asia (2M points)', input: { polylines: readGpl(asia) } });
}

console.log(`| input | 1 thread ms | ${threads} threads ms | ratio | stats.threads |`);
console.log('|---|--:|--:|--:|--:|');
for (const { name, input } of inputs) {
  const describe = (r) => r.stats.threads;
  const results = await alternate([
    { name: 'single', run: () => single.triangulate(input), describe },
    { name: 'threaded', run: () => triangulate(input), describe },
  ], rounds);
  const one = results.single, many = results.threaded;
  if (one.error || many.error) {
    console.log(`| ${name} | ${one.error ?? ''} | ${many.error ?? ''} | | |`);
    continue;
  }
  console.log(`| ${name} | ${one.ms.toFixed(0)} | ${many.ms.toFixed(0)} | `
    + `${(many.ms / one.ms).toFixed(2)}x | ${many.summary} |`);
}
