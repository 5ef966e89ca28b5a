// triangulateRaster through the wasm build: the error bound over every pixel of the USGS
// Jacksboro DEM (checked here, independently of the mesher), breaklines crossing each other
// and the raster's edges, no-data holes, tiles that match along their shared borders, a flat
// raster, a single row, one pixel, the bbox, the worker, the CLI, and bad input (a RangeError
// naming it, the module usable afterwards).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { init, triangulate, triangulateRaster } from 'geocdt';
import { createWorker } from 'geocdt/worker';
import { crop, jacksboro } from '../../scripts/usgs-dems.mjs';
import { checkMesh } from './support/invariants.js';
import { orient } from './support/predicates.js';
import { throwsWith } from './support/throws.js';

before(() => init());

const dem = jacksboro();

// The largest |height - surface| over the pixels of each triangle, pixels found by exact
// orientation tests (points in pixel positions), and the pixels no triangle holds.
function pixelErrors(r, { heights, width, height }) {
  const covered = new Uint8Array(width * height);
  let worst = 0;
  const p = r.points;
  for (let t = 0; t < r.triangles.length; t += 3) {
    const v = [r.triangles[t], r.triangles[t + 1], r.triangles[t + 2]];
    const x = v.map((k) => p[2 * k]), y = v.map((k) => p[2 * k + 1]);
    const z = v.map((k) => r.values[k]);
    // A sliver (vertices on a breakline, a crossing ulps off it) gives its weights no digits:
    // its pixels lie on its long edge, which a proper triangle shares.
    const area = orient(x[0], y[0], x[1], y[1], x[2], y[2]);
    const longest = Math.max(...[0, 1, 2].map((k) => (x[(k + 1) % 3] - x[k]) ** 2
      + (y[(k + 1) % 3] - y[k]) ** 2));
    if (!(area > 1e-9 * longest)) continue;
    for (let j = Math.max(0, Math.ceil(Math.min(...y))); j <= Math.min(height - 1,
      Math.floor(Math.max(...y))); j++) {
      for (let i = Math.max(0, Math.ceil(Math.min(...x))); i <= Math.min(width - 1,
        Math.floor(Math.max(...x))); i++) {
        const w = [0, 1, 2].map((k) => orient(x[(k + 1) % 3], y[(k + 1) % 3], x[(k + 2) % 3],
          y[(k + 2) % 3], i, j));
        if (w.some((a) => a < 0)) continue;
        const value = (w[0] * z[0] + w[1] * z[1] + w[2] * z[2]) / (w[0] + w[1] + w[2]);
        worst = Math.max(worst, Math.abs(value - heights[j * width + i]));
        covered[j * width + i] = 1;
      }
    }
  }
  return { worst, uncovered: covered.reduce((n, c) => n + 1 - c, 0) };
}

function withinBound(r, raster, maxError) {
  const { worst, uncovered } = pixelErrors(r, raster);
  assert.equal(uncovered, 0, 'every pixel is in a triangle');
  assert.ok(worst <= maxError * (1 + 1e-9), `largest error ${worst} within ${maxError}`);
  assert.ok(r.stats.maxError <= maxError && r.stats.maxError >= worst * (1 - 1e-9));
}

test('every pixel of the Jacksboro DEM is within maxError', () => {
  for (const maxError of [1, 5, 20]) {
    const r = triangulateRaster(dem, { maxError });
    checkMesh(r);
    withinBound(r, dem, maxError);
    assert.equal(r.values.length, r.points.length / 2);
    assert.equal(r.stats.triangles, r.triangles.length / 3);
  }
});

test('decimate removes inserted vertices the bound no longer needs, keeping it', () => {
  for (const maxError of [5, 20]) {
    const plain = triangulateRaster(dem, { maxError });
    const r = triangulateRaster(dem, { maxError, decimate: true });
    checkMesh(r);
    withinBound(r, dem, maxError);
    assert.equal(plain.stats.decimated, 0);
    assert.ok(r.stats.decimated > 0);
    assert.equal(r.values.length, r.points.length / 2);
    assert.ok(r.triangles.length < 0.95 * plain.triangles.length,
      `${r.triangles.length / 3} triangles against ${plain.triangles.length / 3}`);
  }
});

