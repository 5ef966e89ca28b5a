// Builds the demo's three bundled datasets (world-110m, world-50m, world-10m) from npm
// `world-atlas` (Natural Earth) and the committed GSHHG river extracts in demo/data/.
// Each one holds land rings (inside/outside comes from them), country borders and rivers.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { feature, mesh } from 'topojson-client';
import { encodeDataset } from '../src/dataset-codec.js';

const require = createRequire(import.meta.url);

export const DATASETS = [
  { name: 'world-110m', atlas: '110m', rivers: 'c', riverLevels: [1, 2] },
  { name: 'world-50m', atlas: '50m', rivers: 'i', riverLevels: [1, 2] },
  { name: 'world-10m', atlas: '10m', rivers: 'i', riverLevels: [1, 2, 3, 4] },
];

function readTopology(path) {
  return JSON.parse(readFileSync(path, 'utf8'));
}

// Back to the topology's integer grid: the coordinates were quantized on it, so this is exact.
function quantize(topology, coordinates) {
  const [sx, sy] = topology.transform.scale;
  const [tx, ty] = topology.transform.translate;
  const q = new Array(2 * coordinates.length);
  for (let i = 0; i < coordinates.length; i++) {
    q[2 * i] = Math.round((coordinates[i][0] - tx) / sx);
    q[2 * i + 1] = Math.round((coordinates[i][1] - ty) / sy);
  }
  return q;
}

// world-atlas is made for spherical rendering: a line that crosses the antimeridian jumps
// from +179 to -179 degrees, which on a flat map is an edge across the whole world. Such a
// line is cut where it crosses, at +-180 with the crossing latitude on both sides; a ring
// crossing twice becomes two rings closed along the meridian. Rings around a pole
// (Antarctica's, which cross once) stay as they are: their jump runs along the map's edge.
function jumpsAt(line) {
  const at = [];
  for (let i = 1; i < line.length; i++) if (Math.abs(line[i][0] - line[i - 1][0]) > 180) at.push(i);
  return at;
}

function crossing(a, b) {
  const side = a[0] > 0 ? 180 : -180;
  const bx = b[0] + 2 * side; // b moved next to a
  const lat = bx === a[0] ? a[1] : a[1] + ((b[1] - a[1]) * (side - a[0])) / (bx - a[0]);
  return [[side, lat], [-side, lat]]; // the end of a's piece, the start of b's
}

function cutLine(line) {
  const pieces = [[line[0]]];
  for (let i = 1; i < line.length; i++) {
    if (Math.abs(line[i][0] - line[i - 1][0]) > 180) {
      const [end, start] = crossing(line[i - 1], line[i]);
      pieces[pieces.length - 1].push(end);
      pieces.push([start]);
    }
    pieces[pieces.length - 1].push(line[i]);
  }
  return pieces;
}

function cutRing(ring) {
  const jumps = jumpsAt(ring);
  if (jumps.length === 0 || jumps.length % 2 === 1) return [ring];
  // Start the ring just after a jump, so that every piece runs from meridian to meridian.
  const open = ring.slice(0, -1);
  const first = jumps[0] % open.length;
  const rotated = [...open.slice(first), ...open.slice(0, first)];
  const pieces = cutLine(rotated);
  const [end, start] = crossing(rotated[rotated.length - 1], rotated[0]);
  pieces[pieces.length - 1].push(end);
  pieces[0].unshift(start);
  return pieces.map((p) => [...p, p[0]]);
}

// A closed line that is not meant as a ring (a border around an enclave, a river loop)
// is cut in two open halves, so that it adds constraints but never flips inside/outside.
function openLines(q) {
  const n = q.length / 2;
  const closed = n > 2 && q[0] === q[2 * n - 2] && q[1] === q[2 * n - 1];
  if (!closed) return [q];
  const mid = Math.floor(n / 2);
  return [q.slice(0, 2 * mid + 2), q.slice(2 * mid)];
}

function layerOf(topology, name, role, lines) {
  const { scale, translate } = topology.transform;
  return { name, role, scale, translate, lines };
}

export function buildDataset({ atlas, rivers, riverLevels }, dataDir) {
  const land = readTopology(require.resolve(`world-atlas/land-${atlas}.json`));
  const countries = readTopology(require.resolve(`world-atlas/countries-${atlas}.json`));
  const riverTopology = readTopology(new URL(`rivers-${rivers}.topo.json`, dataDir));

  const rings = [];
  const landGeometry = feature(land, land.objects.land);
  for (const f of landGeometry.features ?? [landGeometry]) {
    const g = f.geometry;
    const polygons = g.type === 'Polygon' ? [g.coordinates] : g.coordinates;
    for (const polygon of polygons) {
      for (const ring of polygon) {
        for (const piece of cutRing(ring)) rings.push(quantize(land, piece));
      }
    }
  }

  // Borders between two countries only: coastlines are already the land rings.
  const borderMesh = mesh(countries, countries.objects.countries, (a, b) => a !== b);
  const borders = borderMesh.coordinates.flatMap((line) =>
    cutLine(line).flatMap((piece) => openLines(quantize(countries, piece))));

  const levels = new Set(riverLevels);
  const riverObject = {
    ...riverTopology.objects.rivers,
    geometries: riverTopology.objects.rivers.geometries
      .filter((g) => levels.has(g.properties.level)),
  };
  const riverLines = feature(riverTopology, riverObject).features.flatMap((f) =>
    cutLine(f.geometry.coordinates).flatMap((piece) => openLines(quantize(riverTopology, piece))));

  return encodeDataset([
    layerOf(land, 'land', 'ring', rings),
    layerOf(countries, 'borders', 'line', borders),
    layerOf(riverTopology, 'rivers', 'line', riverLines),
  ]);
}

// { 'data/world-110m.bin': Uint8Array, ... }
export function buildAllDatasets(dataDir = new URL('../data/', import.meta.url)) {
  const files = {};
  for (const d of DATASETS) files[`data/${d.name}.bin`] = buildDataset(d, dataDir);
  return files;
}
