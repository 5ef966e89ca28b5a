// Compiled with tsc --noEmit by types.test.js: the declarations must accept real use and
// reject wrong use (the @ts-expect-error lines fail the build if they stop being errors).
import { init, triangulate, triangulateGeoJSON, Triangulation, memoryUsage, type TriangulateResult } from 'geocdt';
import { createWorker } from 'geocdt/worker';

async function main(): Promise<void> {
  await init();
  await init({ wasmUrl: 'geocdt.wasm' });
  const r: TriangulateResult = triangulate({ points: new Float64Array(6), polylines: [[0, 0, 1, 1]] }, { keep: 'inside' });
  const t: Uint32Array = r.triangles;
  const h: Int32Array = r.halfedges;
  const inside: Uint8Array | undefined = r.inside;
  const ms: number = r.stats.milliseconds;

  const fc = triangulateGeoJSON({ type: 'FeatureCollection', features: [] });
  const firstRing: [number, number][] = fc.features[0].geometry.coordinates[0];
  const arrays = triangulateGeoJSON({ type: 'Point', coordinates: [0, 0] }, { output: 'arrays' });
  const ids: Uint32Array = arrays.inputToVertex;

  const tri = new Triangulation();
  const v: Uint32Array = tri.insertPoints([0, 0, 1, 0, 0, 1]);
  const where = tri.locate(0.2, 0.2);
  const kind: 'empty' | 'outside' | 'face' | 'edge' | 'vertex' = where.kind;
  tri.dispose();
  const heap: number = memoryUsage().heapBytes;

  const worker = createWorker();
  const remote = await worker.triangulate({ points: [0, 0, 1, 0, 0, 1] }, { transfer: false });
  const rt = worker.createTriangulation();
  const located = await rt.locate(0, 0);
  worker.terminate();

  // @ts-expect-error keep takes 'all' or 'inside'
  triangulate({ points: [] }, { keep: 'outside' });
  // @ts-expect-error points are numbers
  triangulate({ points: ['0', '1'] });
  // @ts-expect-error results() of a mesh has no inputToVertex
  new Triangulation().results().inputToVertex;

  void [t, h, inside, ms, firstRing, ids, v, kind, heap, remote, located];
}

main();