test('breaklines cross each other and the raster\'s edges', () => {
  const raster = crop(dem, 120);
  const breaklines = [
    [-10, 30, 60.5, 70.25, 130, 90],   // enters at x = 0, leaves at x = 119
    [20.5, 110.5, 100.25, 5.75],       // crosses the first
    [30, 30, 80, 30, 80, 80, 30, 30],  // closed: it bounds nothing
  ];
  const breaklineHeights = [NaN, NaN, NaN, 700, 800, NaN, NaN, NaN, NaN];
  const r = triangulateRaster(raster, { maxError: 3, breaklines, breaklineHeights });
  checkMesh(r);
  withinBound(r, raster, 3);
  const vertexAt = (x, y) => {
    for (let v = 0; v < r.points.length / 2; v++) {
      if (r.points[2 * v] === x && r.points[2 * v + 1] === y) return v;
    }
    return -1;
  };
  // Given heights where given, the raster's (bilinear) elsewhere.
  assert.equal(r.values[vertexAt(20.5, 110.5)], 700);
  assert.equal(r.values[vertexAt(100.25, 5.75)], 800);
  const v = vertexAt(60.5, 70.25);
  const h = (i, j) => raster.heights[j * 120 + i];
  const bilinear = 0.5 * 0.75 * h(60, 70) + 0.5 * 0.75 * h(61, 70) + 0.5 * 0.25 * h(60, 71)
    + 0.5 * 0.25 * h(61, 71);
  assert.ok(Math.abs(r.values[v] - bilinear) < 1e-9);
  // Each breakline's edges are constrained and name it; the closed one leaves no inside.
  const named = new Set(r.sources);
  assert.deepEqual([...named].sort(), [0, 1, 2]);
  const cut = [];
  for (let k = 0; k < r.points.length / 2; k++) {
    if (r.points[2 * k] === 0 || r.points[2 * k] === 119) cut.push(r.points[2 * k + 1]);
  }
  assert.ok(cut.some((y) => Math.abs(y - (30 + 10 * 40.25 / 70.5)) < 1e-9), 'enters at x = 0');
});

test('no-data holes are left out, their boundary constrained', () => {
  const raster = crop(dem, 100);
  const heights = Float32Array.from(raster.heights);
  for (let j = 0; j < 100; j++) {
    for (let i = 0; i < 100; i++) {
      if ((i - 40) ** 2 + (j - 55) ** 2 < 200 || i + j < 15) heights[j * 100 + i] = -32768;
      if (i === 80 && j > 20 && j < 60) heights[j * 100 + i] = NaN;
    }
  }
  const holey = { heights, width: 100, height: 100 };
  const r = triangulateRaster(holey, { maxError: 2, noData: -32768 });
  checkMesh(r, {}, { keepAll: false });
  let boundary = 0;
  for (let e = 0; e < r.halfedges.length; e++) {
    assert.equal(r.constrained[e] === 1, r.halfedges[e] < 0);
    boundary += r.halfedges[e] < 0;
  }
  assert.ok(boundary > 50);
  assert.ok([...r.sources].every((s) => s === 0));  // no breaklines: the boundary is number 0
  assert.ok(r.values.every(Number.isFinite));
  // Every triangle lies in cells whose corners have data, and the pixels of those cells are
  // all covered within the bound.
  const valid = (i, j) => Number.isFinite(heights[j * 100 + i]) && heights[j * 100 + i] !== -32768;
  for (let t = 0; t < r.triangles.length; t += 3) {
    const c = [0, 1, 2].map((k) => r.triangles[t + k]);
    const cx = c.reduce((s, k) => s + r.points[2 * k], 0) / 3;
    const cy = c.reduce((s, k) => s + r.points[2 * k + 1], 0) / 3;
    const i = Math.floor(cx), j = Math.floor(cy);
    assert.ok(valid(i, j) && valid(i + 1, j) && valid(i, j + 1) && valid(i + 1, j + 1));
  }
  const { worst } = pixelErrors(r, holey);
  assert.ok(worst <= 2);
});

