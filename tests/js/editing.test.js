// Editing a Triangulation in place through the wasm build: random sequences of insertions,
// removals and moves checked by the exact JS invariants and against a fresh triangulate() of
// what remains; bad ids; the ids of results(); the worker.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { init, triangulate, Triangulation } from 'geocdt';
import { createWorker } from 'geocdt/worker';
import { checkMesh } from './support/invariants.js';
import { checkConstraints } from './support/constraints.js';
import { random } from './support/inputs.js';
import { throwsWith } from './support/throws.js';

before(() => init());

// Triangles, and constrained edges with their polylines, by coordinates: the numbering of
// an edited mesh differs from a fresh one's. number maps a fresh polyline to its edited one.
function shape(r, number = (k) => k) {
  const at = (v) => `${r.points[2 * v]},${r.points[2 * v + 1]}`;
  const triangles = [];
  for (let t = 0; t < r.triangles.length; t += 3) {
    const c = [0, 1, 2].map((k) => at(r.triangles[t + k]));
    const first = c.indexOf([...c].sort()[0]);
    triangles.push([...c.slice(first), ...c.slice(0, first)].join(' '));
  }
  const edges = [];
  for (let i = 0; i < r.constraintEdges.length; i++) {
    const e = r.constraintEdges[i];
    const ends = [at(r.triangles[e]), at(r.triangles[e % 3 === 2 ? e - 2 : e + 1])].sort();
    const names = Array.from(r.sources.subarray(r.sourceOffsets[i], r.sourceOffsets[i + 1]),
      number).sort((a, b) => a - b);
    edges.push(`${ends.join(' ')} ${names.join(',')}`);
  }
  return { triangles: triangles.sort(), edges: edges.sort() };
}

// What the triangulation should hold: points and polylines by id, moved where moved.
class Model {
  places = new Map();
  points = new Set();
  lines = [];

  insertPoints(t, xy) {
    const ids = t.insertPoints(xy);
    ids.forEach((id, i) => {
      this.places.set(id, [xy[2 * i], xy[2 * i + 1]]);
      this.points.add(id);
    });
  }

  insertPolyline(t, xy) {
    const ids = t.insertPolyline(xy);
    ids.forEach((id, i) => this.places.set(id, [xy[2 * i], xy[2 * i + 1]]));
    this.lines.push({ ids: Array.from(ids), live: true });
  }

  input() {
    const points = [...this.points].sort((a, b) => a - b).flatMap((id) => this.places.get(id));
    const live = this.lines.map((line, k) => ({ ...line, k })).filter((line) => line.live);
    return {
      points,
      polylines: live.map((line) => line.ids.flatMap((id) => this.places.get(id))),
      numbers: live.map((line) => line.k),
    };
  }

  // The invariants of the edited mesh, and its sameness with a fresh triangulation.
  check(t, label) {
    const r = t.results({ insideFlags: true });
    assert.equal(r.vertexIds.length, r.points.length / 2, `${label}: one id per vertex`);
    const { points, polylines, numbers } = this.input();
    // The constraint checker reads each input point's vertex (points, then polylines by
    // number, removed ones empty) from inputToVertex: output vertices, found by id.
    const index = new Map(Array.from(r.vertexIds, (id, i) => [id, i]));
    const pointIds = [...this.points].sort((a, b) => a - b);
    const lineIds = this.lines.map((line) => (line.live ? line.ids : []));
    const inputToVertex = [...pointIds, ...lineIds.flat()].map((id) => index.get(id));
    const polylinesByNumber = lineIds.map((ids) => ids.flatMap((id) => this.places.get(id)));
    checkMesh(r, { points, polylines });
    if (r.triangles.length > 0) {
      checkConstraints({ ...r, inputToVertex }, { points, polylines: polylinesByNumber });
    }
    const fresh = triangulate({ points, polylines }, { insideFlags: true });
    assert.deepEqual(shape(r), shape(fresh, (k) => numbers[k]), `${label}: as triangulate()`);
  }
}

