// Bundled by Vite from the installed tarball and run in headless Chromium, on a page served
// cross-origin isolated: init({ threads: 2 }) loads the threaded build.
import { init, triangulate } from 'geocdt';

const out = document.getElementById('result');
try {
  await init({ threads: 2 });
  const points = new Float64Array(2 * 100_000);
  for (let i = 0; i < points.length; i++) points[i] = Math.sin(i * 12.9898) * 43758.5453 % 100;
  const r = triangulate({ points });
  out.textContent = JSON.stringify({
    isolated: globalThis.crossOriginIsolated,
    threads: r.stats.threads,
    vertices: r.points.length / 2,
    triangles: r.triangles.length / 3,
  });
} catch (error) {
  out.textContent = `error: ${error?.stack ?? error}`;
}
