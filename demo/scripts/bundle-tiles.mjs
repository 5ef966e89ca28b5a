// Builds the tiles page's data: the real-world vector tiles of npm @mapbox/mvt-fixtures
// (Mapbox Streets and terrain, OSM QA), decoded into one file per region: its tiles' polygons
// in GeoArrow's layout, with each polygon's layer and each tile's place.
//   data/tiles-<region>.bin: uint32 n, n bytes of JSON { region, tiles: [{ file, z, x, y,
//   extent }], layers: [name], arrays: [{ name, type, length }] }, padded to 4 bytes, then the
//   arrays in that order: coords (Int32Array), ringOffsets, polygonOffsets, tileOffsets
//   (Uint32Array: tile t has the polygons tileOffsets[t] .. tileOffsets[t + 1] - 1) and
//   polygonLayers (Uint8Array). data/tiles-regions.json lists the regions.
import { mvtTileFiles, readTile, tilePolygons } from '../../scripts/datasets/polygon_sets.mjs';

export function tileRegions() {
  return [...new Set(mvtTileFiles().map((f) => f.split('/')[0]))];
}

export function encodeRegion(region) {
  const files = mvtTileFiles().filter((f) => f.startsWith(`${region}/`));
  const coords = [], ringOffsets = [0], polygonOffsets = [0], tileOffsets = [0];
  const polygonLayers = [], layers = [], tiles = [];
  for (const file of files) {
    const [z, x, y] = file.split('/')[1].split('.')[0].split('-').map(Number);
    let extent = 4096;
    for (const { layer, extent: e, rings } of tilePolygons(readTile(file), { layers: true })) {
      extent = e;
      if (!layers.includes(layer)) layers.push(layer);
      for (const ring of rings) {
        for (const v of ring) coords.push(v);
        ringOffsets.push(coords.length / 2);
      }
      polygonOffsets.push(ringOffsets.length - 1);
      polygonLayers.push(layers.indexOf(layer));
    }
    tileOffsets.push(polygonOffsets.length - 1);
    tiles.push({ file, z, x, y, extent });
  }
  const arrays = [
    ['coords', Int32Array.from(coords)], ['ringOffsets', Uint32Array.from(ringOffsets)],
    ['polygonOffsets', Uint32Array.from(polygonOffsets)],
    ['tileOffsets', Uint32Array.from(tileOffsets)],
    ['polygonLayers', Uint8Array.from(polygonLayers)],
  ];
  const header = new TextEncoder().encode(JSON.stringify({
    region, tiles, layers,
    arrays: arrays.map(([name, a]) => ({ name, type: a.constructor.name, length: a.length })),
  }));
  const padded = 4 + Math.ceil(header.length / 4) * 4;
  const size = padded + arrays.reduce((s, [, a]) => s + a.byteLength, 0);
  const out = new Uint8Array(size);
  new DataView(out.buffer).setUint32(0, header.length, true);
  out.set(header, 4);
  let at = padded;
  for (const [, a] of arrays) {
    out.set(new Uint8Array(a.buffer, a.byteOffset, a.byteLength), at);
    at += a.byteLength;
  }
  return out;
}

// Every region's file, and data/tiles-regions.json listing the regions in order.
export function buildTileData() {
  const files = {};
  const regions = tileRegions();
  for (const region of regions) files[`data/tiles-${region}.bin`] = encodeRegion(region);
  files['data/tiles-regions.json'] = new TextEncoder().encode(JSON.stringify(regions));
  return files;
}