test('a closed breakline bounds nothing where pixels have no data elsewhere', () => {
  const raster = crop(dem, 60);
  const heights = Float64Array.from(raster.heights);
  heights[0] = -32768;  // one pixel without data: the mesh covers the area with data only
  const holey = { heights, width: 60, height: 60 };
  // Closed, and closed with its first point repeated at the end (once cut into a ring).
  for (const ring of [[10, 10, 40, 10, 25, 35, 10, 10], [10, 10, 40, 10, 25, 35, 10, 10, 10, 10]]) {
    const r = triangulateRaster(holey, { maxError: 5, noData: -32768, breaklines: [ring] });
    checkMesh(r, {}, { keepAll: false });
    const { worst, uncovered } = pixelErrors(r, holey);
    assert.equal(uncovered, 1, `only the pixel without data left out (${ring.length / 2} points)`);
    assert.ok(worst <= 5);
  }
});

test('tiles that share a border get the same vertices along it', () => {
  // Two tiles side by side sharing column 150, in map coordinates x = column, y = -row.
  const tile = (left, width) => {
    const heights = new Int16Array(width * dem.height);
    for (let j = 0; j < dem.height; j++) {
      heights.set(dem.heights.subarray(j * dem.width + left, j * dem.width + left + width),
        j * width);
    }
    return triangulateRaster({ heights, width, height: dem.height },
      { maxError: 4, bbox: [left, -(dem.height - 1), left + width - 1, 0] });
  };
  const onColumn = (r, x) => {
    const out = [];
    for (let v = 0; v < r.points.length / 2; v++) {
      if (r.points[2 * v] === x) out.push(`${r.points[2 * v + 1]} ${r.values[v]}`);
    }
    return out.sort();
  };
  const a = tile(0, 151), b = tile(150, 201);
  const left = onColumn(a, 150), right = onColumn(b, 150);
  assert.ok(left.length > 10);
  assert.deepEqual(left, right);
  checkMesh(a, {}, { delaunay: false });  // mapped: rounding may break cocircular ties
});

test('elevation tiles made a pixel larger from their neighbours match (API.md\'s recipe)', () => {
  // The DEM as 64 x 64 Terrain-RGB tiles, each 1000 units a side, y = -1000 * row of tiles.
  const size = 64, extent = 1000;
  const rgb = (tx, ty) => {
    const bytes = new Uint8Array(4 * size * size);
    for (let y = 0; y < size; y++) {
      for (let x = 0; x < size; x++) {
        const h = dem.heights[(ty * size + y) * dem.width + tx * size + x];
        const v = Math.round((h + 10000) * 10), i = 4 * (y * size + x);
        bytes.set([v >> 16, (v >> 8) & 255, v & 255, 255], i);
      }
    }
    return bytes;
  };
  const mesh = (tx, ty, backfill = false) => {
    const tile = rgb(tx, ty);
    // backfill: the last column and row copied from the tile itself, as martini's examples do
    const right = backfill ? tile : rgb(tx + 1, ty), below = backfill ? tile : rgb(tx, ty + 1);
    const belowRight = backfill ? tile : rgb(tx + 1, ty + 1);
    const n = size + 1, heights = new Float32Array(n * n);
    for (let y = 0; y < n; y++) {
      for (let x = 0; x < n; x++) {
        const from = y < size ? (x < size ? tile : right) : (x < size ? below : belowRight);
        const i = backfill ? 4 * (Math.min(y, size - 1) * size + Math.min(x, size - 1))
          : 4 * ((y % size) * size + (x % size));
        heights[y * n + x] = -10000 + 0.1 * (from[i] * 65536 + from[i + 1] * 256 + from[i + 2]);
      }
    }
    const west = tx * extent, east = west + extent, north = -ty * extent, south = north - extent;
    const h = (east - west) / (2 * size), v = (north - south) / (2 * size);
    return triangulateRaster({ heights, width: n, height: n },
      { maxError: 3, bbox: [west + h, south - v, east + h, north - v] });
  };
  const along = (r, axis, at) => {
    const out = [];
    for (let k = 0; k < r.points.length / 2; k++) {
      if (r.points[2 * k + axis] === at) out.push(`${r.points[2 * k + 1 - axis]} ${r.values[k]}`);
    }
    return out.sort();
  };
  const tile = mesh(1, 1), right = mesh(2, 1), below = mesh(1, 2);
  const seamX = 2 * extent + extent / (2 * size), seamY = -2 * extent - extent / (2 * size);
  const east = along(tile, 0, seamX), south = along(tile, 1, seamY);
  assert.ok(east.length > 3 && south.length > 3, `${east.length}, ${south.length} seam vertices`);
  assert.deepEqual(east, along(right, 0, seamX));
  assert.deepEqual(south, along(below, 1, seamY));
  // Backfilled, the same seam takes the tile's own last column: the neighbours' meshes part.
  assert.notDeepEqual(along(mesh(1, 1, true), 0, seamX), along(right, 0, seamX));
});

