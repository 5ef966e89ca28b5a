// The Voronoi page: sites scattered, clicked or dropped; their cells clipped to the land (or the
// sites' hull, or the view) by the worker; Lloyd's relaxation on demand.
import 'leaflet/dist/leaflet.css';
import './style.css';
import L from 'leaflet';
import { projectLonLat } from './mercator.js';
import { VoronoiLayer } from './voronoi-layer.js';

const MAX_FILE_BYTES = 200 * 1024 * 1024;
const $ = (id) => document.getElementById(id);
const format = (n) => n.toLocaleString('en');
const formatMs = (ms) => `${ms < 10 ? ms.toFixed(1) : Math.round(ms).toLocaleString('en')} ms`;

const map = L.map('map', { minZoom: 1, maxZoom: 19 }).setView([25, 10], 2);
map.attributionControl.setPrefix('<a href="https://leafletjs.com/">Leaflet</a>');
map.attributionControl.addAttribution('Natural Earth (public domain)');
const layer = new VoronoiLayer().addTo(map);

// Requests to the worker, answered in order; a crash rejects what is pending.
const worker = (() => {
  let w = null;
  let next = 1;
  const pending = new Map();
  const start = () => {
    w = new Worker(new URL('./voronoi-worker.js', import.meta.url), { type: 'module' });
    w.onmessage = ({ data }) => {
      const p = pending.get(data.id);
      pending.delete(data.id);
      if (data.ok) p?.resolve(data);
      else p?.reject(new Error(data.error));
    };
    w.onerror = (e) => {
      e.preventDefault();
      for (const p of pending.values()) p.reject(new Error(`the worker crashed: ${e.message}`));
      pending.clear();
      w = null;
    };
  };
  return (type, payload = {}, transfer = []) => {
    if (!w) start();
    const id = next++;
    return new Promise((resolve, reject) => {
      pending.set(id, { resolve, reject });
      w.postMessage({ id, type, ...payload }, transfer);
    });
  };
})();

const state = { sites: new Float64Array(0), bounds: [-180, -60, 180, 80], stats: null, seed: 1 };

function random() {
  state.seed = (state.seed * 16807) % 2147483647;
  return state.seed / 2147483647;
}

function setStatus(status, text) {
  document.body.dataset.status = status;
  $('stat-status').textContent = text;
}

function showError(message) {
  $('error').textContent = message;
  $('error').hidden = !message;
}

// The cells' total area (outer rings positive, holes negative) and how many cells have any.
function measure(cells) {
  const { coords: p, ringOffsets, siteOffsets } = cells;
  let area = 0;
  for (let r = 0; r + 1 < ringOffsets.length; r++) {
    const b = ringOffsets[r];
    for (let k = b + 1; k + 1 < ringOffsets[r + 1]; k++) {
      area += ((p[2 * k] - p[2 * b]) * (p[2 * k + 3] - p[2 * b + 1])
        - (p[2 * k + 1] - p[2 * b + 1]) * (p[2 * k + 2] - p[2 * b])) / 2;
    }
  }
  let withArea = 0;
  for (let i = 0; i + 1 < siteOffsets.length; i++) withArea += siteOffsets[i + 1] > siteOffsets[i];
  return { area, withArea };
}

// The view as a box in metres, for clip: 'box'.
function viewBox() {
  const b = map.getBounds();
  const sw = L.CRS.EPSG3857.project(b.getSouthWest());
  const ne = L.CRS.EPSG3857.project(b.getNorthEast());
  return [sw.x, sw.y, ne.x, ne.y];
}

