// What region labels cost: Natural Earth countries (world-atlas) triangulated with and without
// their polygons (one per country), stats.coreMilliseconds of each in alternating rounds in one
// process, medians and their ratio; then triangulateGeoJSON() of the same countries, which
// labels the regions and keeps the features, against triangulate() of its flat input alone.
//   node --expose-gc bench/js/regions.js [--scale 10m|50m|110m] [--rounds N]
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { feature } from 'topojson-client';
import { geoJSONToInput, init, triangulate, triangulateGeoJSON } from '../../web/index.node.js';
import { median } from './timing.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const scale = option('--scale', '10m');
const rounds = Number(option('--rounds', 9));

const require = createRequire(import.meta.url);
const topology =
  JSON.parse(readFileSync(require.resolve(`world-atlas/countries-${scale}.json`), 'utf8'));
const countries = feature(topology, topology.objects.countries);
await init();

// contenders: [{ name, run() -> a result with stats }]; times: which stat (or the wall clock).
function measure(contenders, time) {
  const ms = contenders.map(() => []);
  for (let round = 0; round < rounds; round++) {
    contenders.forEach((_, k) => {
      const j = (k + round) % contenders.length;
      globalThis.gc?.();
      const started = performance.now();
      const r = contenders[j].run();
      ms[j].push(time === 'core' ? r.stats.coreMilliseconds : performance.now() - started);
    });
  }
  const base = median(ms[0]);
  console.log(`| call | ${time === 'core' ? 'core' : 'whole call'} ms (median) | vs the first |`);
  console.log('| --- | --- | --- |');
  contenders.forEach((c, j) => {
    const m = median(ms[j]);
    console.log(`| ${c.name} | ${m.toFixed(1)} | ${(m / base).toFixed(3)} |`);
  });
  console.log();
}

const input = geoJSONToInput(countries, { flat: true });
const { polylines, polygons } = input;
const points = polylines.offsets.at(-1).toLocaleString('en-US');
console.log(`## Natural Earth ${scale} countries: ${points} points, `
  + `${polylines.offsets.length - 1} rings, ${polygons.length - 1} polygons `
  + `(${rounds} alternating rounds)\n`);
measure([
  { name: 'triangulate({ polylines })', run: () => triangulate({ polylines }) },
  { name: 'triangulate({ polylines, polygons })', run: () => triangulate({ polylines, polygons }) },
  {
    name: 'the same, keep: \'inside\'',
    run: () => triangulate({ polylines, polygons }, { keep: 'inside' }),
  },
], 'core');
measure([
  { name: 'triangulate({ polylines })', run: () => triangulate({ polylines }) },
  {
    name: 'triangulateGeoJSON(countries, { output: \'arrays\' })',
    run: () => triangulateGeoJSON(countries, { output: 'arrays' }),
  },
], 'call');