test('a flat raster is two triangles, a single row its profile, one pixel one vertex', () => {
  const flat = triangulateRaster({ heights: new Float32Array(64 * 48).fill(7), width: 64,
    height: 48 });
  assert.equal(flat.triangles.length, 6);
  assert.deepEqual([...flat.values], [7, 7, 7, 7]);
  const plane = [];
  for (let j = 0; j < 20; j++) for (let i = 0; i < 30; i++) plane.push(0.3 * i - 0.7 * j + 5);
  assert.equal(triangulateRaster({ heights: plane, width: 30, height: 20 }).triangles.length, 6);

  const row = dem.heights.subarray(0, dem.width);
  const profile = triangulateRaster({ heights: row, width: dem.width, height: 1 },
    { maxError: 2 });
  assert.equal(profile.triangles.length, 0);
  const n = profile.points.length / 2;
  assert.ok(n >= 2 && n < dem.width);
  for (let k = 0; k + 1 < n; k++) {
    const x0 = profile.points[2 * k], x1 = profile.points[2 * k + 2];
    for (let x = x0 + 1; x < x1; x++) {
      const z = profile.values[k] + (profile.values[k + 1] - profile.values[k]) * (x - x0)
        / (x1 - x0);
      assert.ok(Math.abs(z - row[x]) <= 2);
    }
  }
  const one = triangulateRaster({ heights: [42], width: 1, height: 1 });
  assert.deepEqual([...one.points], [0, 0]);
  assert.deepEqual([...one.values], [42]);
});

test('bbox maps pixel positions; limits stop at the largest error first', () => {
  const raster = crop(dem, 64);
  const r = triangulateRaster(raster, { maxError: 3, bbox: [10, 20, 73, 83] });
  assert.ok(r.points.every((x, i) => (i % 2 ? x >= 20 && x <= 83 : x >= 10 && x <= 73)));
  checkMesh(r, {}, { delaunay: false });
  const limited = triangulateRaster(raster, { maxTriangles: 500 });
  assert.ok(limited.triangles.length / 3 <= 500 && limited.triangles.length / 3 >= 498);
  const few = triangulateRaster(raster, { maxVertices: 100 });
  assert.equal(few.points.length / 2, 100);
  withinBound(few, raster, few.stats.maxError);
});

