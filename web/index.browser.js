// The browser and web-worker entry. The wasm is fetched from beside this file; bundlers see
// the `new URL(..., import.meta.url)` and ship it as an asset.
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi } from './api.js';

export { geoJSONToInput, meshToGeoJSON } from './geojson.js';
export { GeocdtError } from './errors.js';

async function instantiate(options) {
  if (options.wasmBinary) return createGeocdtModule({ wasmBinary: options.wasmBinary });
  const { wasmUrl } = options;
  const url = wasmUrl === undefined ? new URL('./dist/geocdt.wasm', import.meta.url).href
    : typeof wasmUrl === 'string' ? wasmUrl : wasmUrl.href;
  return createGeocdtModule({ locateFile: () => url });
}

export const { init, triangulate, triangulateGeoJSON, memoryUsage, Triangulation } =
  createApi(instantiate);
