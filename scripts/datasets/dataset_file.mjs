// Writers for the binary dataset files read by tests/cpp/support/polyline_file.h.
//   .gpl: "GPL1", uint32 P, uint32 count[P], float64 x, y of all points in order.
//   .gpt: "GPT1", uint64 n, float64 x, y of n points.
//   .gpg: "GPG1", uint32 G, uint32 count[G]: polygon g has the next count[g] polylines of
//         the .gpl file of the same name.
// All numbers little-endian.
import { writeFileSync } from 'node:fs';

// polylines: an array of polylines, each an array of [x, y] positions.
export function encodePolylines(polylines) {
  let points = 0;
  for (const line of polylines) points += line.length;
  const header = 8 + 4 * polylines.length;
  const buffer = new ArrayBuffer(header + 16 * points);
  const view = new DataView(buffer);
  view.setUint8(0, 0x47); view.setUint8(1, 0x50); view.setUint8(2, 0x4c); view.setUint8(3, 0x31);
  view.setUint32(4, polylines.length, true);
  let at = header;
  polylines.forEach((line, i) => {
    view.setUint32(8 + 4 * i, line.length, true);
    for (const [x, y] of line) {
      view.setFloat64(at, x, true);
      view.setFloat64(at + 8, y, true);
      at += 16;
    }
  });
  return new Uint8Array(buffer);
}

// xy: a flat array of x, y numbers.
export function encodePoints(xy) {
  const n = Math.floor(xy.length / 2);
  const buffer = new ArrayBuffer(12 + 16 * n);
  const view = new DataView(buffer);
  view.setUint8(0, 0x47); view.setUint8(1, 0x50); view.setUint8(2, 0x54); view.setUint8(3, 0x31);
  view.setBigUint64(4, BigInt(n), true);
  for (let i = 0; i < 2 * n; i++) view.setFloat64(12 + 8 * i, xy[i], true);
  return new Uint8Array(buffer);
}

export function writePolylines(path, polylines) {
  writeFileSync(path, encodePolylines(polylines));
  let points = 0;
  for (const line of polylines) points += line.length;
  return { polylines: polylines.length, points };
}

export function writePoints(path, xy) {
  writeFileSync(path, encodePoints(xy));
  return { points: Math.floor(xy.length / 2) };
}

// ringCounts: how many polylines each polygon has, in order.
export function writePolygons(path, ringCounts) {
  const view = new DataView(new ArrayBuffer(8 + 4 * ringCounts.length));
  [0x47, 0x50, 0x47, 0x31].forEach((byte, i) => view.setUint8(i, byte));
  view.setUint32(4, ringCounts.length, true);
  ringCounts.forEach((count, i) => view.setUint32(8 + 4 * i, count, true));
  writeFileSync(path, new Uint8Array(view.buffer));
  return { polygons: ringCounts.length };
}
