// What GeoJSON users pay: triangulateGeoJSON() of the Natural Earth countries (world-atlas) with
// its default output, a FeatureCollection of one Polygon feature per triangle, against the
// same call with output: 'arrays'; and meshToGeoJSON() alone, which makes that collection.
// Each run is a fresh Node process (the collection's objects fill a fresh JS heap, as in a
// script or the CLI): init(), a wait of 1 s, then one call of each kind, then three more
// collections, made while the earlier ones are still in the heap (the first call's is kept).
// Medians over the runs.
//   node bench/js/geojson-output.js [--scale 10m|50m|110m] [--runs N] [--baseline DIR]
// --baseline DIR: another build of the package (a folder holding its web/) in the same runs,
// alternating, for a before/after.
import { execFileSync } from 'node:child_process';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { median } from './timing.js';

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}

const scale = option('--scale', '10m');
const runs = Number(option('--runs', 5));
const baseline = option('--baseline', null);
const root = resolve(new URL('../..', import.meta.url).pathname);

async function child(packageDir) {
  const { readFileSync } = await import('node:fs');
  const { createRequire } = await import('node:module');
  const { feature } = await import('topojson-client');
  const api = await import(pathToFileURL(resolve(packageDir, 'web/index.node.js')).href);
  const require = createRequire(import.meta.url);
  const topology =
    JSON.parse(readFileSync(require.resolve(`world-atlas/countries-${scale}.json`), 'utf8'));
  const countries = feature(topology, topology.objects.countries);
  await api.init();
  await new Promise((done) => setTimeout(done, 1000));
  const timed = (f) => {
    const started = performance.now();
    const result = f();
    return [performance.now() - started, result];
  };
  const [geojson, collection] = timed(() => api.triangulateGeoJSON(countries));
  const [arrays, mesh] = timed(() => api.triangulateGeoJSON(countries, { output: 'arrays' }));
  if (collection.features.length !== mesh.triangles.length / 3) {
    throw new Error('the two outputs disagree on the triangles');
  }
  const build = [];
  for (let k = 0; k < 3; k++) build.push(timed(() => api.meshToGeoJSON(mesh))[0]);
  console.log(JSON.stringify({ geojson, arrays, build, triangles: mesh.triangles.length / 3 }));
}

function inFreshProcess(packageDir) {
  const args = [new URL(import.meta.url).pathname, '--child', packageDir, '--scale', scale];
  return JSON.parse(execFileSync(process.execPath, args, { encoding: 'utf8' }));
}

function main() {
  const builds = [['this build', root]];
  if (baseline) builds.push(['baseline', resolve(baseline)]);
  const results = builds.map(() => []);
  for (let run = 0; run < runs; run++) {
    builds.forEach((_, k) => {
      const i = (k + run) % builds.length;
      results[i].push(inFreshProcess(builds[i][1]));
    });
  }
  const ms = (values) => `${median(values).toFixed(0)} (${Math.min(...values).toFixed(0)}–`
    + `${Math.max(...values).toFixed(0)})`;
  console.log(`### GeoJSON output, Natural Earth ${scale} countries `
    + `(${results[0][0].triangles.toLocaleString('en-US')} triangles; ${runs} fresh processes, `
    + 'medians and ranges, ms)\n');
  console.log('| build | triangulateGeoJSON(), FeatureCollection | the same, output: \'arrays\' '
    + '| meshToGeoJSON(), first | meshToGeoJSON(), later |');
  console.log('| --- | --: | --: | --: | --: |');
  builds.forEach(([name], k) => {
    const rs = results[k];
    console.log(`| ${name} | ${ms(rs.map((r) => r.geojson))} | ${ms(rs.map((r) => r.arrays))} | `
      + `${ms(rs.map((r) => r.build[0]))} | ${ms(rs.flatMap((r) => r.build.slice(1)))} |`);
  });
}

const at = process.argv.indexOf('--child');
if (at >= 0) await child(process.argv[at + 1]);
else main();
