// The tiles page: a region of real vector tiles, every polygon filled by one
// triangulatePolygons() call, or by earcut polygon by polygon, with earcut's wrong polygons
// counted and outlined. document.body.dataset.status says what the page is doing (the
// browser test waits on it).
import earcut from 'earcut';
import { init, triangulatePolygons } from 'geocdt';
import { decodeRegion, earcutPolygon, tileGrid } from './tiles-data.js';
import { TileView } from './tiles-view.js';
import './style.css';
import './tiles.css';

const $ = (id) => document.getElementById(id);
let view = null;  // made once the page has its size
let current = null;  // { region, geocdt, earcut, wrong }
// The region shown first: one where earcut fills a polygon wrongly.
const FIRST_REGION = 'nepal';

function setStatus(status, text = status) {
  document.body.dataset.status = status;
  $('stat-status').textContent = text;
}

const number = (n) => n.toLocaleString('en-US');

// Twice the area of triangles, each |area| summed: x(i), y(i) give the corners.
function doubledArea(triangles, from, to, x, y) {
  let sum = 0;
  for (let i = from; i < to; i += 3) {
    const a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
    sum += Math.abs((x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a)));
  }
  return sum;
}

function runGeocdt(region) {
  const started = performance.now();
  const r = triangulatePolygons({
    coords: region.coords, ringOffsets: region.ringOffsets, polygonOffsets: region.polygonOffsets,
  });
  return { ...r, ms: performance.now() - started };
}

function runEarcut(region) {
  const polygons = region.polygonOffsets.length - 1;
  const inputs = [];
  for (let p = 0; p < polygons; p++) inputs.push(earcutPolygon(region, p));
  const started = performance.now();
  const triangles = inputs.map(({ data, holes }) => earcut(data, holes));
  return { inputs, triangles, ms: performance.now() - started };
}

// Polygons whose earcut triangles' area is off geocdt's (the area inside) by more than 1e-9.
function wrongPolygons(region, g, e) {
  const { coords } = region;
  const n = coords.length / 2;
  const gx = (i) => (i < n ? coords[2 * i] : g.extraPoints[2 * (i - n)]);
  const gy = (i) => (i < n ? coords[2 * i + 1] : g.extraPoints[2 * (i - n) + 1]);
  const wrong = [];
  e.triangles.forEach((t, p) => {
    const inside = doubledArea(g.triangles, 3 * g.triangleOffsets[p],
      3 * g.triangleOffsets[p + 1], gx, gy);
    const { data } = e.inputs[p];
    const got = doubledArea(t, 0, t.length, (i) => data[2 * i], (i) => data[2 * i + 1]);
    if (Math.abs(got - inside) > 1e-9 * inside) wrong.push({ p, got: got / 2, inside: inside / 2 });
  });
  return wrong;
}

function fillWith(which) {
  const { region, geocdt: g, earcut: e } = current;
  const { coords } = region;
  const n = coords.length / 2;
  const gx = (i) => (i < n ? coords[2 * i] : g.extraPoints[2 * (i - n)]);
  const gy = (i) => (i < n ? coords[2 * i + 1] : g.extraPoints[2 * (i - n) + 1]);
  if (which === 'geocdt') {
    view.setFill(g.triangles.length / 3, (p, emit) => {
      const t = g.triangles;
      for (let i = 3 * g.triangleOffsets[p]; i < 3 * g.triangleOffsets[p + 1]; i += 3) {
        emit(gx(t[i]), gy(t[i]), gx(t[i + 1]), gy(t[i + 1]), gx(t[i + 2]), gy(t[i + 2]));
      }
    });
  } else {
    view.setFill(e.triangles.reduce((s, t) => s + t.length / 3, 0), (p, emit) => {
      const t = e.triangles[p], { data } = e.inputs[p];
      for (let i = 0; i < t.length; i += 3) {
        emit(data[2 * t[i]], data[2 * t[i] + 1], data[2 * t[i + 1]], data[2 * t[i + 1] + 1],
          data[2 * t[i + 2]], data[2 * t[i + 2] + 1]);
      }
    });
  }
  view.draw();
}