test('random sequences of insertions, removals and moves match triangulate()', () => {
  for (let seed = 1; seed <= 8; seed++) {
    const rand = random(seed);
    const coordinate = () => Math.floor(rand() * 1000 * 64) / 64;
    const t = new Triangulation();
    const model = new Model();
    for (let step = 0; step < 120; step++) {
      const r = rand();
      const points = [...model.points];
      const lines = model.lines.map((line, k) => k).filter((k) => model.lines[k].live);
      let label = `seed ${seed} step ${step}`;
      if (r < 0.25 || points.length === 0) {
        model.insertPoints(t, Array.from({ length: 2 * (1 + Math.floor(rand() * 10)) },
          coordinate));
      } else if (r < 0.35) {
        const line = Array.from({ length: 2 * (2 + Math.floor(rand() * 4)) }, coordinate);
        if (rand() < 0.3) line.push(line[0], line[1]);
        model.insertPolyline(t, line);
      } else if (r < 0.6) {
        const id = points[Math.floor(rand() * points.length)];
        label += ` removePoint ${id}`;
        const went = t.removePoint(id);
        model.points.delete(id);
        const onLine = model.lines.some((line) => line.live && line.ids.includes(id));
        assert.equal(went, !onLine, `${label}: removePoint tells whether the vertex went`);
        assert.equal(t.hasVertex(id), onLine, label);
      } else if (r < 0.7 && lines.length > 0) {
        const k = lines[Math.floor(rand() * lines.length)];
        label += ` removePolyline ${k}`;
        t.removePolyline(k);
        model.lines[k].live = false;
      } else {
        const from = rand() < 0.5 && lines.length > 0
          ? model.lines[lines[Math.floor(rand() * lines.length)]].ids : points;
        const id = from[Math.floor(rand() * from.length)];
        const x = coordinate(), y = coordinate();
        label += ` movePoint ${id}`;
        t.movePoint(id, x, y);
        model.places.set(id, [x, y]);
      }
      if (step % 6 === 5) model.check(t, label);
    }
    t.dispose();
  }
});

// removePoints: random batches, some of their points also polylines' vertices (which stay),
// removed in one call each; the mesh must be triangulate()'s of what remains.
test('removePoints removes a batch as removePoint would one by one', () => {
  for (let seed = 1; seed <= 4; seed++) {
    const rand = random(100 + seed);
    const coordinate = () => Math.floor(rand() * 1000 * 64) / 64;
    const t = new Triangulation();
    const model = new Model();
    model.insertPoints(t, Array.from({ length: 600 }, coordinate));
    let points = [...model.points];
    for (let k = 0; k < 3; k++) {  // through some of the points, and across each other
      const through = [0, 1, 2].map(() => points[Math.floor(rand() * points.length)]);
      model.insertPolyline(t, through.flatMap((id) => model.places.get(id)));
    }
    const onLine = (id) => model.lines.some((line) => line.live && line.ids.includes(id));
    for (const size of [1, 20, 120]) {
      points = [...model.points];
      const batch = new Set();
      while (batch.size < size) batch.add(points[Math.floor(rand() * points.length)]);
      const ids = seed % 2 === 0 ? Uint32Array.from(batch) : [...batch];
      const stay = [...batch].filter(onLine).length;
      const label = `seed ${seed}, a batch of ${size}`;
      assert.equal(t.removePoints(ids), size - stay, `${label}: how many vertices went`);
      for (const id of batch) {
        model.points.delete(id);
        assert.equal(t.hasVertex(id), onLine(id), `${label}: vertex ${id}`);
      }
      model.check(t, label);
    }
    assert.equal(t.removePoints([]), 0);
    t.dispose();
  }
});