async function update(lloyd = 0) {
  if (state.sites.length === 0) {
    layer.setCells(null, state.sites);
    state.stats = { sites: 0 };
    $('stat-sites').textContent = '0';
    setStatus('ready', 'ready: no sites');
    return;
  }
  setStatus('working', lloyd ? 'relaxing…' : 'making cells…');
  try {
    const clip = $('clip').value;
    const reply = await worker('cells', { sites: state.sites, clip, box: viewBox(), lloyd });
    const { cells } = reply;
    if (cells.points) state.sites = cells.points;
    const drawStarted = performance.now();
    layer.setCells(cells, state.sites);
    await new Promise((resolve) => requestAnimationFrame(resolve));
    const { area, withArea } = measure(cells);
    state.stats = {
      sites: state.sites.length / 2, cells: withArea, polygons: cells.stats.polygons,
      clipped: cells.stats.clippedCells, crossings: cells.stats.crossings, area,
      domainArea: cells.stats.domainArea, lloyd: cells.lloyd, ms: reply.ms,
      drawMs: performance.now() - drawStarted,
    };
    showStats(state.stats);
    showError('');
    setStatus('ready', 'ready');
  } catch (e) {
    showError(e.message);
    setStatus('error', 'error');
  }
}

function showStats(s) {
  $('stat-sites').textContent = format(s.sites);
  $('stat-cells').textContent = format(s.cells);
  $('stat-polygons').textContent = format(s.polygons);
  $('stat-clipped').textContent = format(s.clipped);
  $('stat-crossings').textContent = format(s.crossings);
  $('stat-area').textContent = s.domainArea > 0
    ? `1 ${s.area >= s.domainArea ? '+' : '−'} ${(Math.abs(s.area / s.domainArea - 1))
      .toExponential(1)}` : '–';
  $('stat-lloyd').textContent = s.lloyd
    ? `${s.lloyd.iterations} steps, last moved ${format(Math.round(s.lloyd.movement))} m` : '–';
  $('stat-ms').textContent = formatMs(s.ms);
  $('stat-draw-ms').textContent = formatMs(s.drawMs);
}

function scatter() {
  const n = Number($('count').value);
  const [west, south, east, north] = state.bounds;
  const lonLat = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    lonLat[2 * i] = west + (east - west) * random();
    lonLat[2 * i + 1] = south + (north - south) * random();
  }
  state.sites = projectLonLat(lonLat);
  return update();
}

async function loadDataset(name) {
  setStatus('working', `loading ${name}…`);
  try {
    await worker('dataset', { url: new URL(`data/${name}.bin`, document.baseURI).href });
    state.bounds = [-180, -60, 180, 80];
    if (state.sites.length > 0) await update();
  } catch (e) {
    showError(e.message);
    setStatus('failed', 'error');
  }
}

async function loadFile(file) {
  if (!file) return;
  if (file.size > MAX_FILE_BYTES) {
    showError(`${file.name}: too big for the demo (${format(file.size)} bytes)`);
    return;
  }
  const bytes = await file.arrayBuffer();
  setStatus('working', `reading ${file.name}…`);
  try {
    const reply = await worker('geojson', { bytes }, [bytes]);
    if (reply.sites.length > 0) state.sites = reply.sites;
    state.bounds = reply.bounds;
    $('clip').value = reply.rings > 0 ? 'rings' : 'hull';
    await update();
  } catch (e) {
    showError(`${file.name}: ${e.message}`);
    setStatus('error', 'error');
  }
}

map.on('click', (e) => {
  const p = L.CRS.EPSG3857.project(e.latlng);
  const sites = new Float64Array(state.sites.length + 2);
  sites.set(state.sites);
  sites[state.sites.length] = p.x;
  sites[state.sites.length + 1] = p.y;
  state.sites = sites;
  update();
});
map.on('moveend', () => $('clip').value === 'box' && update());
$('dataset').addEventListener('change', (e) => loadDataset(e.target.value));
$('clip').addEventListener('change', () => update());
$('scatter').addEventListener('click', () => scatter());
$('relax').addEventListener('click', () => update(10));
$('clear').addEventListener('click', () => {
  state.sites = new Float64Array(0);
  update();
});
$('file').addEventListener('change', (e) => {
  loadFile(e.target.files[0]);
  e.target.value = '';
});
$('map').addEventListener('dragover', (e) => e.preventDefault());
$('map').addEventListener('drop', (e) => {
  e.preventDefault();
  loadFile(e.dataTransfer.files[0]);
});

// For automated checks and for the curious in the console.
window.geocdtVoronoiDemo = { map, get stats() { return state.stats; } };

(async () => {
  await loadDataset($('dataset').value);
  await scatter();
})();
