// The terrain page's worker: holds the DEM and meshes it with geocdt's triangulateRaster for
// each request, sending back the mesh's arrays (transferred, not copied).
import { init, triangulateRaster } from 'geocdt';

let raster = null;

self.onmessage = async ({ data }) => {
  try {
    await init({ warmUp: false });
    if (data.raster) {
      raster = data.raster;
      self.postMessage({ id: data.id, ok: true });
      return;
    }
    const started = performance.now();
    const mesh = triangulateRaster(raster, data.options);
    const ms = performance.now() - started;
    const { points, triangles, values, constrained, stats } = mesh;
    self.postMessage({ id: data.id, ok: true, mesh: { points, triangles, values, constrained,
      stats, ms } }, [points.buffer, triangles.buffer, values.buffer, constrained.buffer]);
  } catch (error) {
    self.postMessage({ id: data.id, ok: false, error: `${error.name}: ${error.message}` });
  }
};
