// GeoJSON in and out. Coordinates are used as given (lon/lat or projected) and triangulated in
// the plane: no projection, no great circles.
import { MAX_COORDINATE } from './input.js';

// A growable typed array, so large inputs never go through number[] of boxed values.
class Growable {
  constructor(Type, capacity = 64) {
    this.data = new Type(capacity);
    this.length = 0;
  }

  reserve(more) {
    if (this.length + more <= this.data.length) return;
    const bigger = new this.data.constructor(Math.max(2 * this.data.length, this.length + more));
    bigger.set(this.data);
    this.data = bigger;
  }

  push(x, y) {
    this.reserve(2);
    this.data[this.length++] = x;
    this.data[this.length++] = y;
  }

  take() {
    return this.data.slice(0, this.length);
  }
}

// The name of position i (-1: the position itself) of the array at path, and of one of its
// coordinates: built only for an error message.
const where = (path, i, axis = -1) =>
  `${path}${i < 0 ? '' : `[${i}]`}${axis < 0 ? '' : `[${axis}]`}`;

function coordinate(v, path, i, axis) {
  if (typeof v !== 'number') {
    throw new TypeError(
      `geocdt: ${where(path, i, axis)} must be a number, got ${JSON.stringify(v)}`);
  }
  if (!(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) {
    throw new RangeError(`geocdt: ${where(path, i, axis)} is ${v}: coordinates must be finite `
      + 'with |value| <= 1e150');
  }
  return v;
}

// Reads position i of the array at path into `into`.
function position(p, path, i, into) {
  if (!Array.isArray(p) || p.length < 2) {
    throw new TypeError(
      `geocdt: ${where(path, i)} must be a position [x, y], got ${JSON.stringify(p)}`);
  }
  into.push(coordinate(p[0], path, i, 0), coordinate(p[1], path, i, 1));
}

function list(value, path) {
  if (!Array.isArray(value)) {
    throw new TypeError(`geocdt: ${path} must be an array, got ${JSON.stringify(value)}`);
  }
  return value;
}

// Appends one polyline to the flat lines ({ coords, offsets }).
function line(positions, path, closeRing, lines) {
  const { coords, offsets } = lines;
  list(positions, path);
  const start = coords.length;
  coords.reserve(2 * positions.length + 2);
  for (let i = 0; i < positions.length; i++) position(positions[i], path, i, coords);
  const n = coords.length - start;
  const d = coords.data;
  // GeoJSON rings repeat their first position at the end; close the ones that forgot.
  if (closeRing && n >= 4 && (d[start] !== d[start + n - 2] || d[start + 1] !== d[start + n - 1])) {
    coords.push(d[start], d[start + 1]);
  }
  offsets.reserve(1);
  offsets.data[offsets.length++] = coords.length / 2;
}

function geometry(g, path, points, lines) {
  if (g === null) return;  // a Feature without geometry
  if (typeof g !== 'object') {
    throw new TypeError(`geocdt: ${path} must be a GeoJSON geometry, got ${JSON.stringify(g)}`);
  }
  const c = g.coordinates;
  const at = `${path}.coordinates`;
  switch (g.type) {
    case 'Point':
      position(c, at, -1, points);
      break;
    case 'MultiPoint':
      list(c, at).forEach((p, i) => position(p, at, i, points));
      break;
    case 'LineString':
      line(c, at, false, lines);
      break;
    case 'MultiLineString':
      list(c, at).forEach((l, i) => line(l, `${at}[${i}]`, false, lines));
      break;
    case 'Polygon':
      list(c, at).forEach((r, i) => line(r, `${at}[${i}]`, true, lines));
      break;
    case 'MultiPolygon':
      list(c, at).forEach((poly, i) =>
        list(poly, `${at}[${i}]`).forEach((r, j) => line(r, `${at}[${i}][${j}]`, true, lines)));
      break;
    case 'GeometryCollection':
      list(g.geometries, `${path}.geometries`).forEach((child, i) =>
        geometry(child, `${path}.geometries[${i}]`, points, lines));
      break;
    default:
      throw new TypeError(
        `geocdt: ${path}.type ${JSON.stringify(g.type)} is not a GeoJSON geometry type`);
  }
}

// A FeatureCollection, Feature or geometry -> { points, polylines: { coords, offsets } }, the
// flat input of triangulate(): no array per ring. Point and MultiPoint become points;
// LineString and MultiLineString become constraints; every Polygon and MultiPolygon ring
// becomes a closed constraint that bounds the inside.
export function readGeoJSON(geojson) {
  if (geojson === null || typeof geojson !== 'object') {
    const got = geojson === null ? 'null' : typeof geojson;
    throw new TypeError(`geocdt: expected a GeoJSON object, got ${got}`);
  }
  const points = new Growable(Float64Array);
  const lines = { coords: new Growable(Float64Array), offsets: new Growable(Uint32Array) };
  lines.offsets.data[lines.offsets.length++] = 0;
  if (geojson.type === 'FeatureCollection') {
    list(geojson.features, 'features').forEach((f, i) => {
      if (f === null || typeof f !== 'object' || f.type !== 'Feature') {
        throw new TypeError(`geocdt: features[${i}] is not a GeoJSON Feature`);
      }
      geometry(f.geometry, `features[${i}].geometry`, points, lines);
    });
  } else if (geojson.type === 'Feature') {
    geometry(geojson.geometry, 'geometry', points, lines);
  } else {
    geometry(geojson, 'geometry', points, lines);
  }
  return {
    points: points.take(),
    polylines: { coords: lines.coords.take(), offsets: lines.offsets.take() },
  };
}

// The same, with { flat: false } (the default) as one Float64Array per polyline.
export function geoJSONToInput(geojson, { flat = false } = {}) {
  const input = readGeoJSON(geojson);
  if (flat) return input;
  const { coords, offsets } = input.polylines;
  const polylines = new Array(offsets.length - 1);
  for (let i = 0; i < polylines.length; i++) {
    polylines[i] = coords.slice(2 * offsets[i], 2 * offsets[i + 1]);
  }
  return { points: input.points, polylines };
}

// The output option of triangulateGeoJSON(), shared with the worker client.
export function geoJSONOutput(options) {
  const { output = 'geojson', ...rest } = options ?? {};
  if (output !== 'geojson' && output !== 'arrays') {
    throw new TypeError(
      `geocdt: options.output must be 'geojson' or 'arrays', got ${JSON.stringify(output)}`);
  }
  return { output, rest };
}

// A mesh from triangulate() -> a FeatureCollection with one counter-clockwise Polygon per
// triangle. Each feature's id is its triangle index; properties.inside is set when the mesh
// has inside flags.
export function meshToGeoJSON(mesh) {
  const { points, triangles, inside } = mesh;
  const n = triangles.length / 3;
  const features = new Array(n);
  const at = (v) => [points[2 * v], points[2 * v + 1]];
  for (let t = 0; t < n; t++) {
    const a = at(triangles[3 * t]);
    features[t] = {
      type: 'Feature',
      id: t,
      properties: inside ? { inside: inside[t] === 1 } : {},
      geometry: {
        type: 'Polygon',
        coordinates: [[a, at(triangles[3 * t + 1]), at(triangles[3 * t + 2]), [a[0], a[1]]]],
      },
    };
  }
  return { type: 'FeatureCollection', features };
}
