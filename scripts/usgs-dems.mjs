// The USGS elevation models that Debian's python-matplotlib-data installs (public domain
// data; scripts/ensure-deps.sh installs the package for the tests and the demo):
//   jacksboro()  the Jacksboro fault DEM: 403 x 344 int16 metres, with its lon/lat bounds
//   topobathy()  a 120 x 91 float32 topography and bathymetry grid, metres
// and upsampled(raster, k): a raster k times finer, bilinear (the size of a high-resolution
// model of the same ground).
import { readFileSync } from 'node:fs';
import { readNpz } from '../web/npy.js';

export const kSampleData = '/usr/share/matplotlib/mpl-data/sample_data';

function read(file) {
  try {
    return readNpz(readFileSync(`${kSampleData}/${file}`));
  } catch (error) {
    if (error.code !== 'ENOENT') throw error;
    throw new Error(`${kSampleData}/${file} is missing: install Debian's python-matplotlib-data `
      + '(sh scripts/ensure-deps.sh does)', { cause: error });
  }
}

// Rows from the north, as the .npz stores them; bbox [west, south, east, north] in degrees.
export function jacksboro() {
  const a = read('jacksboro_fault_dem.npz');
  const [height, width] = a.elevation.shape;
  // The file names the northern edge ymin: the bounds are sorted here.
  const [y0, y1] = [a.ymin.data[0], a.ymax.data[0]].sort((p, q) => p - q);
  const bbox = [a.xmin.data[0], y0, a.xmax.data[0], y1];
  return { name: 'Jacksboro fault DEM', heights: a.elevation.data, width, height, bbox };
}

// The top-left size x size pixels of a raster, as a new array of the same type.
export function crop({ heights, width }, size) {
  const out = new heights.constructor(size * size);
  for (let j = 0; j < size; j++) {
    out.set(heights.subarray(j * width, j * width + size), j * size);
  }
  return { heights: out, width: size, height: size };
}

// (width - 1) k + 1 by (height - 1) k + 1 float32 heights, bilinear between the pixels.
export function upsampled({ heights, width, height }, k) {
  const w = (width - 1) * k + 1, h = (height - 1) * k + 1;
  const out = new Float32Array(w * h);
  for (let y = 0; y < h; y++) {
    const j = Math.min(Math.floor(y / k), height - 2), v = y / k - j;
    for (let x = 0; x < w; x++) {
      const i = Math.min(Math.floor(x / k), width - 2), u = x / k - i, p = j * width + i;
      out[y * w + x] = (heights[p] * (1 - u) + heights[p + 1] * u) * (1 - v)
        + (heights[p + width] * (1 - u) + heights[p + width + 1] * u) * v;
    }
  }
  return { heights: out, width: w, height: h };
}

export function topobathy() {
  const a = read('topobathy.npz');
  const [height, width] = a.topo.shape;
  return { name: 'topobathy', heights: a.topo.data, width, height };
}
