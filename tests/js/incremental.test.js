// The Triangulation class: incremental insertion, locate(), results(), dispose().
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { init, triangulate, Triangulation } from 'geocdt';
import { checkMesh } from './support/invariants.js';
import { lattice, uniform } from './support/inputs.js';

const runModule = (script) => execFileSync(process.execPath,
  ['--input-type=module', '-e', script], { encoding: 'utf8' });

before(() => init());

// Triangles as sets of coordinate triples, independent of vertex numbering.
function triangleSet(r) {
  const set = new Set();
  for (let t = 0; t < r.triangles.length; t += 3) {
    const corners = [0, 1, 2].map((k) => {
      const v = r.triangles[t + k];
      return `${r.points[2 * v]},${r.points[2 * v + 1]}`;
    });
    set.add(corners.sort().join(' '));
  }
  return set;
}

test('before init() the API says what to do', () => {
  const script = "import { triangulate } from 'geocdt'; "
    + 'try { triangulate({}); } catch (e) { console.log(e.message); }';
  const out = runModule(script);
  assert.match(out, /`await init\(\)` first/);
});

test('inserting in batches gives the one-shot triangulation', () => {
  const xy = uniform(6_000, 21);
  const t = new Triangulation();
  const ids = [];
  for (let start = 0; start < xy.length; start += 2_000) {
    const batch = t.insertPoints(xy.subarray(start, start + 2_000));
    assert.equal(batch.length, 1_000);
    ids.push(...batch);
    const r = t.results();
    checkMesh({ ...r, inputToVertex: Uint32Array.from(ids) },
      { points: xy.subarray(0, start + 2_000) });
  }
  const whole = t.results();
  assert.equal(t.vertexCount, 6_000);
  assert.equal(t.triangleCount, whole.triangles.length / 3);
  assert.deepEqual(triangleSet(whole), triangleSet(triangulate({ points: xy })));
  t.dispose();
});

test('results() is a copy: later insertions do not change it', () => {
  const t = new Triangulation();
  t.insertPoints([0, 0, 10, 0, 0, 10]);
  const before = t.results();
  t.insertPoints([3, 3, 10, 10]);
  assert.equal(before.triangles.length, 3);
  assert.equal(t.results().triangles.length, 12);
  t.dispose();
});

test('duplicates return the existing vertex id', () => {
  const t = new Triangulation();
  const a = t.insertPoints([0, 0, 1, 0, 0, 1]);
  const b = t.insertPoints([1, 0, 5, 5, 0, 0]);
  assert.deepEqual(Array.from(b), [a[1], 3, a[0]]);
  assert.equal(t.vertexCount, 4);
  assert.equal(t.stats.duplicates, 2);
  t.dispose();
});

test('locate() finds faces, edges, vertices and the outside', () => {
  const t = new Triangulation();
  assert.deepEqual(t.locate(0, 0), { kind: 'empty', triangle: -1, vertices: [] });
  const ids = t.insertPoints(lattice(5).map((v) => 2 * v));  // even coordinates: exact midpoints
  const r = t.results();

  for (let tri = 0; tri < r.triangles.length / 3; tri++) {
    const corner = (k) => r.triangles[3 * tri + k];
    const cx = (r.points[2 * corner(0)] + r.points[2 * corner(1)] + r.points[2 * corner(2)]) / 3;
    const cy = (r.points[2 * corner(0) + 1] + r.points[2 * corner(1) + 1]
      + r.points[2 * corner(2) + 1]) / 3;
    const hit = t.locate(cx, cy);
    assert.equal(hit.kind, 'face');
    assert.equal(hit.triangle, tri);
    assert.deepEqual(new Set(hit.vertices), new Set([corner(0), corner(1), corner(2)]));
  }

  const v = t.locate(4, 6);
  assert.equal(v.kind, 'vertex');
  assert.deepEqual(v.vertices, [ids[2 * 5 + 3]]);
  const tri = v.triangle;
  assert.ok(Array.from(r.triangles.subarray(3 * tri, 3 * tri + 3)).includes(v.vertices[0]));

  const e = t.locate(4, 5);  // midpoint of the lattice edge (4, 4)-(4, 6)
  assert.equal(e.kind, 'edge');
  assert.deepEqual(new Set(e.vertices), new Set([ids[2 * 5 + 2], ids[2 * 5 + 3]]));

  const out = t.locate(-1, 3);
  assert.equal(out.kind, 'outside');
  assert.equal(out.triangle, -1);
  assert.equal(out.vertices.length, 2);
  t.dispose();
});

test('stats and counts', () => {
  const t = new Triangulation();
  t.insertPoints(uniform(500, 4));
  const s = t.stats;
  assert.equal(s.inserted, 500);
  assert.ok(s.locates > 0 && s.walkSteps > 0);
  assert.equal(t.polylineCount, 0);
  assert.equal(t.triangleCount, t.results().stats.triangles);
  t.dispose();
  assert.ok(t.disposed);
  assert.throws(() => t.vertexCount, /disposed/);
});

test('Symbol.dispose disposes (using declarations)', () => {
  assert.equal(typeof Symbol.dispose, 'symbol');
  const t = new Triangulation();
  t[Symbol.dispose]();
  assert.ok(t.disposed);
});

test('a failed init() rejects and can be retried; wasmBinary is accepted', () => {
  const script = `
    import { readFileSync } from 'node:fs';
    import { createRequire } from 'node:module';
    import { init, triangulate } from 'geocdt';
    const out = [];
    await init({ wasmUrl: '/nonexistent/geocdt.wasm' }).catch((e) => out.push(e.code));
    const wasm = readFileSync(new URL('dist/geocdt.wasm', import.meta.resolve('geocdt')));
    await init({ wasmBinary: wasm });
    out.push(triangulate({ points: [0, 0, 1, 0, 0, 1] }).triangles.length);
    console.log(out.join(' '));`;
  const out = runModule(script);
  assert.equal(out.trim(), 'ENOENT 3');
});
