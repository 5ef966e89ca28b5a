// triangulatePolygons() and earcut() through the wasm build: the troubles earcut's users meet,
// every coordinate array type, both fill rules, earcut's signature, bad input, and real
// tiles, each result held to the exact checker of support/polygons.js.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import earcutPeer from 'earcut';
import { init, triangulatePolygons, earcut, memoryUsage } from 'geocdt';
import { checkPolygonTriangles } from './support/polygons.js';
import { throwsWith } from './support/throws.js';
import { loadSet } from '../../scripts/datasets/polygon_sets.mjs';

before(() => init());

// throwsWith, returning the error for its properties.
function thrown(fn, Type, pattern) {
  let error;
  throwsWith(() => {
    try {
      fn();
    } catch (e) {
      error = e;
      throw e;
    }
  }, Type, pattern);
  return error;
}

// A batch from polygons given as arrays of rings (flat x, y numbers each).
function batch(polygons, CoordArray = Float64Array) {
  const coords = [], ringOffsets = [0], polygonOffsets = [0];
  for (const rings of polygons) {
    for (const ring of rings) {
      coords.push(...ring);
      ringOffsets.push(coords.length / 2);
    }
    polygonOffsets.push(ringOffsets.length - 1);
  }
  return {
    coords: CoordArray.from(coords), ringOffsets: Uint32Array.from(ringOffsets),
    polygonOffsets: Uint32Array.from(polygonOffsets),
  };
}

const square = [0, 0, 10, 0, 10, 10, 0, 10, 0, 0];
const triangleCount = (r, p) => r.triangleOffsets[p + 1] - r.triangleOffsets[p];

const troubles = {
  'hole touching the shell at a vertex': [square, [0, 0, 3, 2, 2, 3, 0, 0]],
  'hole touching the shell along an edge': [square, [0, 2, 3, 2, 3, 5, 0, 5, 0, 2]],
  'holes touching each other': [square, [2, 2, 5, 2, 5, 5, 2, 2], [5, 5, 8, 5, 8, 8, 5, 5]],
  'overlapping holes': [square, [2, 2, 6, 2, 6, 6, 2, 6, 2, 2], [4, 4, 8, 4, 8, 8, 4, 8, 4, 4]],
  'a hole twice': [square, [2, 2, 6, 2, 6, 6, 2, 6, 2, 2], [2, 2, 6, 2, 6, 6, 2, 6, 2, 2]],
  'a hole outside the shell': [square, [20, 20, 22, 20, 22, 22, 20, 20]],
  'a hole crossing the shell': [square, [8, 4, 12, 4, 12, 6, 8, 6, 8, 4]],
  'a self-tangent figure eight': [[0, 0, 4, 0, 2, 2, 4, 4, 0, 4, 2, 2, 0, 0]],
  'a ring touching its own edge': [[0, 0, 10, 0, 10, 10, 5, 0, 0, 10, 0, 0]],
  'a bow tie': [[0, 0, 4, 4, 4, 0, 0, 4, 0, 0]],
  'a zero-area ring': [[0, 0, 5, 0, 10, 0, 0, 0]],
  'repeated points': [[0, 0, 10, 0, 10, 10, 10, 10, 10, 10, 0, 10, 0, 0]],
  'a spike': [[0, 0, 10, 0, 15, 0, 10, 0, 10, 10, 0, 10, 0, 0]],
  'collinear points along the edges': [[0, 0, 2, 0, 4, 0, 6, 0, 8, 0, 10, 0, 10, 5, 10, 10, 5, 10,
    0, 10, 0, 5, 0, 0]],
  'an island in a lake in an island': [[0, 0, 12, 0, 12, 12, 0, 12, 0, 0],
    [2, 2, 10, 2, 10, 10, 2, 10, 2, 2], [4, 4, 8, 4, 8, 8, 4, 8, 4, 4]],
  'a ring wound twice': [[0, 0, 10, 0, 10, 10, 0, 10, 0, 0, 10, 0, 10, 10, 0, 10, 0, 0]],
  'nothing: a point, a segment, empty rings': [[3, 3], [0, 0, 4, 4], []],
};

