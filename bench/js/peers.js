// The libraries geocdt is measured against. Each returns { xy, triangles } for summary(),
// which counts the triangles and checks them (no zero-area or flipped ones) untimed.
import { createRequire } from 'node:module';
import { Worker } from 'node:worker_threads';
import Delaunator from 'delaunator';
import Constrainautor from '@kninnug/constrainautor';
import earcut from 'earcut';
import { orient2d } from 'robust-predicates';

const require = createRequire(import.meta.url);
const cdt2d = require('cdt2d');
const Triangle = require('triangle-wasm');

// Zero-area triangles, plus those turning against the majority: a sound mesh has none.
export function badTriangles(xy, triangles) {
  let positive = 0, negative = 0, zero = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const a = 2 * triangles[t], b = 2 * triangles[t + 1], c = 2 * triangles[t + 2];
    const o = orient2d(xy[a], xy[a + 1], xy[b], xy[b + 1], xy[c], xy[c + 1]);
    if (o > 0) positive++;
    else if (o < 0) negative++;
    else zero++;
  }
  return zero + Math.min(positive, negative);
}

export function summary({ xy, triangles }) {
  const bad = badTriangles(xy, triangles);
  const count = (triangles.length / 3).toLocaleString('en-US');
  return `${count} triangles${bad ? `, ${bad} INVALID (flipped or zero-area)` : ''}`;
}

// The smallest angle, in degrees, of the triangles keep(t) accepts.
export function worstAngle(xy, triangles, keep = () => true) {
  let worst = 180;
  for (let t = 0; t < triangles.length / 3; t++) {
    if (!keep(t)) continue;
    for (let k = 0; k < 3; k++) {
      const a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
      const c = triangles[3 * t + (k + 2) % 3];
      const ux = xy[2 * b] - xy[2 * a], uy = xy[2 * b + 1] - xy[2 * a + 1];
      const vx = xy[2 * c] - xy[2 * a], vy = xy[2 * c + 1] - xy[2 * a + 1];
      const deg = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / Math.PI;
      worst = Math.min(worst, deg);
    }
  }
  return worst;
}

// A refined mesh: points added to the input's, triangles and the worst angle.
export function refinedSummary(inputPoints, { xy, triangles }) {
  return `${xy.length / 2 - inputPoints} Steiner points, ${summary({ xy, triangles })}, `
    + `worst ${worstAngle(xy, triangles).toFixed(2)} deg`;
}

export function delaunator(xy) {
  return { xy, triangles: new Delaunator(xy).triangles };
}

export function constrainautor({ xy, edges }) {
  const d = new Delaunator(xy);
  new Constrainautor(d, edges);
  return { xy, triangles: d.triangles };
}

export function cdt({ xy, edges }) {
  const points = [];
  for (let i = 0; i < xy.length; i += 2) points.push([xy[i], xy[i + 1]]);
  return { xy, cells: cdt2d(points, edges, { exterior: true }) };
}

// Its glue would fetch() a file path under Node 20, which fails: hide fetch so that it reads
// the file instead.
export async function initTriangle() {
  const { fetch } = globalThis;
  globalThis.fetch = undefined;
  try {
    await Triangle.init(require.resolve('triangle-wasm/triangle.out.wasm'));
  } finally {
    globalThis.fetch = fetch;
  }
}

// Triangle in a worker thread (see triangle-worker.js): a crash fails this run only, and a
// run that does not finish in timeoutMs is stopped and reported as failed.
export function triangleInWorker(timeoutMs = 60_000) {
  let worker = null;
  return {
    run(graph) {
      // Triangle prints its internal errors: keep them out of the report (the failure is in it).
      worker ??= new Worker(new URL('./triangle-worker.js', import.meta.url),
        { stdout: true, stderr: true });
      worker.stdout.resume();
      worker.stderr.resume();
      return new Promise((resolve, reject) => {
        const w = worker;
        const timer = setTimeout(() => {
          done();
          worker = null;
          w.terminate();
          reject(new Error(`Triangle did not finish in ${timeoutMs / 1000} s`));
        }, timeoutMs);
        const onMessage = (m) => { done(); resolve(m); };
        const onError = (e) => { done(); worker = null; reject(e); };
        const onExit = (code) => {
          done();
          worker = null;
          reject(new Error(`Triangle exited (code ${code}): internal error`));
        };
        const done = () => {
          clearTimeout(timer);
          w.off('message', onMessage).off('error', onError).off('exit', onExit);
        };
        w.on('message', onMessage).on('error', onError).on('exit', onExit);
        worker.postMessage(graph);
      });
    },
    close() { worker?.terminate(); },
  };
}

// switches: more of Triangle's switches (refine.js asks for quality).
export function triangle({ xy, edges, switches = {} }) {
  const input = Triangle.makeIO({ pointlist: xy, segmentlist: Int32Array.from(edges.flat()) });
  const output = Triangle.makeIO();
  try {
    Triangle.triangulate({ pslg: true, quiet: true, ...switches }, input, output);
    const triangles = Uint32Array.from(output.trianglelist ?? []);
    if (triangles.length === 0) throw new Error('Triangle returned no triangles');
    return { xy: Float64Array.from(output.pointlist), triangles };
  } finally {
    Triangle.freeIO(input, true);
    Triangle.freeIO(output);
  }
}

// cdt2d answers with [[i, j, k], ...].
export function cdtSummary({ xy, cells }) {
  return summary({ xy, triangles: Uint32Array.from(cells.flat()) });
}

// Triangulates each polygon on its own (no shared borders, not Delaunay).
export function earcutPolygons(polygons) {
  return polygons.map(({ coords, holes }) => earcut(coords, holes));
}

export function earcutSummary(polygons, results) {
  let count = 0, bad = 0;
  results.forEach((t, i) => {
    count += t.length / 3;
    bad += badTriangles(polygons[i].coords, t);
  });
  return `${count.toLocaleString('en-US')} triangles${bad ? `, ${bad} zero-area or flipped` : ''}`;
}
