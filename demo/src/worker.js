// The demo's module worker: loads data, projects it to Web Mercator, triangulates it with
// geocdt and hands the map ready-to-draw buffers (transferred, not copied). Edits made by
// clicking go through geocdt's incremental Triangulation, built from the same input the
// first time the user edits.
import { init, triangulate, Triangulation } from 'geocdt';
import { decodeDataset } from './dataset-codec.js';
import { parseGeoJSONText } from './geojson-input.js';
import { projectLonLat } from './mercator.js';
import { VertexBook } from './vertex-book.js';
import { meshBuffers, surfaceBuffers, transferablesOf } from './mesh-buffers.js';

const MESH_OPTIONS = { keep: 'all', insideFlags: true };
// Refinement of a whole world map at 30 degrees would add millions of points: a cap keeps
// the demo interactive (the panel says when it ended refinement).
const MAX_STEINER_POINTS = 300_000;

// What is on the map now: its projected input, the edits made by clicking, and the
// incremental twin once edited.
let current = null;
// The minimum angle the panel asks for (0: no refinement).
let minAngle = 0;
const refineOptions = () =>
  (minAngle > 0 ? { minAngle, maxSteinerPoints: MAX_STEINER_POINTS } : undefined);

self.onmessage = async ({ data: request }) => {
  try {
    await loadWasm();
    // geocdt reports once a phase begins and at most ten times a second within it: each report
    // goes straight to the page.
    const onProgress = (progress) => self.postMessage({ id: request.id, progress });
    const reply = await handle(request, onProgress);
    self.postMessage({ id: request.id, ok: true, ...reply },
      reply.mesh ? transferablesOf(reply.mesh) : []);
  } catch (e) {
    // geocdt rejects bad coordinates with a TypeError or RangeError that names them.
    const checked =
      (e instanceof TypeError || e instanceof RangeError) && /^geocdt:/.test(e.message);
    const userFacing = e && (e.name === 'InputError' || checked);
    self.postMessage({
      id: request.id,
      ok: false,
      error: String(e && e.message ? e.message : e),
      kind: userFacing ? 'input' : 'internal',
    });
  }
};

async function loadWasm() {
  try {
    // Every core (at most 8) where the page is cross-origin isolated (the demo's server makes
    // it so); one thread elsewhere.
    await init({ threads: 'auto' });
  } catch (e) {
    throw new Error(`could not load geocdt's WebAssembly module (${e.message})`, { cause: e });
  }
}

async function handle(request, onProgress) {
  switch (request.type) {
    case 'dataset':
      return loadDataset(request.url, onProgress);
    case 'geojson': {
      const started = performance.now();
      const input = prepareGeoJSON(new TextDecoder().decode(request.bytes));
      return loadInput(input, performance.now() - started, onProgress);
    }
    case 'addPoint':
      return addPoint(request.lonLat);
    case 'addSegment':
      return addSegment(request.from, request.to);
    case 'refine':
      return refineAgain(request.minAngle, onProgress);
    case 'pick':
      return pick(request.lonLat);
    case 'movePoint':
      return edit({ kind: 'move', id: request.vertex, xy: projectLonLat(request.lonLat) });
    case 'removePoint':
      return edit({ kind: 'removePoint', id: request.vertex });
    case 'removeLines':
      return edit({ kind: 'removeLines', id: request.vertex });
    default:
      throw new Error(`unknown request ${request.type}`);
  }
}

async function loadDataset(url, onProgress) {
  const started = performance.now();
  const response = await fetch(url);
  if (!response.ok) throw new Error(`could not load ${url}: HTTP ${response.status}`);
  const layers = decodeDataset(await response.arrayBuffer());
  const input = { points: new Float64Array(0), polylines: [] };
  for (const layer of layers) for (const line of layer.lines) input.polylines.push(line);
  return loadInput(projectInput(input), performance.now() - started, onProgress);
}

function prepareGeoJSON(text) {
  const { points, rings, lines, hasZ, pointZ, ringZ, lineZ } = parseGeoJSONText(text);
  // Rings first: the order does not change the triangulation, only which input ids are which.
  const input = projectInput({ points: new Float64Array(points), polylines: [...rings, ...lines] });
  // Heights, when the file has them: one value per point, for the surface view.
  if (hasZ) input.values = { points: Float64Array.from(pointZ), polylines: [...ringZ, ...lineZ] };
  return input;
}

// The values in triangulate()'s order: the points, then each polyline's.
function flatValues({ points, polylines }) {
  const out = new Float64Array(polylines.reduce((n, z) => n + z.length, points.length));
  out.set(points);
  let at = points.length;
  for (const z of polylines) {
    out.set(z, at);
    at += z.length;
  }
  return out;
}

function projectInput({ points, polylines }) {
  const bounds = [Infinity, Infinity, -Infinity, -Infinity]; // lon/lat
  const grow = (xy) => {
    for (let i = 0; i < xy.length; i += 2) {
      bounds[0] = Math.min(bounds[0], xy[i]);
      bounds[1] = Math.min(bounds[1], xy[i + 1]);
      bounds[2] = Math.max(bounds[2], xy[i]);
      bounds[3] = Math.max(bounds[3], xy[i + 1]);
    }
  };
  grow(points);
  polylines.forEach(grow);
  return {
    points: projectLonLat(points),
    polylines: polylines.map((l) => projectLonLat(l)),
    bounds,
    addedPoints: 0,
    addedSegments: 0,
  };
}

