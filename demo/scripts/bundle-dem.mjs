// The terrain page's elevation model: the USGS Jacksboro fault DEM from Debian's
// python-matplotlib-data (public domain), read at build time and bundled as jacksboro.dem:
// "DEM1", uint32 width, uint32 height, float64 west, south, east, north, then int16 heights
// row by row from the north (little-endian).
import { jacksboro } from '../../scripts/usgs-dems.mjs';

export function encodeDem({ heights, width, height, bbox }) {
  const bytes = new Uint8Array(44 + 2 * width * height);
  const view = new DataView(bytes.buffer);
  bytes.set([0x44, 0x45, 0x4d, 0x31]);
  view.setUint32(4, width, true);
  view.setUint32(8, height, true);
  bbox.forEach((v, i) => view.setFloat64(12 + 8 * i, v, true));
  heights.forEach((h, i) => view.setInt16(44 + 2 * i, h, true));
  return bytes;
}

export function buildTerrainData() {
  return { 'jacksboro.dem': encodeDem(jacksboro()) };
}
