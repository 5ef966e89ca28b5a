// The demo's module worker: loads data, projects it to Web Mercator, triangulates it with
// geocdt and hands the map ready-to-draw buffers (transferred, not copied). Edits made by
// clicking go through geocdt's incremental Triangulation, built from the same input the
// first time the user edits.
import { init, triangulate, Triangulation } from 'geocdt';
import { decodeDataset } from './dataset-codec.js';
import { parseGeoJSONText } from './geojson-input.js';
import { projectLonLat } from './mercator.js';
import { meshBuffers, surfaceBuffers, transferablesOf } from './mesh-buffers.js';

const MESH_OPTIONS = { keep: 'all', insideFlags: true };

// What is on the map now: its projected input, and the incremental twin once edited.
let current = null;

self.onmessage = async ({ data: request }) => {
  try {
    await loadWasm();
    // geocdt reports at most about ten times a second: each report goes straight to the page.
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
    await init();
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
    { ...MESH_OPTIONS, onProgress });
  const triangulateMs = performance.now() - started;
  current?.incremental?.dispose();
  current = { input, incremental: null };
  return reply(result, triangulateMs, loadMs, input.bounds);
}

// The first edit replays the current input into an incremental Triangulation.
function incremental() {
  if (!current) throw new Error('nothing is loaded yet');
  if (!current.incremental) {
    const t = new Triangulation();
    const { points, polylines, values } = current.input;
    if (points.length) t.insertPoints(points, values?.points);
    polylines.forEach((line, i) => t.insertPolyline(line, values?.polylines[i]));
    current.incremental = t;
  }
  return current.incremental;
}

function addPoint(lonLat) {
  const t = incremental();
  const started = performance.now();
  t.insertPoints(projectLonLat(lonLat));
  const result = t.results(MESH_OPTIONS);
  current.input.addedPoints++;
  return reply(result, performance.now() - started, 0, null);
}

function addSegment(from, to) {
  const t = incremental();
  const started = performance.now();
  t.insertPolyline(projectLonLat([...from, ...to]));
  const result = t.results(MESH_OPTIONS);
  current.input.addedSegments++;
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
    inputPoints,
    vertices: result.points.length / 2,
    constraints,
    crossings: result.stats.crossings,
    triangles: result.triangles.length / 3,
    insideTriangles: mesh.insideTriangles,
    loadMs,
    triangulateMs,
    buffersMs: performance.now() - started,
  };
  return { mesh, stats, bounds };
}

