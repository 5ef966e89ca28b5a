// Deterministic test inputs.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { feature } from 'topojson-client';

export function random(seed = 1) {
  let s = seed >>> 0 || 1;
  return () => {
    // xorshift32: fast, deterministic, good enough to scatter points.
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s / 4294967296;
  };
}

export function uniform(n, seed = 1, scale = 1000) {
  const rnd = random(seed);
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < 2 * n; i++) xy[i] = rnd() * scale;
  return xy;
}

export function gaussianClusters(n, seed = 2) {
  const rnd = random(seed);
  const xy = new Float64Array(2 * n);
  const centres = Array.from({ length: 5 }, () => [rnd() * 100, rnd() * 100]);
  for (let i = 0; i < n; i++) {
    const [cx, cy] = centres[i % centres.length];
    const r = Math.sqrt(-2 * Math.log(rnd() + 1e-12));
    const a = 2 * Math.PI * rnd();
    xy[2 * i] = cx + r * Math.cos(a);
    xy[2 * i + 1] = cy + r * Math.sin(a);
  }
  return xy;
}

export function lattice(side) {
  const xy = new Float64Array(2 * side * side);
  for (let i = 0, k = 0; i < side; i++) for (let j = 0; j < side; j++) {
    xy[k++] = i;
    xy[k++] = j;
  }
  return xy;
}

export function circle(n, r = 1) {
  const xy = new Float64Array(2 * n);
  for (let i = 0; i < n; i++) {
    xy[2 * i] = r * Math.cos((2 * Math.PI * i) / n);
    xy[2 * i + 1] = r * Math.sin((2 * Math.PI * i) / n);
  }
  return xy;
}

export function scaled(xy, factor, offset = 0) {
  return xy.map((v) => v * factor + offset);
}

// An array of polylines (x, y arrays) -> the flat form { coords, offsets }, GeoArrow's layout.
export function flatPolylines(polylines) {
  const offsets = new Uint32Array(polylines.length + 1);
  polylines.forEach((line, i) => { offsets[i + 1] = offsets[i] + line.length / 2; });
  const coords = new Float64Array(2 * offsets[polylines.length]);
  polylines.forEach((line, i) => coords.set(line, 2 * offsets[i]));
  return { coords, offsets };
}

// The flat form -> one Float64Array per polyline.
export function polylineArrays({ coords, offsets }) {
  const lines = [];
  for (let i = 0; i + 1 < offsets.length; i++) {
    lines.push(Float64Array.from(coords.slice(2 * offsets[i], 2 * offsets[i + 1])));
  }
  return lines;
}

// Natural Earth countries (world-atlas through topojson-client) as a GeoJSON
// FeatureCollection: shared borders, touching corners, enclaves, and rings across the
// antimeridian that overlap others in the plane. scale: '110m', '50m' or '10m'.
export function countries(scale) {
  const require = createRequire(import.meta.url);
  const topology =
    JSON.parse(readFileSync(require.resolve(`world-atlas/countries-${scale}.json`), 'utf8'));
  return feature(topology, topology.objects.countries);
}