function loadInput(input, loadMs, onProgress) {
  const started = performance.now();
  const values = input.values && flatValues(input.values);
  const result = triangulate({ points: input.points, polylines: input.polylines, values },
    { ...MESH_OPTIONS, refine: refineOptions(), onProgress });
  const triangulateMs = performance.now() - started;
  current?.incremental?.dispose();
  current = { input, edits: [], incremental: null };
  return reply(result, triangulateMs, loadMs, input.bounds);
}

// The first edit replays the current input (and the edits so far) into an incremental
// Triangulation, refined as the panel asks.
function incremental() {
  if (!current) throw new Error('nothing is loaded yet');
  if (!current.incremental) {
    const t = new Triangulation();
    const book = new VertexBook();
    const { points, polylines, values } = current.input;
    if (points.length) book.addPoints(t.insertPoints(points, values?.points), points);
    polylines.forEach((line, i) => {
      book.addLine(t.insertPolyline(line, values?.polylines[i]), line);
    });
    current.book = book;
    for (const edit of current.edits) applyEdit(t, book, edit);
    if (minAngle > 0) t.refine(refineOptions());
    current.incremental = t;
  }
  return current.incremental;
}

// Edits replay in order on a fresh Triangulation (after a new minimum angle): the same calls
// give the same ids.
function applyEdit(t, book, { kind, xy, id }) {
  if (kind === 'point') {
    book.addPoints(t.insertPoints(xy), xy);
  } else if (kind === 'segment') {
    book.addLine(t.insertPolyline(xy), xy);
  } else if (kind === 'move') {
    t.movePoint(id, xy[0], xy[1]);
    book.places.set(id, [xy[0], xy[1]]);
  } else if (kind === 'removePoint') {
    if (t.hasVertex(id) && book.points.has(id)) t.removePoint(id);
    book.points.delete(id);
  } else if (kind === 'removeLines') {
    for (const k of book.linesOf(id)) {
      t.removePolyline(k);
      book.lines[k].live = false;
    }
  }
}

// What a click picks: the nearest point or line vertex of the triangle (or edge) under it.
function pick(lonLat) {
  const t = incremental();
  const [x, y] = projectLonLat(lonLat);
  return { picked: current.book.pick(t.locate(x, y), x, y) };
}

function edit(change) {
  const { kind } = change;
  const t = incremental();
  const started = performance.now();
  applyEdit(t, current.book, change);
  current.edits.push(change);
  // Refinement again, around what the edit changed (its Steiner points add up).
  if (minAngle > 0) t.refine(refineOptions());
  const result = t.results(MESH_OPTIONS);
  if (kind === 'point') current.input.addedPoints++;
  else if (kind === 'segment') current.input.addedSegments++;
  return reply(result, performance.now() - started, 0, null);
}

function addPoint(lonLat) {
  return edit({ kind: 'point', xy: projectLonLat(lonLat) });
}

function addSegment(from, to) {
  return edit({ kind: 'segment', xy: projectLonLat([...from, ...to]) });
}

// A new minimum angle: what is loaded, edits included, triangulated afresh and refined.
function refineAgain(angle, onProgress) {
  if (!current) throw new Error('nothing is loaded yet');
  minAngle = angle;
  if (current.edits.length === 0) return loadInput(current.input, 0, onProgress);
  current.incremental?.dispose();
  current.incremental = null;
  const started = performance.now();
  const result = incremental().results(MESH_OPTIONS);
  return reply(result, performance.now() - started, 0, null);
}

function reply(result, triangulateMs, loadMs, bounds) {
  const started = performance.now();
  const { input } = current;
  const inputPoints = input.points.length / 2
    + input.polylines.reduce((n, l) => n + l.length / 2, 0)
    + input.addedPoints + 2 * input.addedSegments;
  const constraints =
    input.polylines.reduce((n, l) => n + l.length / 2 - 1, 0) + input.addedSegments;
  const mesh = meshBuffers(result);
  if (result.values) Object.assign(mesh, surfaceBuffers(result));
  const stats = {
    refine: minAngle > 0 ? refineStats(result) : null,
    inputPoints,
    vertices: result.points.length / 2,
    constraints,
    crossings: result.stats.crossings,
    threads: result.stats.threads,
    triangles: result.triangles.length / 3,
    insideTriangles: mesh.insideTriangles,
    loadMs,
    triangulateMs,
    buffersMs: performance.now() - started,
  };
  return { mesh, stats, bounds };
}


// What refinement did, and the smallest angle of any triangle (in the corners of input angles
// below the minimum, refinement leaves them: stats.refineSkipped counts those triangles).
function refineStats({ points, triangles, stats }) {
  let smallest = Math.PI;
  for (let t = 0; t < triangles.length; t += 3) {
    for (let k = 0; k < 3; k++) {
      const a = 2 * triangles[t + k], b = 2 * triangles[t + (k + 1) % 3];
      const c = 2 * triangles[t + (k + 2) % 3];
      const ux = points[b] - points[a], uy = points[b + 1] - points[a + 1];
      const vx = points[c] - points[a], vy = points[c + 1] - points[a + 1];
      const angle = Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy);
      if (angle < smallest) smallest = angle;
    }
  }
  return {
    steinerPoints: stats.steinerPoints,
    capped: stats.refineCapped === 1,
    skipped: stats.refineSkipped,
    smallestAngle: (smallest * 180) / Math.PI,
  };
}