// Pixel (0, 0) is at (minX, maxY): a single column at minX, a single row at maxY, and their
// bbox may be flat that way.
test('a single row, a single column and one pixel land on the bbox\'s north-west', () => {
  const row = { heights: [5, 0, 9], width: 3, height: 1 };
  const column = { ...row, width: 1, height: 3 };
  const points = (raster, bbox) => Array.from(triangulateRaster(raster, { bbox }).points);
  assert.deepEqual(points(row, [1, 2, 3, 4]), [1, 4, 2, 4, 3, 4]);
  assert.deepEqual(points(row, [1, 4, 3, 4]), [1, 4, 2, 4, 3, 4]);
  assert.deepEqual(points(column, [1, 2, 3, 4]), [1, 4, 1, 3, 1, 2]);
  assert.deepEqual(points(column, [1, 2, 1, 4]), [1, 4, 1, 3, 1, 2]);
  assert.deepEqual(points({ heights: [5], width: 1, height: 1 }, [1, 2, 3, 4]), [1, 4]);
  assert.deepEqual(points({ heights: [5], width: 1, height: 1 }, [1, 2, 1, 2]), [1, 2]);
  throwsWith(() => points(row, [1, 2, 1, 4]), RangeError, /minX < maxX and minY <= maxY/);
});

test('minAngle refines and keeps the bound', () => {
  const raster = crop(dem, 100);
  const r = triangulateRaster(raster, { maxError: 5, minAngle: 20 });
  checkMesh(r);
  withinBound(r, raster, 5);
  assert.ok(r.stats.steinerPoints > 0);
  let worst = 180;
  for (let t = 0; t < r.triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = r.triangles[t + k], b = r.triangles[t + (k + 1) % 3];
      const c = r.triangles[t + (k + 2) % 3];
      const ux = r.points[2 * b] - r.points[2 * a], uy = r.points[2 * b + 1] - r.points[2 * a + 1];
      const vx = r.points[2 * c] - r.points[2 * a], vy = r.points[2 * c + 1] - r.points[2 * a + 1];
      worst = Math.min(worst, Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy)
        * 180 / Math.PI);
    }
  }
  assert.ok(worst >= 20 - 1e-9, `smallest angle ${worst}`);
  assert.equal(r.stats.refineSkipped, 0);
  // Two breaklines a hair apart: their gap is not filled with triangles its width, and the
  // thin triangles left there are counted.
  const hairline = triangulateRaster(raster, { maxError: 5, minAngle: 20,
    breaklines: [[3.3, 5.7, 95.1, 80.2], [3.3, 5.7001, 95.1, 80.2001]] });
  checkMesh(hairline);
  withinBound(hairline, raster, 5);
  assert.ok(hairline.stats.refineSkipped > 0);
  assert.ok(hairline.stats.steinerPoints < r.stats.steinerPoints + 20000,
    `${hairline.stats.steinerPoints} Steiner points`);
});

