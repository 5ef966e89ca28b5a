// Benchmark inputs: uniform points, and Natural Earth countries from npm world-atlas.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { feature, mesh } from 'topojson-client';

// The polyline forms' conversions, shared with the tests.
export { flatPolylines, polylineArrays } from '../../tests/js/support/inputs.js';

// n points uniform in [0, 1000)², from Lehmer's minimal standard generator: the benchmarks'
// points since their first figures (the tests' uniform() draws others, with xorshift32).
export function uniformLehmer(n, seed = 12345) {
  let s = seed;
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < 2 * n; i++) {
    s = (s * 16807) % 2147483647;
    xy[i] = (s / 2147483647) * 1000;
  }
  return xy;
}

const require = createRequire(import.meta.url);

function topology(scale) {
  return JSON.parse(readFileSync(require.resolve(`world-atlas/countries-${scale}.json`), 'utf8'));
}

// Every ring of every country as its own closed polyline: shared borders overlap.
// Also the polygons, for earcut: [{ coords: [x, y, ...], holes: [start index, ...] }].
export function countryRings(scale) {
  const fc = feature(topology(scale), topology(scale).objects.countries);
  const polylines = [];
  const polygons = [];
  for (const f of fc.features) {
    const g = f.geometry;
    if (!g) continue;
    const parts = g.type === 'Polygon' ? [g.coordinates] : g.coordinates;
    for (const rings of parts) {
      const coords = [];
      const holes = [];
      for (const [i, ring] of rings.entries()) {
        polylines.push(Float64Array.from(ring.flat()));
        if (i > 0) holes.push(coords.length / 2);
        for (const [x, y] of ring.slice(0, -1)) coords.push(x, y);
      }
      polygons.push({ coords, holes });
    }
  }
  return { name: `Natural Earth ${scale} country rings`, polylines, polygons };
}

// The borders and coasts once each: the mesh of the topology's arcs.
export function countryArcs(scale) {
  const t = topology(scale);
  const m = mesh(t, t.objects.countries);
  const polylines = m.coordinates.map((l) => Float64Array.from(l.flat()));
  return { name: `Natural Earth ${scale} arcs`, polylines };
}

export function pointCount(polylines) {
  return polylines.reduce((s, l) => s + l.length / 2, 0);
}

// Deduplicated points and index edges, the input form of constrainautor, cdt2d and Triangle.
export function indexedGraph(polylines) {
  const ids = new Map();
  const xy = [];
  const edges = [];
  const id = (x, y) => {
    const key = `${x},${y}`;
    let i = ids.get(key);
    if (i === undefined) {
      i = xy.length / 2;
      ids.set(key, i);
      xy.push(x, y);
    }
    return i;
  };
  for (const line of polylines) {
    let prev = id(line[0], line[1]);
    for (let k = 2; k < line.length; k += 2) {
      const cur = id(line[k], line[k + 1]);
      if (cur !== prev) edges.push([prev, cur]);
      prev = cur;
    }
  }
  return { xy: Float64Array.from(xy), edges };
}

// A .gpl file ("GPL1", uint32 P, uint32 count[P], float64 x, y of every point) as the flat
// polylines form: { coords, offsets }.
export function readGpl(path) {
  const bytes = readFileSync(path);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const lines = view.getUint32(4, true);
  const offsets = new Uint32Array(lines + 1);
  for (let i = 0; i < lines; i++) offsets[i + 1] = offsets[i] + view.getUint32(8 + 4 * i, true);
  const start = 8 + 4 * lines;
  const coords = new Float64Array(2 * offsets[lines]);
  new Uint8Array(coords.buffer).set(bytes.subarray(start, start + coords.byteLength));
  return { coords, offsets };
}
