// Run from the folder where the packed tarball was installed: uses geocdt as a user would.
import { init, triangulate, triangulateGeoJSON } from 'geocdt';
import { createWorker } from 'geocdt/worker';

await init();
const r = triangulate({ points: [0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25] });
const fc = triangulateGeoJSON({ type: 'MultiPoint', coordinates: [[0, 0], [2, 0], [0, 2]] });
const worker = createWorker();
const w = await worker.triangulate(
  { points: new Float64Array([0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.25]) });
console.log(JSON.stringify({
  triangles: r.triangles.length / 3,
  features: fc.features.length,
  workerTriangles: w.triangles.length / 3,
}));
