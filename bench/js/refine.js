// Delaunay refinement in Node: geocdt's wasm against triangle-wasm (Triangle's -q), on the
// Natural Earth country rings, alternating in one process (Triangle in a worker). geocdt
// refines the inside (keep: 'inside', even-odd); Triangle refines its -p domain (everything
// within the outer boundary: lakes given as rings stay filled). Prints, per engine, the median
// time, the Steiner points, the triangles and the worst angle of the triangles refined.
// With --uniform N: N uniform points in a square ring instead, where both domains are the
// square. With --baseline DIR, another build of the package (a folder holding its web/) runs
// in the same rounds, and the median of this build's time over the baseline's, round by
// round, is printed: a before/after in one process. With --rings FILE, the rings of a .gpl
// file (inside, even-odd, as bench_refine gives them to geocdt and CGAL's native mesher), and
// no Triangle (it fails on country rings): geocdt's whole call, and its refine() alone on a
// Triangulation whose rings were inserted beforehand, outside the timing.
//   node bench/js/refine.js [--scale 110m | --uniform 20000 | --rings FILE] [--angle 30]
//     [--rounds 3] [--baseline DIR]
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { init, triangulate, Triangulation } from 'geocdt';
import {
  countryRings, indexedGraph, pointCount, polylineArrays, readGpl, uniformLehmer,
} from './datasets.js';
import * as peers from './peers.js';
import { alternate, median } from './timing.js';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 ? args[i + 1] : fallback;
};
const scale = option('scale', '110m');
const angle = Number(option('angle', '30'));
const rounds = Number(option('rounds', '3'));
const uniformCount = Number(option('uniform', '0'));
const ringsFile = option('rings', null);

// N uniform points in [0, 1000)^2 inside a square ring around them.
function pointsInSquare(n) {
  const box = Float64Array.from([-1, -1, 1001, -1, 1001, 1001, -1, 1001, -1, -1]);
  const points = uniformLehmer(n);
  const xy = [...box.subarray(0, 8), ...points];
  const edges = [[0, 1], [1, 2], [2, 3], [3, 0]];
  return {
    name: `${n} uniform points in a square`,
    input: { points, polylines: [box] },
    graph: { xy, edges },
  };
}

// The polylines of a .gpl file, as one array each (the form Triangulation.insertPolyline
// takes, and triangulate too).
function ringsOf(file) {
  const polylines = polylineArrays(readGpl(file));
  return { name: file, input: { polylines }, graph: indexedGraph(polylines) };
}

await init();
const { name, input, graph } = uniformCount > 0 ? pointsInSquare(uniformCount)
  : ringsFile ? ringsOf(ringsFile) : (() => {
    const rings = countryRings(scale);
    return { name: rings.name, input: { polylines: rings.polylines },
      graph: indexedGraph(rings.polylines) };
  })();
const vertices = graph.xy.length / 2;
const describeRefined = (r) => `${r.steiner.length} Steiner points, `
  + `${r.triangles.length / 3} triangles, `
  + `worst ${peers.worstAngle(r.points, r.triangles).toFixed(2)} deg, `
  + `${r.stats.refineSkipped} left (capped: ${r.stats.refineCapped})`;
const refineWith = (run) => ({
  run: () => run(input, { keep: 'inside', refine: { minAngle: angle } }),
  describe: describeRefined,
});
// refine() alone: the insertion before it and the copy of the mesh after it stay out of the
// time, which run() takes itself (alternate() accepts a promise of { output, ms }).
const refineAlone = {
  name: 'geocdt refine() alone',
  run: () => {
    const t = new Triangulation();
    try {
      for (const ring of input.polylines) t.insertPolyline(ring);
      const started = performance.now();
      t.refine({ keep: 'inside', minAngle: angle });
      const ms = performance.now() - started;
      return Promise.resolve({ output: t.results({ keep: 'inside' }), ms });
    } finally {
      t.dispose();
    }
  },
  describe: describeRefined,
};
const baselineDir = option('baseline', null);
let baseline = null;
if (baselineDir) {
  baseline = await import(pathToFileURL(join(resolve(baselineDir), 'web/index.node.js')).href);
  await baseline.init({ warmUp: false });
}
const triangle = ringsFile ? null : peers.triangleInWorker(600_000);
const results = await alternate([
  { name: 'geocdt', ...refineWith(triangulate) },
  ...(baseline ? [{ name: 'baseline', ...refineWith(baseline.triangulate) }] : []),
  ...(triangle ? [{
    name: 'triangle-wasm',
    run: () => triangle.run({ ...graph, switches: { quality: angle } }),
    describe: (s) => s,
  }] : [refineAlone]),
], rounds);
triangle?.close();
const points = (input.points?.length ?? 0) / 2 + pointCount(input.polylines);
console.log(`${name}: ${points} points (${vertices} distinct), ${angle} degrees`);
for (const [engine, r] of Object.entries(results)) {
  console.log(`  ${engine}: ${r.error ?? `${r.ms.toFixed(0)} ms, ${r.summary}`}`);
}
if (baseline && !results.geocdt.error && !results.baseline.error) {
  const ratios = results.geocdt.times.map((t, i) => t / results.baseline.times[i]);
  const range = `${Math.min(...ratios).toFixed(3)}-${Math.max(...ratios).toFixed(3)}`;
  console.log(`  this build / baseline: ${median(ratios).toFixed(3)} `
    + `(${range}, ${ratios.length} rounds)`);
}
