// GeoJSON in and out. Coordinates are used as given (lon/lat or projected) and triangulated in
// the plane: no projection, no great circles.
import { MAX_COORDINATE } from './input.js';

// A growable Float64Array, so large inputs never go through number[] of boxed values.
class Coordinates {
  constructor(capacity = 64) {
    this.data = new Float64Array(capacity);
    this.length = 0;
  }

  push(x, y) {
    if (this.length + 2 > this.data.length) {
      const bigger = new Float64Array(this.data.length * 2);
      bigger.set(this.data);
      this.data = bigger;
    }
    this.data[this.length++] = x;
    this.data[this.length++] = y;
  }

  take() {
    return this.data.slice(0, this.length);
  }
}

function position(p, path, into) {
  if (!Array.isArray(p) || p.length < 2) {
    throw new TypeError(`geocdt: ${path} must be a position [x, y], got ${JSON.stringify(p)}`);
  }
  const [x, y] = p;
  for (const [v, axis] of [[x, 0], [y, 1]]) {
    if (typeof v !== 'number') {
      throw new TypeError(`geocdt: ${path}[${axis}] must be a number, got ${JSON.stringify(v)}`);
    }
    if (!(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) {
      throw new RangeError(
        `geocdt: ${path}[${axis}] is ${v}: coordinates must be finite with |value| <= 1e150`);
    }
  }
  into.push(x, y);
}

function list(value, path) {
  if (!Array.isArray(value)) {
    throw new TypeError(`geocdt: ${path} must be an array, got ${JSON.stringify(value)}`);
  }
  return value;
}

function line(coords, path, closeRing) {
  const xy = new Coordinates(2 * coords.length + 2);
  list(coords, path).forEach((p, i) => position(p, `${path}[${i}]`, xy));
  const n = xy.length;
  // GeoJSON rings repeat their first position at the end; close the ones that forgot.
  if (closeRing && n >= 4 && (xy.data[0] !== xy.data[n - 2] || xy.data[1] !== xy.data[n - 1])) {
    xy.push(xy.data[0], xy.data[1]);
  }
  return xy.take();
}

function geometry(g, path, points, polylines) {
  if (g === null) return;  // a Feature without geometry
  if (typeof g !== 'object') {
    throw new TypeError(`geocdt: ${path} must be a GeoJSON geometry, got ${JSON.stringify(g)}`);
  }
  const c = g.coordinates;
  const at = `${path}.coordinates`;
  switch (g.type) {
    case 'Point':
      position(c, at, points);
      break;
    case 'MultiPoint':
      list(c, at).forEach((p, i) => position(p, `${at}[${i}]`, points));
      break;
    case 'LineString':
      polylines.push(line(c, at, false));
      break;
    case 'MultiLineString':
      list(c, at).forEach((l, i) => polylines.push(line(l, `${at}[${i}]`, false)));
      break;
    case 'Polygon':
      list(c, at).forEach((r, i) => polylines.push(line(r, `${at}[${i}]`, true)));
      break;
    case 'MultiPolygon':
      list(c, at).forEach((poly, i) =>
        list(poly, `${at}[${i}]`).forEach((r, j) =>
          polylines.push(line(r, `${at}[${i}][${j}]`, true))));
      break;
    case 'GeometryCollection':
      list(g.geometries, `${path}.geometries`).forEach((child, i) =>
        geometry(child, `${path}.geometries[${i}]`, points, polylines));
      break;
    default:
      throw new TypeError(
        `geocdt: ${path}.type ${JSON.stringify(g.type)} is not a GeoJSON geometry type`);
  }
}

// A FeatureCollection, Feature or geometry -> { points, polylines } for triangulate():
// Point and MultiPoint become points; LineString and MultiLineString become constraints;
// every Polygon and MultiPolygon ring becomes a closed constraint that bounds the inside.
export function geoJSONToInput(geojson) {
  if (geojson === null || typeof geojson !== 'object') {
    const got = geojson === null ? 'null' : typeof geojson;
    throw new TypeError(`geocdt: expected a GeoJSON object, got ${got}`);
  }
  const points = new Coordinates();
  const polylines = [];
  if (geojson.type === 'FeatureCollection') {
    list(geojson.features, 'features').forEach((f, i) => {
      if (f === null || typeof f !== 'object' || f.type !== 'Feature') {
        throw new TypeError(`geocdt: features[${i}] is not a GeoJSON Feature`);
      }
      geometry(f.geometry, `features[${i}].geometry`, points, polylines);
    });
  } else if (geojson.type === 'Feature') {
    geometry(geojson.geometry, 'geometry', points, polylines);
  } else {
    geometry(geojson, 'geometry', points, polylines);
  }
  return { points: points.take(), polylines };
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
