// The demo page: a Leaflet map, the panel's controls, and the round trips to the worker.
import 'leaflet/dist/leaflet.css';
import './style.css';
import L from 'leaflet';
import { MapEditing } from './map-editing.js';
import { VertexEditing } from './vertex-editing.js';
import { DEFAULT_STYLE } from './mesh-style.js';
import { MeshView } from './mesh-view.js';
import { MeshWorker } from './worker-client.js';

const MAX_FILE_BYTES = 200 * 1024 * 1024;

const $ = (id) => document.getElementById(id);
const format = (n) => (typeof n === 'number' ? n.toLocaleString('en') : String(n));
const formatMs = (ms) => `${ms < 10 ? ms.toFixed(1) : Math.round(ms).toLocaleString('en')} ms`;

const map = L.map('map', { minZoom: 1, maxZoom: 19, worldCopyJump: false }).setView([25, 10], 2);
map.attributionControl.setPrefix('<a href="https://leafletjs.com/">Leaflet</a>');
map.attributionControl.addAttribution('Natural Earth (public domain) · rivers: GSHHG, LGPL-3.0');
L.control.scale().addTo(map);

const style = { ...DEFAULT_STYLE };
const view = new MeshView(map, style, showNotice);
const worker = new MeshWorker(
  () => new Worker(new URL('./worker.js', import.meta.url), { type: 'module' }));
const state = { generation: 0, pending: 0, stats: null, source: null, hasMesh: false };
const progress = createProgressBar();

// One round trip: ask the worker, draw the answer, show the numbers. A newer load makes
// older answers stale; edits are applied in the order they were made.
async function run(source, ask, { fit = false, isEdit = false } = {}) {
  const generation = isEdit ? state.generation : ++state.generation;
  const started = performance.now();
  state.pending++;
  setStatus('working', isEdit ? 'updating…' : `triangulating ${source}…`);
  const onProgress = ({ phase, fraction }) => {
    if (generation === state.generation) progress.show(phase, fraction);
  };
  let reply = null;
  let failure = null;
  try {
    reply = await ask(onProgress);
  } catch (e) {
    failure = e;
  } finally {
    state.pending--;
  }
  if (generation !== state.generation) return;
  progress.hide();
  try {
    if (failure) throw failure;
    hideMessages();
    const drawStarted = performance.now();
    if (fit && reply.bounds) fitTo(reply.bounds);
    offerSurface(reply.mesh);
    view.show(reply.mesh);
    await nextFrame();
    const now = performance.now();
    state.source = source;
    state.hasMesh = true;
    state.stats = {
      ...reply.stats,
      drawMs: now - drawStarted,
      totalMs: now - started,
      renderer: view.drawnWith,
    };
    showStats(state.stats);
    if (state.pending === 0) setStatus('ready', 'ready');
  } catch (e) {
    showError(e.name === 'InputRejected' ? `${source}: ${e.message}` : e.message);
    setStatus(state.hasMesh ? 'error' : 'failed', 'error');
  }
}

function loadDataset(name) {
  editing.finishLine();
  const url = new URL(`data/${name}.bin`, document.baseURI).href;
  return run(name, (onProgress) => worker.request('dataset', { url }, [], onProgress),
    { fit: false });
}

async function loadFile(file) {
  if (!file) return;
  editing.finishLine();
  if (file.size > MAX_FILE_BYTES) {
    showError(`${file.name}: too big for the demo (${format(file.size)} bytes; `
      + `the limit is ${format(MAX_FILE_BYTES)}).`);
    setStatus(state.hasMesh ? 'error' : 'failed', 'error');
    return;
  }
  const bytes = await file.arrayBuffer();
  await run(file.name,
    (onProgress) => worker.request('geojson', { bytes }, [bytes], onProgress), { fit: true });
}

function fitTo([west, south, east, north]) {
  const clamp = (lat) => Math.max(-85, Math.min(85, lat));
  map.fitBounds([[clamp(south), west], [clamp(north), east]],
    { padding: [20, 20], maxZoom: 16, animate: false });
}

const editing = new MapEditing(map, {
  onPoint: (lonLat) => state.hasMesh
    && run(state.source, () => worker.request('addPoint', { lonLat }), { isEdit: true }),
  onSegment: (from, to) => state.hasMesh
    && run(state.source, () => worker.request('addSegment', { from, to }), { isEdit: true }),
  onModeChange: () => {
    $('finish-line').disabled = !editing.drawing;
  },
});

// --- panel -------------------------------------------------------------------------

