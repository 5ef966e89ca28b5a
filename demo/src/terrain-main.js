// The terrain page: the bundled DEM meshed in a worker with geocdt's triangulateRaster each
// time a slider or the breaklines change, drawn shaded on a canvas with its statistics.
import './style.css';
import './terrain.css';
import { decodeDem } from './terrain-dem.js';
import { drawTerrain, smallestAngle } from './terrain-render.js';

const $ = (id) => document.getElementById(id);
const n = (x) => x.toLocaleString('en-US');

// Lines across the DEM in pixel positions: they cross each other and the raster's edges.
const kBreaklines = [
  [-10, 330, 120, 230, 260, 150, 415, 20],
  [30, -5, 160, 120, 250, 200, 330, 350],
];

// The error slider: 0..100 -> 0.5 m .. 128 m, evenly on a log scale.
const maxErrorOf = (v) => 0.5 * 2 ** (v / 12.5);

let dem = null;
let drawn = [];        // finished lines drawn by clicking, in DEM pixels
let drawing = null;    // the line being drawn
let mesh = null;
let pending = null;    // a request waiting for the one in flight
let busy = false;
let nextId = 1;

function setStatus(status) {
  document.body.dataset.status = status;
  $('stat-status').textContent = status;
}

function showError(message) {
  const box = $('error');
  box.hidden = !message;
  box.textContent = message ?? '';
}

const worker = new Worker(new URL('./terrain-worker.js', import.meta.url), { type: 'module' });
const waiting = new Map();
worker.onmessage = ({ data }) => {
  const done = waiting.get(data.id);
  waiting.delete(data.id);
  done?.(data);
};
function ask(message, transfer = []) {
  const id = nextId++;
  return new Promise((resolve) => {
    waiting.set(id, resolve);
    worker.postMessage({ id, ...message }, transfer);
  });
}

function breaklines() {
  const lines = $('use-breaklines').checked ? [...kBreaklines] : [];
  return lines.concat(drawn);
}

function options() {
  const maxError = maxErrorOf(Number($('max-error').value));
  const minAngle = Number($('min-angle').value);
  return { maxError, minAngle, decimate: $('decimate').checked, breaklines: breaklines() };
}

function fitCanvas() {
  const canvas = $('terrain');
  const area = $('terrain-view');
  const scale = Math.max(1, Math.min(area.clientWidth / dem.width,
    area.clientHeight / dem.height));
  canvas.width = Math.round(dem.width * scale);
  canvas.height = Math.round(dem.height * scale);
  return scale;
}

function draw() {
  if (!mesh) return;
  const scale = fitCanvas();
  let low = Infinity, high = -Infinity;
  for (const h of dem.heights) {
    low = Math.min(low, h);
    high = Math.max(high, h);
  }
  const lines = mesh.breaklines.concat(drawing ? [drawing] : []);
  drawTerrain($('terrain'), mesh, {
    scale, wireframe: $('wireframe').checked, breaklines: lines, low, high,
    metresPerPixel: 90, exaggeration: 2,
  });
}

function showStats(m, request) {
  const stats = m.stats;
  $('stat-vertices').textContent = n(stats.vertices ?? m.points.length / 2);
  $('stat-triangles').textContent = n(m.triangles.length / 3);
  $('stat-max-error').textContent = `${stats.maxError.toFixed(2)} m (bound ${
    request.maxError.toFixed(2)} m)`;
  // Below minAngle only where breaklines meet at a smaller angle or run a hair apart.
  const skipped = stats.refineSkipped > 0 ? ` (${n(stats.refineSkipped)} triangles below)` : '';
  $('stat-min-angle').textContent = `${smallestAngle(m).toFixed(1)}°${skipped}`;
  $('stat-steiner').textContent = n(stats.steinerPoints);
  $('stat-decimated').textContent = n(stats.decimated);
  let constrained = 0;
  for (const c of m.constrained) constrained += c;
  $('stat-constrained').textContent = n(constrained / 2);
  $('stat-share').textContent = `${(100 * m.triangles.length / 3 / (2 * dem.width * dem.height))
    .toFixed(1)}%`;
  $('stat-ms').textContent = `${m.ms.toFixed(0)} ms`;
}

async function remesh() {
  const request = options();
  $('max-error-value').textContent = `${request.maxError.toFixed(request.maxError < 10 ? 1 : 0)} m`;
  $('min-angle-value').textContent = request.minAngle > 0 ? `${request.minAngle}°` : 'none';
  if (busy) {
    pending = request;
    return;
  }
  busy = true;
  setStatus('meshing');
  const reply = await ask({ options: request });
  busy = false;
  if (!reply.ok) {
    showError(reply.error);
    setStatus('failed');
    return;
  }
  showError(null);
  mesh = { ...reply.mesh, breaklines: request.breaklines };
  showStats(reply.mesh, request);
  draw();
  if (pending) {
    pending = null;
    remesh();
    return;
  }
  setStatus('ready');
}

// A click adds a point to the line being drawn (in DEM pixels); a double-click ends it.
function pixelAt(event) {
  const canvas = $('terrain');
  const rect = canvas.getBoundingClientRect();
  const scale = canvas.width / dem.width;
  return [(event.clientX - rect.left) * (canvas.width / rect.width) / scale - 0.5,
    (event.clientY - rect.top) * (canvas.height / rect.height) / scale - 0.5];
}

function setUp() {
  for (const id of ['max-error', 'min-angle']) $(id).addEventListener('input', remesh);
  $('use-breaklines').addEventListener('change', remesh);
  $('decimate').addEventListener('change', remesh);
  $('wireframe').addEventListener('change', draw);
  $('clear-lines').addEventListener('click', () => {
    drawn = [];
    drawing = null;
    remesh();
  });
  $('terrain').addEventListener('click', (event) => {
    drawing = (drawing ?? []).concat(pixelAt(event));
    draw();
  });
  $('terrain').addEventListener('dblclick', () => {
    if (drawing && drawing.length >= 4) drawn.push(drawing);
    drawing = null;
    remesh();
  });
  window.addEventListener('resize', draw);
}

async function start() {
  try {
    const response = await fetch(new URL('./jacksboro.dem', document.baseURI));
    if (!response.ok) throw new Error(`jacksboro.dem: HTTP ${response.status}`);
    dem = decodeDem(await response.arrayBuffer());
    const heights = Int16Array.from(dem.heights);
    await ask({ raster: { heights, width: dem.width, height: dem.height } }, [heights.buffer]);
    setUp();
    await remesh();
  } catch (error) {
    showError(String(error?.message ?? error));
    setStatus('failed');
  }
}

start();
