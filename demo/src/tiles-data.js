// Reads a region of the tiles page (demo/scripts/bundle-tiles.mjs writes them): the header,
// then the typed arrays, views on the fetched buffer.
const TYPES = { Int32Array, Uint32Array, Uint8Array };

export function decodeRegion(buffer) {
  const view = new DataView(buffer);
  const length = view.getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  let at = 4 + Math.ceil(length / 4) * 4;
  const region = { name: header.region, tiles: header.tiles, layers: header.layers };
  for (const { name, type, length: n } of header.arrays) {
    const Type = TYPES[type];
    region[name] = new Type(buffer, at, n);
    at += n * Type.BYTES_PER_ELEMENT;
  }
  return region;
}

// Where each tile goes on the page: its column and row in the region's grid, in tile units.
export function tileGrid(tiles) {
  const minX = Math.min(...tiles.map((t) => t.x)), minY = Math.min(...tiles.map((t) => t.y));
  const columns = Math.max(...tiles.map((t) => t.x)) - minX + 1;
  const rows = Math.max(...tiles.map((t) => t.y)) - minY + 1;
  return { place: tiles.map((t) => [t.x - minX, t.y - minY]), columns, rows };
}

// Polygon p as earcut takes it: its points (flat x, y, from the region's coords) and the
// vertex index where each hole starts.
export function earcutPolygon(region, p) {
  const { coords, ringOffsets, polygonOffsets } = region;
  const first = ringOffsets[polygonOffsets[p]];
  const data = coords.subarray(2 * first, 2 * ringOffsets[polygonOffsets[p + 1]]);
  const holes = [];
  for (let r = polygonOffsets[p] + 1; r < polygonOffsets[p + 1]; r++) {
    holes.push(ringOffsets[r] - first);
  }
  return { data, holes, first };
}
