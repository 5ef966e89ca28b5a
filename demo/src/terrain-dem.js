// Reads the bundled elevation model (demo/scripts/bundle-dem.mjs writes it).
export function decodeDem(buffer) {
  const view = new DataView(buffer);
  const magic = String.fromCharCode(...new Uint8Array(buffer, 0, 4));
  if (magic !== 'DEM1') throw new Error('not a DEM1 file');
  const width = view.getUint32(4, true), height = view.getUint32(8, true);
  const bbox = [0, 1, 2, 3].map((i) => view.getFloat64(12 + 8 * i, true));
  const heights = new Int16Array(width * height);
  for (let i = 0; i < heights.length; i++) heights[i] = view.getInt16(44 + 2 * i, true);
  return { width, height, bbox, heights };
}