// A drag: one point moved in small steps, mostly within its star, where a free point or a
// polyline vertex whose segments are whole edges moves by flips alone; after each step the
// mesh is triangulate()'s, polylines' edges unflipped.
test('a point dragged in small steps keeps the mesh triangulate()\'s', () => {
  const rand = random(5);
  const t = new Triangulation();
  const model = new Model();
  model.insertPoints(t, Array.from({ length: 600 }, () => rand() * 1000));
  model.insertPolyline(t, [100, 120, 480, 530, 900, 610]);
  const points = [...model.points];
  const lineVertex = model.lines[0].ids[1];
  for (let drag = 0; drag < 5; drag++) {
    const id = drag === 4 ? lineVertex : points[Math.floor(rand() * points.length)];
    let [x, y] = model.places.get(id);
    for (let step = 0; step < 25; step++) {
      x += (rand() - 0.5) * 8;  // the mean spacing is about 58
      y += (rand() - 0.5) * 8;
      t.movePoint(id, x, y);
      model.places.set(id, [x, y]);
      model.check(t, `drag ${drag} step ${step}`);
    }
  }
  t.dispose();
});

test('bad ids throw a RangeError and change nothing', () => {
  const t = new Triangulation();
  const ids = t.insertPoints([0, 0, 4, 0, 0, 4, 4, 4]);
  const line = t.insertPolyline([1, 1, 3, 2]);
  const arrays = (r) => [r.points, r.triangles, r.halfedges, r.constrained, r.vertexIds];
  const before = arrays(t.results());
  throwsWith(() => t.removePoint(99), RangeError, /no vertex has id 99/);
  throwsWith(() => t.removePoint(1.5), RangeError, /must be an integer/);
  throwsWith(() => t.removePoint(-1), RangeError, /must be an integer/);
  throwsWith(() => t.removePoint('1'), TypeError, /must be a number/);
  throwsWith(() => t.removePoint(line[0]), RangeError, /not a point inserted with insertPoints/);
  throwsWith(() => t.removePolyline(1), RangeError, /no polyline 1/);
  throwsWith(() => t.movePoint(ids[0], NaN, 0), RangeError, /new place of vertex/);
  throwsWith(() => t.movePoint(ids[0], 4, 4), RangeError, /is that of vertex/);
  throwsWith(() => t.removePoints(5), TypeError, /ids must be an array or typed array/);
  throwsWith(() => t.removePoints([ids[0], '1']), TypeError, /ids\[1\]: the id must be a number/);
  throwsWith(() => t.removePoints([ids[0], 1.5]), RangeError, /ids\[1\]: the id must be an integer/);
  throwsWith(() => t.removePoints(new Int32Array([ids[0], -1])), RangeError, /ids\[1\]/);
  throwsWith(() => t.removePoints([ids[0], ids[1], 99]), RangeError, /ids\[2\]: no vertex has id 99/);
  throwsWith(() => t.removePoints([ids[0], line[0]]), RangeError, /not a point inserted/);
  throwsWith(() => t.removePoints([ids[1], ids[0], ids[1]]), RangeError,
    /ids\[2\]: vertex 1 is also ids\[0\]/);
  assert.throws(() => t.removePoints(new Uint32Array([ids[0], 99])), (e) => e.index === 1);
  assert.throws(() => t.removePoints([ids[0], ids[1], -1]), (e) => e.index === 2);
  assert.throws(() => t.removePoints([ids[0], ids[0], 99]), (e) => e.index === 1);
  assert.deepEqual(arrays(t.results()), before);
  assert.equal(t.removePoint(ids[0]), true);
  throwsWith(() => t.removePoint(ids[0]), RangeError, /was removed/);
  throwsWith(() => t.movePoint(ids[0], 2, 2), RangeError, /was removed/);
  t.removePolyline(0);
  throwsWith(() => t.removePolyline(0), RangeError, /polyline 0 was removed/);
  // The module stays usable.
  assert.equal(t.results().points.length / 2, 3);
  t.dispose();
});

test('results() names the id of each vertex once some were removed', () => {
  const t = new Triangulation();
  const ids = t.insertPoints([0, 0, 10, 0, 10, 10, 0, 10, 5, 5, 2, 7]);
  assert.deepEqual(Array.from(t.results().vertexIds), [0, 1, 2, 3, 4, 5]);
  t.removePoint(ids[4]);
  const r = t.results();
  assert.deepEqual(Array.from(r.vertexIds), [0, 1, 2, 3, 5]);
  assert.deepEqual(Array.from(r.points.subarray(8, 10)), [2, 7]);
  assert.equal(t.locate(2, 7).vertices[0], ids[5]);  // locate() names ids
  assert.equal(t.stats.removed, 1);
  assert.equal(t.vertexCount, 5);
  t.dispose();
});

