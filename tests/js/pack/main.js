// Bundled by Vite from the installed tarball and run in headless Chromium.
import { init, triangulate, Triangulation } from 'geocdt';
import { createWorker } from 'geocdt/worker';

const out = document.getElementById('result');
try {
  await init();
  const points = new Float64Array(2_000);
  for (let i = 0; i < points.length; i++) points[i] = Math.sin(i * 12.9898) * 43758.5453 % 100;
  const polylines = { coords: [0, 0, 100, 100], offsets: new Uint32Array([0, 2]) };
  const syncProgress = [];
  const r = triangulate({ points, polylines }, { onProgress: (e) => syncProgress.push(e) });
  const t = new Triangulation();
  t.insertPoints([0, 0, 4, 0, 0, 4]);
  const located = t.locate(1, 1).kind;
  t.dispose();
  const worker = createWorker();
  const copy = points.slice();
  const workerProgress = [];
  const w = await worker.triangulate({ points: copy, polylines },
    { onProgress: (e) => workerProgress.push(e) });
  worker.terminate();
  out.textContent = JSON.stringify({
    triangles: r.triangles.length / 3,
    workerTriangles: w.triangles.length / 3,
    transferred: copy.byteLength === 0,
    located,
    syncProgress,
    workerProgress,
  });
} catch (error) {
  out.textContent = `error: ${error?.stack ?? error}`;
}
