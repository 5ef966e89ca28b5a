// The threaded build in Node, run by threads-2.test.js and threads-4.test.js (each file is a
// process of its own, and init() loads one build per process). Every result goes through the
// invariant checker and is compared with the single-threaded build's, loaded beside it.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { feature } from 'topojson-client';
import { init, triangulate, triangulatePolygons, Triangulation, voronoi } from 'geocdt';
import createGeocdtModule from '../../../web/dist/geocdt.mjs';
import { createApi } from '../../../web/api.js';
import { instantiateCompiled } from '../../../web/warm-up.js';
import { checkMesh } from './invariants.js';
import { checkConstraints } from './constraints.js';
import { gaussianClusters, lattice, uniform } from './inputs.js';
import { loadSet } from '../../../scripts/datasets/polygon_sets.mjs';

const require = createRequire(import.meta.url);

// The single-threaded build, as a second API in this process.
const single = createApi(async () => {
  const bytes = readFileSync(new URL('../../../web/dist/geocdt.wasm', import.meta.url));
  return { wasm: await instantiateCompiled(createGeocdtModule, await WebAssembly.compile(bytes)),
    threads: 1 };
});

// The triangles as sorted strings, each turned to start at its least vertex.
function triangleSet(r) {
  const set = [];
  for (let t = 0; t < r.triangles.length; t += 3) {
    const c = [r.triangles[t], r.triangles[t + 1], r.triangles[t + 2]];
    const k = c.indexOf(Math.min(...c));
    set.push(`${c[k]},${c[(k + 1) % 3]},${c[(k + 2) % 3]}`);
  }
  return set.sort();
}

function naturalEarth50mRings() {
  const topology = JSON.parse(
    readFileSync(require.resolve('world-atlas/countries-50m.json'), 'utf8'));
  const polylines = [];
  for (const f of feature(topology, topology.objects.countries).features) {
    const parts = f.geometry.type === 'Polygon' ? [f.geometry.coordinates] : f.geometry.coordinates;
    for (const rings of parts) {
      for (const ring of rings) polylines.push(Float64Array.from(ring.flat()));
    }
  }
  return { polylines };
}

export function threadsSuite(threads) {
  before(async () => {
    await assert.rejects(() => init({ threads: 0 }), RangeError);
    await assert.rejects(() => init({ threads: 2.5 }), RangeError);
    await assert.rejects(() => init({ threads: 'all' }), TypeError);
    await init({ threads });
    await single.init();
  });

  // Without cocircular points, one thread's triangles; with them, a Delaunay triangulation.
  const same = (input, generalPosition) => {
    const r = triangulate(input);
    const one = single.triangulate(input);
    assert.equal(r.stats.threads, threads, 'each strip on a thread of its own');
    assert.equal(one.stats.threads, 1);
    checkMesh(r, input);
    assert.deepEqual(r.inputToVertex, one.inputToVertex);
    assert.deepEqual(r.points, one.points);
    assert.equal(r.triangles.length, one.triangles.length);
    if (generalPosition) assert.deepEqual(triangleSet(r), triangleSet(one));
    return r;
  };

  test(`polygons of the real-world tiles on ${threads} threads: one thread's arrays`, () => {
    const { coords, ringOffsets, polygonOffsets } = loadSet('tiles');
    const input = { coords, ringOffsets, polygonOffsets };
    const r = triangulatePolygons(input);
    const one = single.triangulatePolygons(input);
    assert.equal(r.stats.threads, threads, 'each range of polygons on a thread of its own');
    assert.equal(one.stats.threads, 1);
    assert.deepEqual(r.triangles, one.triangles);
    assert.deepEqual(r.extraPoints, one.extraPoints);
    assert.deepEqual(r.triangleOffsets, one.triangleOffsets);
  });

  test(`uniform points on ${threads} threads: one thread's triangles`, () => {
    same({ points: uniform(150_000, 7) }, true);
  });

  test(`clustered points on ${threads} threads: one thread's triangles`, () => {
    same({ points: gaussianClusters(150_000, 8) }, true);
  });

  test(`a lattice on ${threads} threads (cocircular everywhere) is Delaunay`, () => {
    same({ points: lattice(300) }, false);
  });

  test(`Natural Earth 50m country rings on ${threads} threads`, () => {
    // (The constraint checker, which takes half a minute here, runs on 110m in
    // constraints.test.js; here the result is compared with one thread's.)
    const input = naturalEarth50mRings();
    const r = triangulate(input, { insideFlags: true });
    const one = single.triangulate(input, { insideFlags: true });
    assert.equal(r.stats.threads, threads);
    checkMesh(r, input);
    assert.deepEqual(r.inputToVertex, one.inputToVertex);
    assert.deepEqual(r.points, one.points);
    assert.equal(r.stats.crossings, one.stats.crossings);
    const constrainedEdges = (m) => Array.from(m.constraintEdges, (e) => {
      const u = m.triangles[e], v = m.triangles[e % 3 === 2 ? e - 2 : e + 1];
      return u < v ? `${u}-${v}` : `${v}-${u}`;
    }).sort();
    assert.deepEqual(constrainedEdges(r), constrainedEdges(one));
    assert.deepEqual(triangleSet(r), triangleSet(one));
    const insideSet = (m) => triangleSet({
      triangles: m.triangles.filter((_, i) => m.inside[Math.floor(i / 3)]) });
    assert.deepEqual(insideSet(r), insideSet(one));
  });

  test(`a Triangulation's first batch of points on ${threads} threads`, () => {
    const points = uniform(120_000, 9);
    const t = new Triangulation();
    const ids = t.insertPoints(points);
    assert.equal(t.stats.threads, threads);
    assert.deepEqual(triangleSet(t.results()), triangleSet(single.triangulate({ points })));
    const line = [0, 0, 1000, 1000];
    const lineIds = t.insertPolyline(line);
    const r = { ...t.results({ segmentSources: true }),
      inputToVertex: Uint32Array.from([...ids, ...lineIds]) };
    const input = { points, polylines: [line] };
    checkMesh(r, input);
    checkConstraints(r, input);
    t.dispose();
  });

  // The sites' triangulation runs on the threads; without cocircular sites, the cells are one
  // thread's, to the bit.
  test(`Voronoi cells of uniform sites on ${threads} threads: one thread's cells`, () => {
    const points = uniform(100_000, 11);
    for (const clip of [[0, 0, 1000, 1000], 'hull']) {
      const r = voronoi({ points }, { clip });
      const one = single.voronoi({ points }, { clip });
      assert.equal(r.stats.threads, threads);
      assert.equal(one.stats.threads, 1);
      for (const field of ['coords', 'ringOffsets', 'polygonOffsets', 'siteOffsets']) {
        assert.deepEqual(r[field], one[field], field);
      }
    }
  });

  test(`a small call stays on one thread (${threads} asked)`, () => {
    assert.equal(triangulate({ points: uniform(10_000, 10) }).stats.threads, 1);
  });
}