$('dataset').addEventListener('change', (e) => loadDataset(e.target.value));
$('renderer').addEventListener('change', (e) => view.setRenderer(e.target.value));
for (const input of document.querySelectorAll('input[name="show"]')) {
  input.addEventListener('change', () => restyle({ show: input.value }));
}
for (const id of ['fill', 'edges', 'constraints']) {
  $(id).addEventListener('change', (e) => restyle({ [id]: e.target.checked }));
}
// Edit mode: requests that change the mesh redraw it; a pick only asks.
const vertexEditing = new VertexEditing(map, {
  request: (type, payload, redraw) => (redraw
    ? run(state.source, () => worker.request(type, payload), { isEdit: true })
    : worker.request(type, payload)),
  onSelect: (picked) => {
    $('delete-point').disabled = !picked?.point;
    $('delete-lines').disabled = !picked?.lines.length;
  },
});
$('delete-point').addEventListener('click', () => vertexEditing.removePoint());
$('delete-lines').addEventListener('click', () => vertexEditing.removeLines());
for (const input of document.querySelectorAll('input[name="mode"]')) {
  input.addEventListener('change', () => {
    editing.setMode(input.value);
    vertexEditing.setActive(input.value === 'edit');
  });
}
$('finish-line').addEventListener('click', () => editing.finishLine());
const angleLabel = (degrees) => (degrees > 0 ? `${degrees}°` : 'off');
$('min-angle').addEventListener('input', (e) => {
  $('min-angle-value').textContent = angleLabel(Number(e.target.value));
});
// A new minimum angle re-triangulates what is loaded (edits included) and refines it.
$('min-angle').addEventListener('change', (e) => {
  const minAngle = Number(e.target.value);
  if (state.hasMesh) {
    run(state.source, (onProgress) => worker.request('refine', { minAngle }, [], onProgress));
  }
});
$('file').addEventListener('change', (e) => {
  loadFile(e.target.files[0]);
  e.target.value = ''; // picking the same file again should load it again
});

const mapElement = $('map');
mapElement.addEventListener('dragover', (e) => {
  e.preventDefault();
  mapElement.classList.add('dragging-file');
});
mapElement.addEventListener('dragleave', () => mapElement.classList.remove('dragging-file'));
mapElement.addEventListener('drop', (e) => {
  e.preventDefault();
  mapElement.classList.remove('dragging-file');
  loadFile(e.dataTransfer.files[0]);
});

// The surface view is there when the mesh has values (a GeoJSON with z).
function offerSurface(mesh) {
  const has = mesh.surfaceCounts !== undefined;
  $('show-surface').disabled = !has;
  $('surface-range').textContent = has
    ? `(${mesh.surfaceRange.map((v) => format(Number(v.toPrecision(4)))).join(' to ')})` : '';
  if (!has && style.show === 'surface') {
    document.querySelector('input[name="show"][value="all"]').checked = true;
    style.show = 'all';
  }
}

function restyle(change) {
  Object.assign(style, change);
  view.setStyle({ ...style });
}

// --- messages and statistics -----------------------------------------------------------

// The bar under the statistics while a triangulation runs: geocdt's phase and how far it is.
// Every report is also kept in window.geocdtDemo.progress, for automated checks.
function createProgressBar() {
  const box = document.createElement('div');
  box.id = 'progress';
  box.hidden = true;
  const bar = document.createElement('progress');
  bar.max = 1;
  const label = document.createElement('span');
  box.append(bar, label);
  $('stats').before(box);
  const log = [];
  return {
    log,
    show(phase, fraction) {
      log.push({ phase, fraction });
      box.hidden = false;
      bar.value = fraction;
      label.textContent = `${phase} ${Math.round(100 * fraction)}%`;
    },
    hide() {
      box.hidden = true;
    },
  };
}

function setStatus(status, text) {
  document.body.dataset.status = status;
  $('stat-status').textContent = text;
}

function showError(message) {
  $('error').textContent = message;
  $('error').hidden = false;
}

function showNotice(message) {
  $('notice').textContent = message;
  $('notice').hidden = false;
}

function hideMessages() {
  $('error').hidden = true;
}

function showStats(s) {
  $('stat-source').textContent = state.source;
  $('stat-points').textContent = format(s.inputPoints);
  $('stat-constraints').textContent = format(s.constraints);
  $('stat-crossings').textContent = format(s.crossings);
  $('stat-threads').textContent = format(s.threads);
  $('stat-vertices').textContent = format(s.vertices);
  $('stat-triangles').textContent = format(s.triangles);
  $('stat-inside').textContent = format(s.insideTriangles);
  $('stat-steiner').textContent = s.refine
    ? `${format(s.refine.steinerPoints)}${s.refine.capped ? ' (capped)' : ''}` : '–';
  $('stat-min-angle').textContent = s.refine
    ? `${s.refine.smallestAngle.toFixed(1)}°${s.refine.skipped
      ? ` (${format(s.refine.skipped)} below, in smaller input angles)` : ''}`
    : '–';
  $('stat-triangulate-ms').textContent = formatMs(s.triangulateMs);
  $('stat-load-ms').textContent = s.loadMs ? formatMs(s.loadMs) : '–';
  $('stat-draw-ms').textContent = formatMs(s.drawMs);
  $('stat-total-ms').textContent = formatMs(s.totalMs);
  $('stat-renderer').textContent = s.renderer;
}

function nextFrame() {
  return new Promise((resolve) => requestAnimationFrame(() => resolve()));
}

// For automated checks and for the curious in the console.
window.geocdtDemo = { map, progress: progress.log, get stats() { return state.stats; } };

loadDataset($('dataset').value);