for (const fillRule of ['evenodd', 'nonzero']) {
  test(`earcut's troubles, each alone and all in one batch (${fillRule})`, () => {
    for (const [name, rings] of Object.entries(troubles)) {
      const input = batch([rings]);
      const r = triangulatePolygons(input, { fillRule });
      assert.doesNotThrow(() => checkPolygonTriangles(input, r, { fillRule }), name);
    }
    const input = batch(Object.values(troubles));
    checkPolygonTriangles(input, triangulatePolygons(input, { fillRule }), { fillRule });
  });
}

test('a square with a hole: 8 triangles, counter-clockwise with y up', () => {
  const input = batch([[square, [2, 2, 2, 8, 8, 8, 8, 2, 2, 2]]]);
  const r = triangulatePolygons(input);
  assert.equal(triangleCount(r, 0), 8);
  assert.deepEqual(r.extraPoints, new Float64Array(0));
  assert.equal(r.stats.polygons, 1);
  assert.equal(r.stats.smallPath, 1);
  checkPolygonTriangles(input, r);
});

test('crossing rings give extra points after the input points', () => {
  const input = batch([[square], [[0, 0, 4, 4, 4, 0, 0, 4, 0, 0]]]);
  const r = triangulatePolygons(input);
  assert.deepEqual(r.extraPoints, new Float64Array([2, 2]));
  assert.equal(r.stats.general, 1);
  assert.equal(r.stats.crossings, 1);
  const n = input.coords.length / 2;
  assert.ok(r.triangles.includes(n), 'the crossing, index coords.length / 2');
  checkPolygonTriangles(input, r);
});

test('every coordinate array type, open or closed rings, give the same triangles', () => {
  const polygons = [[[0, 0, 100, 0, 100, 100, 0, 100, 0, 0], [20, 20, 20, 80, 80, 80, 80, 20, 20,
    20]], [[200, 0, 300, 50, 200, 100, 250, 50, 200, 0]]];
  const expected = triangulatePolygons(batch(polygons));
  for (const Type of [Int16Array, Int32Array, Uint16Array, Float32Array, Float64Array, Array]) {
    const r = triangulatePolygons(batch(polygons, Type));
    assert.deepEqual(r.triangles, expected.triangles, Type.name);
    assert.deepEqual(r.triangleOffsets, expected.triangleOffsets, Type.name);
  }
  const open = polygons.map((rings) => rings.map((ring) => ring.slice(0, -2)));
  const r = triangulatePolygons(batch(open));
  assert.deepEqual(r.triangleOffsets, expected.triangleOffsets, 'open rings');
  checkPolygonTriangles(batch(open), r);
});

test('nonzero fills what even-odd leaves out', () => {
  const input = batch([[square, [2, 2, 8, 2, 8, 8, 2, 8, 2, 2]]]);  // the hole winds as the shell
  assert.equal(triangleCount(triangulatePolygons(input), 0), 8);
  assert.equal(triangleCount(triangulatePolygons(input, { fillRule: 'nonzero' }), 0), 10);
});

test('earcut(data, holeIndices, dim): the same triangles as triangulatePolygons()', () => {
  const data = [0, 0, 100, 0, 100, 100, 0, 100, 20, 20, 80, 20, 80, 80, 20, 80];
  const indices = earcut(data, [4]);
  assert.ok(indices instanceof Uint32Array);
  assert.deepEqual(indices.extraPoints, new Float64Array(0));
  const r = triangulatePolygons({ coords: data, ringOffsets: [0, 4, 8], polygonOffsets: [0, 2] });
  // (The indices without their extraPoints property, which deepEqual would compare.)
  const indicesOf = (t) => Uint32Array.from(t);
  assert.deepEqual(indicesOf(indices), r.triangles);
  // dim 3: z is carried along, indices are vertex indices.
  const xyz = [];
  for (let i = 0; i < data.length; i += 2) xyz.push(data[i], data[i + 1], i);
  assert.deepEqual(indicesOf(earcut(xyz, [4], 3)), r.triangles);
  assert.deepEqual(indicesOf(earcut(Float32Array.from(data), new Uint32Array([4]))), r.triangles);
  assert.equal(earcut([0, 0, 1, 0, 0, 1]).length, 3);
  assert.equal(earcut([0, 0, 1, 0, 0, 1], null).length, 3);
  // A bow tie: the crossing is an extra point, index data.length / dim.
  const bow = earcut([0, 0, 4, 4, 4, 0, 0, 4]);
  assert.deepEqual(bow.extraPoints, new Float64Array([2, 2]));
  assert.ok(bow.includes(4));
});