test('removing every point leaves an empty mesh; collinear points leave none', () => {
  const t = new Triangulation();
  const ids = t.insertPoints([0, 0, 1, 0, 2, 0, 1, 1]);
  t.removePoint(ids[3]);
  assert.equal(t.triangleCount, 0);
  assert.equal(t.locate(1, 0.5).kind, 'empty');
  t.insertPoints([1, -1]);
  assert.equal(t.triangleCount, 2);  // (1, 0) lies on the hull
  for (const id of [...ids.subarray(0, 3), 4]) t.removePoint(id);
  assert.equal(t.vertexCount, 0);
  assert.equal(t.results().triangles.length, 0);
  t.dispose();
});

test('values move with their vertices; crossings derive theirs again', () => {
  const t = new Triangulation({ valuesPerPoint: 1 });
  t.insertPoints([0, 0, 10, 0, 10, 10, 0, 10], [0, 10, 20, 10]);
  const a = t.insertPolyline([1, 5, 9, 5], [1, 9]);
  t.insertPolyline([5, 1, 5, 9], [5, 5]);
  const crossing = (r) => {
    const i = Array.from(r.vertexIds).findIndex((id) => id > 7);
    return [r.points[2 * i], r.points[2 * i + 1], r.values[i]];
  };
  assert.deepEqual(crossing(t.results()), [5, 5, 5]);
  t.movePoint(a[1], 9, 7);  // the line turns; the crossing moves and takes a new value
  const [x, y, value] = crossing(t.results());
  assert.equal(x, 5);
  assert.ok(y > 5 && y < 7);
  assert.ok(Math.abs(value - 5) < 1e-12);  // 1 + (9 - 1) * 0.5 along the first line
  const r = t.results();
  assert.equal(r.values[Array.from(r.vertexIds).indexOf(a[1])], 9);  // its own value
  t.dispose();
});

test('a refined mesh drops the Steiner points an edit invalidates', () => {
  const t = new Triangulation();
  const ids = t.insertPoints([0, 0, 100, 0, 100, 100, 0, 100, 50, 3]);
  t.insertPolyline([10, 10, 90, 80]);
  t.refine({ minAngle: 30 });
  const refined = t.results();
  assert.ok(refined.steiner.length > 0);
  t.removePoint(ids[4]);
  const r = t.results();
  checkMesh(r, { points: [0, 0, 100, 0, 100, 100, 0, 100] });
  assert.ok(r.steiner.length < refined.steiner.length);
  for (const p of r.steinerParents) assert.ok(p === 0xffffffff || p < r.points.length / 2);
  t.refine({ minAngle: 30 });
  checkMesh(t.results());
  t.dispose();
});

test('the worker edits its Triangulation', async () => {
  const worker = createWorker();
  try {
    const t = worker.createTriangulation();
    const ids = await t.insertPoints([0, 0, 4, 0, 0, 4, 4, 4, 2, 1], { transfer: false });
    assert.equal(await t.removePoint(ids[4]), true);
    assert.equal(await t.removePoints([ids[0], ids[1]]), 2);
    await assert.rejects(t.removePoints([ids[2], 99]), (e) => e instanceof RangeError
      && e.index === 1);
    const later = new Uint32Array([ids[2]]);
    const removing = t.removePoints(later);
    later[0] = 99;  // after the call: the worker has the ids as they were
    assert.equal(await removing, 1);
    await t.movePoint(ids[3], 5, 5);
    const r = await t.results();
    assert.deepEqual(Array.from(r.vertexIds), [3]);
    await assert.rejects(t.removePoint(ids[4]), RangeError);
    await t.dispose();
  } finally {
    worker.terminate();
  }
});
