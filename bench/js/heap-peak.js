// Run as a child process: a fresh module, one triangulation, and the wasm heap it took (the
// allocator's peak, and the memory size) per input point.
//   node bench/js/heap-peak.js [N | rings | arcs] [module path]
// N uniform points (default 1M), or the Natural Earth 10m country rings or arcs as
// constraints; the module path imports another build (its web/index.node.js).
import { pathToFileURL } from 'node:url';
import { countryArcs, countryRings, pointCount, uniformLehmer } from './datasets.js';

const what = process.argv[2] ?? '1000000';
const module = process.argv[3];
const { init, memoryUsage, triangulate } =
  await import(module ? pathToFileURL(module).href : 'geocdt');
await init();
const input = what === 'rings' ? { polylines: countryRings('10m').polylines }
  : what === 'arcs' ? { polylines: countryArcs('10m').polylines }
    : { points: uniformLehmer(Number(what)) };
const n = input.points ? input.points.length / 2 : pointCount(input.polylines);
const before = memoryUsage();
triangulate(input);
const after = memoryUsage();
console.log(JSON.stringify({
  n,
  peakBytesPerPoint: (after.peakBytes - before.peakBytes) / n,
  heapGrowthPerPoint: (after.heapBytes - before.heapBytes) / n,
}));