test('bad input is a clear RangeError or TypeError, and the module stays usable', () => {
  const ok = { heights: new Float32Array(12), width: 4, height: 3 };
  const nan = Float64Array.from(ok.heights);
  nan[6] = NaN;
  throwsWith(() => triangulateRaster({ ...ok, heights: nan }), RangeError,
    /heights\[6\] \(column 2, row 1\) is NaN/);
  throwsWith(() => triangulateRaster({ ...ok, width: 5 }), RangeError,
    /12 numbers, but a 5 x 3 raster has 15/);
  throwsWith(() => triangulateRaster({ ...ok, height: 2.5 }), RangeError, /raster.height/);
  throwsWith(() => triangulateRaster(ok, { maxError: -1 }), RangeError, /maxError.*-1/);
  throwsWith(() => triangulateRaster(ok, { maxError: NaN }), RangeError, /maxError/);
  throwsWith(() => triangulateRaster(ok, { minAngle: 60 }), RangeError, /minAngle/);
  throwsWith(() => triangulateRaster(ok, { bbox: [1, 0, 0, 1] }), RangeError, /bbox/);
  throwsWith(() => triangulateRaster(ok, { bbox: [0, 0, 0, 1] }), RangeError,
    /must have minX < maxX and minY < maxY/);
  throwsWith(() => triangulateRaster(ok, { bbox: [0, 0, 5e-324, 1] }), RangeError,
    /bbox is too narrow for 4 columns: columns 0 and 1 land on the same x/);
  throwsWith(() => triangulateRaster(ok, { bbox: [0, 1, 1, 1 + 2 ** -52] }), RangeError,
    /bbox is too low for 3 rows/);
  throwsWith(() => triangulateRaster(ok, { bbox: [0, 0, 2e150, 1] }), RangeError,
    /bbox\[2\] is 2e\+150, beyond the supported/);
  throwsWith(() => triangulateRaster(ok, { breaklines: [[0, 0, 1, 1]],
    breaklineHeights: [Infinity, 1] }), RangeError, /breaklineHeights\[0\] is Infinity/);
  throwsWith(() => triangulateRaster(ok, { breaklines: [[0, 0, 1, 1]],
    breaklineHeights: [[1, 1]] }), TypeError, /breaklineHeights must be flat/);
  throwsWith(() => triangulateRaster(ok, { maxTriangles: 0 }), RangeError, /maxTriangles/);
  throwsWith(() => triangulateRaster(ok, { breaklines: [[0, 0, NaN, 1]] }), RangeError,
    /breaklines\[0\]\[2\] \(x of point 1 of breakline 0\) is NaN/);
  throwsWith(() => triangulateRaster(ok, { breaklines: [[0, 0, 1, 1]], breaklineHeights: [1] }),
    RangeError, /breaklineHeights has 1 numbers for 2 points/);
  throwsWith(() => triangulateRaster({ heights: ['1'], width: 1, height: 1 }), TypeError,
    /raster.heights\[0\] must be a number/);
  throwsWith(() => triangulateRaster(new Float32Array(4)), TypeError, /heights, width, height/);
  throwsWith(() => triangulateRaster(ok, { maxError: '1' }), TypeError, /maxError/);
  throwsWith(() => triangulateRaster(ok, { decimate: 1 }), TypeError,
    /options.decimate must be true or false, got number/);
  // Still usable, for both calls.
  assert.equal(triangulateRaster(ok).triangles.length, 6);
  assert.equal(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length, 3);
});

test('the worker answers triangulateRaster with transferred arrays', async () => {
  const worker = createWorker();
  try {
    const heights = Float32Array.from(crop(dem, 65).heights);
    const r = await worker.triangulateRaster({ heights, width: 65, height: 65 },
      { maxError: 2 });
    assert.equal(heights.length, 0, 'the heights were transferred');
    assert.ok(r.values instanceof Float64Array && r.triangles.length > 6);
    await assert.rejects(worker.triangulateRaster({ heights: [1], width: 2, height: 1 }),
      RangeError);
  } finally {
    worker.terminate();
  }
});

test('the CLI meshes an ASCII grid with its NODATA_value and coordinates', () => {
  const folder = mkdtempSync(join(tmpdir(), 'geocdt-terrain-'));
  try {
    const rows = [];
    const raster = crop(dem, 40);
    for (let j = 0; j < 40; j++) {
      rows.push(Array.from(raster.heights.subarray(j * 40, j * 40 + 40),
        (h, i) => (i < 3 && j < 3 ? -9999 : h)).join(' '));
    }
    const grid = join(folder, 'dem.asc');
    writeFileSync(grid, `ncols 40\nnrows 40\nxllcorner 1000\nyllcorner 2000\ncellsize 30\n`
      + `NODATA_value -9999\n${rows.join('\n')}\n`);
    const out = join(folder, 'tin.geojson');
    const cli = fileURLToPath(new URL('../../web/cli.js', import.meta.url));
    const run = spawnSync(process.execPath, [cli, grid, '-o', out, '--max-error', '3',
      '--stats'], { encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    assert.match(run.stderr, /maxError/);
    const fc = JSON.parse(readFileSync(out, 'utf8'));
    assert.ok(fc.features.length > 10);
    for (const f of fc.features) {
      for (const [x, y, z] of f.geometry.coordinates[0]) {
        assert.ok(x >= 1015 && x <= 1015 + 39 * 30 && y >= 2015 && y <= 2015 + 39 * 30);
        assert.ok(Number.isFinite(z));
      }
    }
    const bad = spawnSync(process.execPath, [cli, grid, '--max-error', 'x'], { encoding: 'utf8' });
    assert.equal(bad.status, 2);
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
});