test('on valid polygons, earcut (the package) and geocdt fill the same area', () => {
  const polygons = [
    [[0, 0, 100, 0, 100, 100, 0, 100], [20, 20, 20, 80, 80, 80, 80, 20]],
    [[0, 0, 50, 30, 100, 0, 70, 50, 100, 100, 50, 70, 0, 100, 30, 50]],
  ];
  for (const rings of polygons) {
    const data = rings.flat();
    const holes = [];
    let at = rings[0].length / 2;
    for (const ring of rings.slice(1)) {
      holes.push(at);
      at += ring.length / 2;
    }
    const area = (t) => {
      let sum = 0;
      for (let i = 0; i < t.length; i += 3) {
        const [a, b, c] = [t[i], t[i + 1], t[i + 2]];
        sum += Math.abs((data[2 * b] - data[2 * a]) * (data[2 * c + 1] - data[2 * a + 1])
          - (data[2 * b + 1] - data[2 * a + 1]) * (data[2 * c] - data[2 * a]));
      }
      return sum;
    };
    assert.equal(area(earcut(data, holes)), area(earcutPeer(data, holes)));
  }
});

test('bad input: TypeError or RangeError naming the polygon and ring; the module stays usable',
  () => {
    const good = batch([[square], [square, [2, 2, 3, 2, 3, 3, 2, 2]]]);
    const before = memoryUsage().allocatedBytes;
    const bad = (change) => ({ ...good, ...change });
    throwsWith(() => triangulatePolygons(null), TypeError, /takes \{ coords, ringOffsets/);
    throwsWith(() => triangulatePolygons([1, 2]), TypeError, /takes \{ coords/);
    throwsWith(() => triangulatePolygons(bad({ coords: 'xy' })), TypeError, /coords must be/);
    throwsWith(() => triangulatePolygons(bad({ ringOffsets: new Float64Array(2) })), TypeError,
      /ringOffsets must be a Uint32Array/);
    throwsWith(() => triangulatePolygons(good, { fillRule: 'all' }), TypeError,
      /options.fillRule must be 'evenodd' or 'nonzero', got "all"/);
    throwsWith(() => triangulatePolygons(bad({ coords: new Float64Array(3) })), RangeError,
      /coords has an odd length \(3\)/);
    throwsWith(() => triangulatePolygons(bad({ polygonOffsets: [] })), RangeError,
      /polygonOffsets is empty: n polygons take n \+ 1 offsets/);
    const decreasing = bad({ ringOffsets: Uint32Array.from([0, 5, 12, 10]) });
    const e = thrown(() => triangulatePolygons(decreasing), RangeError,
      /polygon 1 ring 1 \(ringOffsets\[2\]\) ends before it starts: ringOffsets\[3\] = 10 is below ringOffsets\[2\] = 12/);
    assert.equal(e.polygon, 1);
    assert.equal(e.ring, 2);
    const past = bad({ ringOffsets: Uint32Array.from([0, 5, 99, 14]) });
    throwsWith(() => triangulatePolygons(past), RangeError,
      /polygon 1 ring 1 \(ringOffsets\[2\]\): ringOffsets\[2\] = 99 is past the 14 points/);
    throwsWith(() => triangulatePolygons(bad({ polygonOffsets: [0, 2, 1] })), RangeError,
      /polygon 1 ends before it starts: polygonOffsets\[2\] = 1 is below polygonOffsets\[1\] = 2/);
    throwsWith(() => triangulatePolygons(bad({ polygonOffsets: [0, 1, 7] })), RangeError,
      /polygon 1: polygonOffsets\[2\] = 7 is past the 3 rings/);
    const coords = Float64Array.from(good.coords);
    coords[23] = NaN;
    const nan = thrown(() => triangulatePolygons(bad({ coords })), RangeError,
      /coords\[23\] \(y of point 11, in polygon 1 ring 1\) is NaN/);
    assert.equal(nan.code, 'InvalidCoordinate');
    assert.equal(nan.polygon, 1);
    coords[23] = 1e200;
    throwsWith(() => triangulatePolygons(bad({ coords })), RangeError, /beyond the supported/);
    throwsWith(() => earcut('data'), TypeError, /earcut\(data, holeIndices, dim\) takes data/);
    throwsWith(() => earcut([0, 0, 1, 0, 1], null, 2), RangeError, /not a multiple of dim = 2/);
    throwsWith(() => earcut([0, 0, 1, 0, 0, 1], [5]), RangeError, /holeIndices\[0\] is 5/);
    throwsWith(() => earcut([0, 0, NaN, 0, 0, 1, 9], null, 3.5), RangeError, /dim must be/);
    throwsWith(() => earcut([0, 0, 1, 0, 0, 1], [], '2'), TypeError, /dim must be a number/);
    throwsWith(() => earcut([0, 0, 1, 0, 0, 1], ['1']), TypeError,
      /holeIndices\[0\] must be a number/);
    throwsWith(() => earcut([[0, 0], [1, 0], [0, 1]]), TypeError,
      /data\[0\] must be a number, got an Array \(data is flat/);
    throwsWith(() => triangulatePolygons(bad({ ringOffsets: Int32Array.from([0, -5, 14]) })),
      RangeError, /ringOffsets\[1\] is -5: below ringOffsets\[0\] = 0/);
    throwsWith(() => earcut([0, 0, NaN, 0, 0, 1]), RangeError,
      /data\[2\] \(x of point 1, in polygon 0 ring 0\) is NaN/);
    // Usable after all that, and nothing left on the heap.
    checkPolygonTriangles(good, triangulatePolygons(good));
    assert.equal(memoryUsage().allocatedBytes, before);
  });

test('no JS work per polygon: 20,000 polygons in one call', () => {
  const polygons = [];
  for (let i = 0; i < 20_000; i++) {
    const x = (i % 200) * 20, y = Math.floor(i / 200) * 20;
    polygons.push([[x, y, x + 10, y, x + 10, y + 10, x, y + 10, x, y]]);
  }
  const input = batch(polygons, Int32Array);
  const r = triangulatePolygons(input);
  assert.equal(r.triangles.length, 6 * 20_000);
  assert.equal(r.stats.smallPath, 20_000);
  checkPolygonTriangles(input, r, { area: false });
});

// Every twelfth real-world tile of @mapbox/mvt-fixtures (18 tiles), and every tenth of the
// Natural Earth countries cut by geojson-vt: the polygons of real tiles, checked one by one
// (ctest checks every tile natively).
function everyNthTile(set, n) {
  const { coords, ringOffsets, polygonOffsets, tileOffsets } = set;
  const out = { coords: [], ringOffsets: [0], polygonOffsets: [0] };
  for (let t = 0; t + 1 < tileOffsets.length; t += n) {
    for (let p = tileOffsets[t]; p < tileOffsets[t + 1]; p++) {
      for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) {
        for (let i = 2 * ringOffsets[r]; i < 2 * ringOffsets[r + 1]; i++) {
          out.coords.push(coords[i]);
        }
        out.ringOffsets.push(out.coords.length / 2);
      }
      out.polygonOffsets.push(out.ringOffsets.length - 1);
    }
  }
  return {
    coords: coords.constructor.from(out.coords), ringOffsets: Uint32Array.from(out.ringOffsets),
    polygonOffsets: Uint32Array.from(out.polygonOffsets),
  };
}

test('real tiles: every polygon exact, by both rules', () => {
  const tiles = everyNthTile(loadSet('tiles'), 12);
  const r = triangulatePolygons(tiles);
  assert.equal(r.stats.crossings, 0);
  checkPolygonTriangles(tiles, r);
  checkPolygonTriangles(tiles, triangulatePolygons(tiles, { fillRule: 'nonzero' }),
    { fillRule: 'nonzero', area: false });
  const cut = everyNthTile(loadSet('geojson-vt'), 10);
  const c = triangulatePolygons(cut);
  assert.ok(c.stats.crossings > 0, 'cut and simplified borders cross');
  checkPolygonTriangles(cut, c);
});
