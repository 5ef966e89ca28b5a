// The Node entry: reads the wasm bytes from the package folder (the generated glue cannot
// load them in Node 20 by itself).
import { readFile } from 'node:fs/promises';
import createGeocdtModule from './dist/geocdt.mjs';
import { createApi } from './api.js';

export { geoJSONToInput, meshToGeoJSON } from './geojson.js';
export { GeocdtError } from './errors.js';

async function instantiate(options) {
  const { wasmUrl } = options;
  const where = wasmUrl === undefined ? new URL('./dist/geocdt.wasm', import.meta.url)
    : typeof wasmUrl === 'string' ? wasmUrl : new URL(wasmUrl.href);
  const wasmBinary = options.wasmBinary ?? await readFile(where);
  return createGeocdtModule({ wasmBinary });
}

export const { init, triangulate, triangulateGeoJSON, memoryUsage, Triangulation } =
  createApi(instantiate);
