// The share of a one-shot triangulate() spent outside the wasm core (checks, copies in and out,
// the JS around them): stats.milliseconds against stats.coreMilliseconds, medians of alternating
// rounds in one process. With --baseline, another build of the package (a folder holding its
// web/) runs in the same rounds, for a before/after.
//   node --expose-gc bench/js/glue.js [--data DIR] [--baseline PACKAGE_DIR] [--rounds N]
// DIR holds gshhg_region.gpl (scripts/datasets/gshhg_region.sh makes it); without it only the
// uniform points run.
import { existsSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { median } from './timing.js';
import { polylineArrays, readGpl, uniformLehmer } from './datasets.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const rounds = Number(option('--rounds', 5));
const data = option('--data', null);
const baseline = option('--baseline', null);

async function load(folder) {
  const api = await import(pathToFileURL(join(folder, 'web/index.node.js')).href);
  await api.init();
  return api;
}

function measure(contenders) {
  const runs = contenders.map(() => ({ total: [], core: [] }));
  for (let round = 0; round < rounds; round++) {
    contenders.forEach((c, k) => {
      const j = (k + round) % contenders.length;
      globalThis.gc?.();
      const { stats } = contenders[j].run();
      runs[j].total.push(stats.milliseconds);
      runs[j].core.push(stats.coreMilliseconds);
    });
  }
  console.log('| build and input | call ms | core ms | outside ms | outside the core |');
  console.log('| --- | --- | --- | --- | --- |');
  contenders.forEach((c, j) => {
    const total = median(runs[j].total);
    const core = median(runs[j].core);
    const outside = median(runs[j].total.map((t, i) => t - runs[j].core[i]));
    const share = median(runs[j].total.map((t, i) => 1 - runs[j].core[i] / t));
    console.log(`| ${c.name} | ${total.toFixed(0)} | ${core.toFixed(0)} | `
      + `${outside.toFixed(0)} | ${(100 * share).toFixed(1)}% |`);
  });
  console.log();
}

const here = resolve(new URL('../..', import.meta.url).pathname);
const builds = [{ name: 'this build', api: await load(here), flat: true }];
if (baseline) builds.push({ name: 'baseline', api: await load(resolve(baseline)), flat: false });

const points = uniformLehmer(1_000_000);
console.log(`## 1,000,000 uniform points (${rounds} alternating rounds, medians)\n`);
measure(builds.map((b) => ({ name: b.name, run: () => b.api.triangulate({ points }) })));

const gpl = data && join(data, 'gshhg_region.gpl');
if (gpl && existsSync(gpl)) {
  const flat = readGpl(gpl);
  const arrays = polylineArrays(flat);
  const n = (flat.offsets.at(-1)).toLocaleString('en-US');
  console.log(`## GSHHG region: ${n} points, ${flat.offsets.length - 1} polylines\n`);
  const contenders = [];
  for (const b of builds) {
    if (b.flat) {
      contenders.push({
        name: `${b.name}, flat polylines`,
        run: () => b.api.triangulate({ polylines: flat }),
      });
    }
    contenders.push({
      name: `${b.name}, an array per polyline`,
      run: () => b.api.triangulate({ polylines: arrays }),
    });
  }
  measure(contenders);
} else {
  console.log('(GSHHG region skipped: pass --data DIR with gshhg_region.gpl in it.)');
}
