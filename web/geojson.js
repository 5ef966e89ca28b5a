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

  add(v) {
    this.reserve(1);
    this.data[this.length++] = v;
  }

  // The values, without a copy when they fill the array (its capacity was counted right).
  take() {
    return this.length === this.data.length ? this.data : this.data.slice(0, this.length);
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
  if (axis < 2 && !(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) {
    throw new RangeError(`geocdt: ${where(path, i, axis)} is ${v}: coordinates must be finite `
      + 'with |value| <= 1e150');
  }
  return v;
}

// Positions: x, y pairs, and a height each once one of them has had one (NaN for the others):
// inputs without heights never pay for them.
class Positions {
  constructor(capacity) {
    this.xy = new Growable(Float64Array, 2 * capacity);
    this.z = null;
  }

  get count() { return this.xy.length / 2; }

  // Appends position i of the array at path.
  add(p, path, i) {
    if (!Array.isArray(p) || p.length < 2) {
      throw new TypeError(
        `geocdt: ${where(path, i)} must be a position [x, y], got ${JSON.stringify(p)}`);
    }
    this.xy.push(coordinate(p[0], path, i, 0), coordinate(p[1], path, i, 1));
    if (p.length > 2) {
      if (this.z === null) {
        this.z = new Growable(Float64Array, this.xy.data.length / 2);
        this.z.data.fill(NaN);
        this.z.length = this.count - 1;
      }
      this.z.add(coordinate(p[2], path, i, 2));
    } else if (this.z !== null) {
      this.z.add(NaN);
    }
  }

  // Repeats position k (a ring's first, to close it).
  repeat(k) {
    this.xy.push(this.xy.data[2 * k], this.xy.data[2 * k + 1]);
    this.z?.add(this.z.data[k]);
  }

  heights() {
    return this.z === null ? new Float64Array(this.count).fill(NaN) : this.z.take();
  }
}

function list(value, path) {
  if (!Array.isArray(value)) {
    throw new TypeError(`geocdt: ${path} must be an array, got ${JSON.stringify(value)}`);
  }
  return value;
}

// Appends one polyline to lines ({ positions, offsets }).
function line(positions, path, closeRing, lines) {
  const to = lines.positions;
  list(positions, path);
  const start = to.xy.length;
  to.xy.reserve(2 * positions.length);
  for (let i = 0; i < positions.length; i++) to.add(positions[i], path, i);
  // GeoJSON rings repeat their first position at the end; close the ones that forgot.
  if (closeRing && opens(positions)) to.repeat(start / 2);
  lines.offsets.add(to.count);
}

function geometry(g, path, reader) {
  if (g === null) return;  // a Feature without geometry
  if (typeof g !== 'object') {
    throw new TypeError(`geocdt: ${path} must be a GeoJSON geometry, got ${JSON.stringify(g)}`);
  }
  const c = g.coordinates;
  const at = `${path}.coordinates`;
  const { points, rings, lines, pointFeatures } = reader;
  switch (g.type) {
    case 'Point':
      points.add(c, at, -1);
      pointFeatures?.push(reader.feature);
      break;
    case 'MultiPoint':
      list(c, at).forEach((p, i) => {
        points.add(p, at, i);
        pointFeatures?.push(reader.feature);
      });
      break;
    case 'LineString':
      line(c, at, false, lines);
      break;
    case 'MultiLineString':
      list(c, at).forEach((l, i) => line(l, `${at}[${i}]`, false, lines));
      break;
    case 'Polygon':
      reader.parts.push(rings.offsets.length - 1);
      list(c, at).forEach((r, i) => line(r, `${at}[${i}]`, true, rings));
      break;
    case 'MultiPolygon':
      list(c, at).forEach((poly, i) => {
        reader.parts.push(rings.offsets.length - 1);
        list(poly, `${at}[${i}]`).forEach((r, j) => line(r, `${at}[${i}][${j}]`, true, rings));
      });
      break;
    case 'GeometryCollection':
      list(g.geometries, `${path}.geometries`).forEach((child, i) =>
        geometry(child, `${path}.geometries[${i}]`, reader));
      break;
    default:
      throw new TypeError(
        `geocdt: ${path}.type ${JSON.stringify(g.type)} is not a GeoJSON geometry type`);
  }
}

// count: { lines, positions }, as counted by countGeometry().
const polylines = (count) => {
  const offsets = new Growable(Uint32Array, count.lines + 1);
  offsets.add(0);
  return { positions: new Positions(count.positions), offsets };
};

// Whether a ring's last position differs from its first, so that line() closes it (and the
// count below counts one more position).
function opens(ring) {
  const a = ring[0], b = ring[ring.length - 1];
  return ring.length >= 2 && Array.isArray(a) && Array.isArray(b)
    && (a[0] !== b[0] || a[1] !== b[1]);
}

function countLine(positions, closeRing, into) {
  if (!Array.isArray(positions)) return;
  into.lines += 1;
  into.positions += positions.length + (closeRing && opens(positions) ? 1 : 0);
}

// Counts the positions and polylines that geometry() will read, without checking anything
// (geometry() does), so that their arrays are made once at their size. Grown by doubling, they
// left behind typed arrays whose memory, outside V8's heap, had V8 collect the caller's whole
// heap, the GeoJSON included, during the read (bench/EXPERIMENTS.md, G1).
function countGeometry(g, counts) {
  if (g === null || typeof g !== 'object') return;
  const c = g.coordinates;
  const each = (a, f) => {
    if (Array.isArray(a)) for (const x of a) f(x);
  };
  switch (g.type) {
    case 'Point':
      counts.points += 1;
      break;
    case 'MultiPoint':
      if (Array.isArray(c)) counts.points += c.length;
      break;
    case 'LineString':
      countLine(c, false, counts.lines);
      break;
    case 'MultiLineString':
      each(c, (l) => countLine(l, false, counts.lines));
      break;
    case 'Polygon':
      each(c, (r) => countLine(r, true, counts.rings));
      break;
    case 'MultiPolygon':
      each(c, (poly) => each(poly, (r) => countLine(r, true, counts.rings)));
      break;
    case 'GeometryCollection':
      each(g.geometries, (child) => countGeometry(child, counts));
      break;
    default:
  }
}

// Reads one feature's geometry (feature: null for a bare geometry); its rings make one
// polygon, the region of that feature.
function feature(g, path, f, reader) {
  reader.feature = f;
  const before = reader.rings.offsets.length;
  geometry(g, path, reader);
  if (reader.rings.offsets.length === before) return;
  reader.polygons.push(reader.rings.offsets.length - 1);
  reader.features.push(f);
}

// A FeatureCollection, Feature or geometry -> the input of triangulate(), flat (no array per
// ring), and the features of its regions:
// - Point and MultiPoint become points; LineString and MultiLineString, constraints; every
//   Polygon and MultiPolygon ring, a closed constraint that bounds the inside.
// - polylines ({ coords, offsets }) hold the rings first, feature by feature, then the lines.
// - polygons: one per feature with rings (all of its Polygons and MultiPolygons, in
//   GeometryCollections too), given as offsets into the polylines; regionFeatures[j] is the
//   feature of polygon j (null for a bare geometry); both are there when polygons are.
// - values: one per input point (its height) when some position has a third coordinate (NaN
//   where one has none).
// - pointFeatures, with { pointFeatures: true }: the feature of each point (null for a bare
//   geometry).
export function readGeoJSON(geojson, { pointFeatures = false } = {}) {
  if (geojson === null || typeof geojson !== 'object') {
    const got = geojson === null ? 'null' : typeof geojson;
    throw new TypeError(`geocdt: expected a GeoJSON object, got ${got}`);
  }
  const counts = {
    points: 0, rings: { lines: 0, positions: 0 }, lines: { lines: 0, positions: 0 },
  };
  if (geojson.type === 'FeatureCollection') {
    if (Array.isArray(geojson.features)) {
      for (const f of geojson.features) countGeometry(f?.geometry, counts);
    }
  } else {
    countGeometry(geojson.type === 'Feature' ? geojson.geometry : geojson, counts);
  }
  const reader = {
    points: new Positions(counts.points), rings: polylines(counts.rings),
    lines: polylines(counts.lines), polygons: [0], parts: [], features: [], feature: null,
    pointFeatures: pointFeatures ? [] : undefined,
  };
  if (geojson.type === 'FeatureCollection') {
    list(geojson.features, 'features').forEach((f, i) => {
      if (f === null || typeof f !== 'object' || f.type !== 'Feature') {
        throw new TypeError(`geocdt: features[${i}] is not a GeoJSON Feature`);
      }
      feature(f.geometry, `features[${i}].geometry`, f, reader);
    });
  } else if (geojson.type === 'Feature') {
    feature(geojson.geometry, 'geometry', geojson, reader);
  } else {
    feature(geojson, 'geometry', null, reader);
  }
  const { points, rings, lines } = reader;
  const ringCount = rings.offsets.length - 1, ringPoints = rings.positions.count;
  const offsets = new Uint32Array(ringCount + lines.offsets.length);
  offsets.set(rings.offsets.data.subarray(0, ringCount + 1));
  for (let i = 1; i < lines.offsets.length; i++) {
    offsets[ringCount + i] = ringPoints + lines.offsets.data[i];
  }
  // Country layers have rings only, road layers lines only: then one of them is the result.
  const concat = (a, b) => {
    if (b.length === 0) return a.take();
    if (a.length === 0) return b.take();
    const out = new Float64Array(a.length + b.length);
    out.set(a.data.subarray(0, a.length));
    out.set(b.data.subarray(0, b.length), a.length);
    return out;
  };
  const input = {
    points: points.xy.take(),
    polylines: { coords: concat(rings.positions.xy, lines.positions.xy), offsets },
  };
  if (reader.features.length > 0) {
    input.polygons = Uint32Array.from(reader.polygons);
    input.regionFeatures = reader.features;
    // Internal (geoJSONToInput() drops it): each Polygon, and each part of a MultiPolygon,
    // as ring offsets, for triangulateGeoJSON()'s perFeature.
    input.parts = Uint32Array.from([...reader.parts, ringCount]);
  }
  if (pointFeatures) input.pointFeatures = reader.pointFeatures;
  const all = [points, rings.positions, lines.positions];
  if (all.some((p) => p.z !== null)) {
    input.values = new Float64Array(all.reduce((n, p) => n + p.count, 0));
    let at = 0;
    for (const p of all) {
      input.values.set(p.heights(), at);
      at += p.count;
    }
  }
  return input;
}

// The same, with { flat: false } (the default) as one Float64Array per polyline.
export function geoJSONToInput(geojson, { flat = false } = {}) {
  const input = readGeoJSON(geojson);
  delete input.parts;
  if (flat) return input;
  const { coords, offsets } = input.polylines;
  const polylines = new Array(offsets.length - 1);
  for (let i = 0; i < polylines.length; i++) {
    polylines[i] = coords.slice(2 * offsets[i], 2 * offsets[i + 1]);
  }
  return { ...input, polylines };
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

// The height GeoJSON positions take from a mesh with values: z(v), the first value of vertex
// v; undefined when the mesh has none.
export function vertexHeights({ points, values }) {
  if (values === undefined || points.length === 0) return undefined;
  const perPoint = values.length / (points.length / 2);
  return (v) => values[perPoint * v];
}

// What the GeoJSON output says of each triangle, shared by meshToGeoJSON() and the CLI:
// id(t) (undefined: none), properties(t), key(t) (equal keys, equal properties) and
// position(v), [x, y] or [x, y, z] (z: the vertex's first value, when it is not NaN).
// - With mesh.regionFeatures (triangulateGeoJSON()): the id and properties of the feature of
//   the triangle's region (the same properties object for all its triangles), none and null
//   outside every polygon; with inside flags, a copy of the properties with `inside` added.
// - Without: id is the triangle index; properties hold `inside` and `region` when the mesh
//   has them.
export function triangleFields(mesh) {
  const { points, inside, regions, regionFeatures } = mesh;
  const regionOf = (t) => (regions === undefined ? -1 : regions[t]);
  const key = (t) => 2 * (regionOf(t) + 1) + (inside?.[t] ?? 0);
  const z = vertexHeights(mesh);
  const position = z === undefined
    ? (v) => [points[2 * v], points[2 * v + 1]]
    : (v) => (Number.isNaN(z(v)) ? [points[2 * v], points[2 * v + 1]]
      : [points[2 * v], points[2 * v + 1], z(v)]);
  if (regionFeatures === undefined) {
    return {
      id: (t) => t,
      properties(t) {
        const p = {};
        if (inside) p.inside = inside[t] === 1;
        if (regions) p.region = regions[t];
        return p;
      },
      key,
      position,
    };
  }
  // Each region's id and properties, read once rather than once a triangle.
  const ids = regionFeatures.map((f) => f?.id ?? undefined);
  const shared = regionFeatures.map((f) => f?.properties ?? null);
  const own = (t) => {
    const r = regionOf(t);
    return r < 0 ? null : shared[r];
  };
  return {
    id(t) {
      const r = regionOf(t);
      return r < 0 ? undefined : ids[r];
    },
    properties: inside ? (t) => ({ ...own(t), inside: inside[t] === 1 }) : own,
    key,
    position,
  };
}

// A mesh from triangulate() or triangulateGeoJSON() -> a FeatureCollection with one
// counter-clockwise Polygon per triangle, its id and properties as triangleFields() says.
export function meshToGeoJSON(mesh) {
  const { triangles } = mesh;
  const n = triangles.length / 3;
  const { id, properties, position } = triangleFields(mesh);
  const features = new Array(n);
  // Each object is made whole by one literal (two shapes of feature: with an id and
  // without), not grown a property at a time.
  for (let t = 0; t < n; t++) {
    const a = position(triangles[3 * t]);
    const closing = a.length === 2 ? [a[0], a[1]] : [a[0], a[1], a[2]];
    const geometry = {
      type: 'Polygon',
      coordinates: [[a, position(triangles[3 * t + 1]), position(triangles[3 * t + 2]), closing]],
    };
    const i = id(t);
    features[t] = i === undefined
      ? { type: 'Feature', properties: properties(t), geometry }
      : { type: 'Feature', id: i, properties: properties(t), geometry };
  }
  return { type: 'FeatureCollection', features };
}

// options.perFeature of triangulateGeoJSON(): false (the default) triangulates everything
// together; true fills each Polygon of each feature alone (triangulatePolygons()), as
// renderers do, and takes fillRule and output only. Returns whether it is on, and the options
// without it.
export function perFeatureMode(options) {
  const { perFeature = false, ...rest } = options;
  if (typeof perFeature !== 'boolean') {
    throw new TypeError(
      `geocdt: options.perFeature must be true or false, got ${JSON.stringify(perFeature)}`);
  }
  if (perFeature) {
    for (const [key, value] of Object.entries(rest)) {
      if (value === undefined || key === 'fillRule' || (key === 'keep' && value === 'inside')) {
        continue;
      }
      throw new TypeError(`geocdt: options.${key} does not apply with perFeature: true (each `
        + 'polygon is filled alone, inside triangles only: it takes fillRule and output)');
    }
  }
  return { perFeature, rest };
}

// readGeoJSON()'s rings as triangulatePolygons()'s batch: one polygon per Polygon (and per
// part of a MultiPolygon) with its holes, as renderers fill them; a feature's are consecutive.
export function featurePolygons(input) {
  const polygonOffsets = input.parts ?? new Uint32Array([0]);
  const rings = polygonOffsets[polygonOffsets.length - 1];
  const ringOffsets = input.polylines.offsets.subarray(0, rings + 1);
  const ringPoints = ringOffsets[rings];
  return {
    coords: input.polylines.coords.subarray(0, 2 * ringPoints), ringOffsets, polygonOffsets,
  };
}

// triangulatePolygons()'s result for featurePolygons(input) -> what triangulateGeoJSON()
// returns with perFeature: the arrays (points: the rings' points, then the extra points;
// triangleOffsets and regions by feature; heights in values, NaN at the extra points), or
// their FeatureCollection.
export function featureFillResult(filled, batch, input, output) {
  const { coords, polygonOffsets: parts } = batch;
  const { triangles, extraPoints, stats } = filled;
  const points = new Float64Array(coords.length + extraPoints.length);
  points.set(coords);
  points.set(extraPoints, coords.length);
  // Feature f has the rings from input.polygons[f], so the parts from there: its triangles
  // run from the first of them.
  const features = input.regionFeatures ?? [];
  const triangleOffsets = new Uint32Array(features.length + 1);
  const regions = new Int32Array(triangles.length / 3);
  let part = 0;
  for (let f = 0; f < features.length; f++) {
    while (part + 1 < parts.length && parts[part] < input.polygons[f]) part += 1;
    triangleOffsets[f] = filled.triangleOffsets[part];
  }
  triangleOffsets[features.length] = triangles.length / 3;
  for (let f = 0; f < features.length; f++) {
    regions.fill(f, triangleOffsets[f], triangleOffsets[f + 1]);
  }
  const mesh = {
    points, triangles, regions, regionFeatures: features, triangleOffsets, stats,
  };
  if (input.values !== undefined) {
    const first = input.points.length / 2;
    mesh.values = new Float64Array(points.length / 2).fill(NaN);
    mesh.values.set(input.values.subarray(first, first + coords.length / 2));
  }
  return output === 'arrays' ? mesh : meshToGeoJSON(mesh);
}

// What triangulateGeoJSON() returns, from triangulate()'s mesh of readGeoJSON()'s input:
// with the features of the regions (none when the GeoJSON has no polygon); as GeoJSON, with
// `inside` only when options.insideFlags asked for it (keep: 'inside' alone adds nothing).
export function geoJSONResult(mesh, input, output, options) {
  mesh.regionFeatures = input.regionFeatures ?? [];
  if (output === 'arrays') return mesh;
  if (options.insideFlags !== true) delete mesh.inside;
  return meshToGeoJSON(mesh);
}
