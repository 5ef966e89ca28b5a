#!/usr/bin/env node
// Writes the USGS elevation models (Debian's python-matplotlib-data) as .grs rasters for the
// C++ tests and benchmarks, read by tests/cpp/support/raster_file.h:
//   .grs  raster:  "GRS1", uint32 width, uint32 height, then float64 heights row by row
// (little-endian), one file each: jacksboro.grs (403 x 344 metres), topobathy.grs (120 x 91).
// Usage: node scripts/datasets/usgs_dems.mjs [output folder, default build/data]
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { jacksboro, topobathy } from '../usgs-dems.mjs';

const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');

function encodeRaster({ heights, width, height }) {
  const bytes = new Uint8Array(12 + 8 * width * height);
  const view = new DataView(bytes.buffer);
  bytes.set([0x47, 0x52, 0x53, 0x31]);
  view.setUint32(4, width, true);
  view.setUint32(8, height, true);
  heights.forEach((h, i) => view.setFloat64(12 + 8 * i, h, true));
  return bytes;
}

const out = resolve(process.argv[2] ?? join(repoRoot, 'build', 'data'));
mkdirSync(out, { recursive: true });
for (const [name, dem] of [['jacksboro', jacksboro()], ['topobathy', topobathy()]]) {
  writeFileSync(join(out, `${name}.grs`), encodeRaster(dem));
  console.log(`${name}.grs: ${dem.width} x ${dem.height}`);
}