function showStats() {
  const { region, geocdt: g, earcut: e, wrong } = current;
  $('stat-tiles').textContent = number(region.tiles.length);
  $('stat-polygons').textContent = number(region.polygonOffsets.length - 1);
  $('stat-vertices').textContent = number(region.coords.length / 2);
  $('stat-geocdt-ms').textContent = `${g.ms.toFixed(1)} ms`;
  $('stat-earcut-ms').textContent = `${e.ms.toFixed(1)} ms`;
  $('stat-geocdt-triangles').textContent = number(g.triangles.length / 3);
  $('stat-earcut-triangles').textContent =
    number(e.triangles.reduce((s, t) => s + t.length / 3, 0));
  $('stat-crossings').textContent = number(g.stats.crossings);
  $('stat-threads').textContent = number(g.stats.threads);
  $('stat-wrong').textContent = number(wrong.length);
  const list = $('wrong-list');
  list.replaceChildren(...wrong.map(({ p, got, inside }) => {
    const item = document.createElement('li');
    const link = document.createElement('a');
    link.href = '#';
    link.textContent = `polygon ${p} (${region.layers[region.polygonLayers[p]]}): earcut fills `
      + `${number(Math.round(got))}, inside ${number(Math.round(inside))}`;
    link.addEventListener('click', (event) => {
      event.preventDefault();
      view.zoomTo(view.polygonBox(p));
      view.draw();
    });
    item.append(link);
    return item;
  }));
}

function highlight() {
  view.setOutlines($('highlight').checked ? current.wrong.map((w) => w.p) : []);
}

async function loadRegion(name) {
  setStatus('loading', `loading ${name}`);
  const response = await fetch(`./data/tiles-${name}.bin`);
  if (!response.ok) throw new Error(`could not fetch the ${name} tiles: HTTP ${response.status}`);
  const region = decodeRegion(await response.arrayBuffer());
  setStatus('triangulating', 'triangulating');
  await new Promise((resolve) => setTimeout(resolve, 0));  // let the status show
  const geocdt = runGeocdt(region);
  const e = runEarcut(region);
  current = { region, geocdt, earcut: e, wrong: wrongPolygons(region, geocdt, e) };
  view.setRegion(region, tileGrid(region.tiles));
  highlight();
  fillWith(document.querySelector('input[name="fill"]:checked').value);
  showStats();
  setStatus('ready');
}

function fail(error) {
  console.error(error);
  $('error').hidden = false;
  $('error').textContent = String(error?.message ?? error);
  setStatus('failed');
}

function listenToTheView() {
  const canvas = $('view');
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => {
    drag = [e.clientX, e.clientY];
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const ratio = globalThis.devicePixelRatio || 1;
    view.pan((e.clientX - drag[0]) * ratio, (e.clientY - drag[1]) * ratio);
    drag = [e.clientX, e.clientY];
    view.draw();
  });
  canvas.addEventListener('pointerup', () => { drag = null; });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const ratio = globalThis.devicePixelRatio || 1;
    view.zoomAt(e.offsetX * ratio, e.offsetY * ratio, Math.exp(-e.deltaY / 500));
    view.draw();
  }, { passive: false });
  globalThis.addEventListener('resize', () => {
    if (!current) return;
    view.fit();
    view.draw();
  });
}

async function main() {
  view = new TileView($('view'), $('overlay'));
  listenToTheView();
  const [regions] = await Promise.all([
    fetch('./data/tiles-regions.json').then((r) => r.json()), init({ threads: 'auto' })]);
  const select = $('region');
  for (const name of regions) select.append(new Option(name, name));
  const asked = new URLSearchParams(location.search).get('region');
  select.value = regions.includes(asked) ? asked : FIRST_REGION;
  select.addEventListener('change', () => loadRegion(select.value).catch(fail));
  for (const radio of document.querySelectorAll('input[name="fill"]')) {
    radio.addEventListener('change', () => {
      setStatus('drawing');
      fillWith(radio.value);
      setStatus('ready');
    });
  }
  $('edges').addEventListener('change', () => {
    view.showEdges = $('edges').checked;
    view.draw();
  });
  $('highlight').addEventListener('change', () => {
    highlight();
    view.draw();
  });
  await loadRegion(select.value);
}

main().catch(fail);
