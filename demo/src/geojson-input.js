// Reads a user's GeoJSON (lon/lat, RFC 7946) into flat lon/lat arrays:
// Point/MultiPoint -> points, LineString/MultiLineString -> open constraint lines,
// Polygon/MultiPolygon -> rings that decide inside/outside. Every failure is a
// InputError whose message can be shown to the user as it is.

export const MAX_INPUT_POINTS = 3_000_000;

export class InputError extends Error {
  constructor(message) {
    super(message);
    this.name = 'InputError';
  }
}

export function parseGeoJSONText(text) {
  let json;
  try {
    json = JSON.parse(text);
  } catch (e) {
    throw new InputError(`not valid JSON: ${e.message}`);
  }
  return readGeoJSON(json);
}

// Returns { points: number[], rings: Float64Array[], lines: Float64Array[], pointCount,
// hasZ } and the heights (third coordinates, NaN where a position has none) in the same
// layout: pointZ: number[], ringZ and lineZ: Float64Array[].
export function readGeoJSON(json) {
  const out = {
    points: [], rings: [], lines: [], pointCount: 0, hasZ: false, pointZ: [], ringZ: [],
    lineZ: [],
  };
  if (!json || typeof json !== 'object') throw new InputError('not a GeoJSON object');
  addObject(json, out, 'the file');
  if (out.pointCount === 0) throw new InputError('the GeoJSON has no coordinates to triangulate');
  return out;
}

function addObject(obj, out, where) {
  switch (obj.type) {
    case 'FeatureCollection':
      if (!Array.isArray(obj.features)) {
        throw new InputError(`${where}: "features" must be an array`);
      }
      obj.features.forEach((f, i) => addObject(f, out, `feature ${i}`));
      return;
    case 'Feature':
      if (obj.geometry === null) return; // allowed by RFC 7946: a feature without a location
      if (!obj.geometry || typeof obj.geometry !== 'object') {
        throw new InputError(`${where}: "geometry" must be an object or null`);
      }
      addObject(obj.geometry, out, where);
      return;
    case 'GeometryCollection':
      if (!Array.isArray(obj.geometries)) {
        throw new InputError(`${where}: "geometries" must be an array`);
      }
      obj.geometries.forEach((g) => addObject(g, out, where));
      return;
    default:
      addGeometry(obj, out, where);
  }
}

function addGeometry(g, out, where) {
  const c = g.coordinates;
  const need = (depth) => {
    if (!isNested(c, depth)) {
      throw new InputError(`${where}: ${g.type} "coordinates" are malformed`);
    }
  };
  switch (g.type) {
    case 'Point':
      need(0);
      out.points.push(...position(c, out, where));
      out.pointZ.push(height(c, out));
      return;
    case 'MultiPoint':
      need(1);
      for (const p of c) {
        out.points.push(...position(p, out, where));
        out.pointZ.push(height(p, out));
      }
      return;
    case 'LineString':
      need(1);
      addLine(c, out, where);
      return;
    case 'MultiLineString':
      need(2);
      for (const l of c) addLine(l, out, where);
      return;
    case 'Polygon':
      need(2);
      for (const r of c) addRing(r, out, where);
      return;
    case 'MultiPolygon':
      need(3);
      for (const p of c) for (const r of p) addRing(r, out, where);
      return;
    default:
      throw new InputError(`${where}: unknown GeoJSON type ${JSON.stringify(g.type)}`);
  }
}

// A position is an array of numbers; depth counts the array levels above it.
function isNested(c, depth) {
  if (!Array.isArray(c)) return false;
  if (depth === 0) return true;
  return c.every((x) => isNested(x, depth - 1));
}

function position(p, out, where) {
  const [lon, lat] = p;
  const numbers = typeof lon === 'number' && typeof lat === 'number';
  if (!numbers || !Number.isFinite(lon) || !Number.isFinite(lat)) {
    throw new InputError(`${where}: a position is not two finite numbers: ${JSON.stringify(p)}`);
  }
  if (Math.abs(lat) > 90 || Math.abs(lon) > 540) {
    throw new InputError(
      `${where}: [${lon}, ${lat}] is not lon/lat in degrees (is the file projected?)`);
  }
  if (++out.pointCount > MAX_INPUT_POINTS) {
    throw new InputError(
      `too big for the demo: more than ${MAX_INPUT_POINTS.toLocaleString('en')} points`);
  }
  return [lon, lat];
}

// The third coordinate, or NaN.
function height(p, out) {
  if (typeof p[2] !== 'number' || !Number.isFinite(p[2])) return NaN;
  out.hasZ = true;
  return p[2];
}

function flatten(positions, out, where) {
  const xy = new Float64Array(2 * positions.length);
  const z = new Float64Array(positions.length);
  positions.forEach((p, i) => {
    xy.set(position(p, out, where), 2 * i);
    z[i] = height(p, out);
  });
  return { xy, z };
}

// Lines are constraints only: a closed one is cut in two so it is not taken for a ring.
function addLine(positions, out, where) {
  if (positions.length < 2) {
    throw new InputError(`${where}: a LineString needs at least 2 positions`);
  }
  const { xy, z } = flatten(positions, out, where);
  const n = positions.length;
  if (n > 2 && xy[0] === xy[2 * n - 2] && xy[1] === xy[2 * n - 1]) {
    const mid = n >> 1;
    out.lines.push(xy.slice(0, 2 * mid + 2), xy.slice(2 * mid));
    out.lineZ.push(z.slice(0, mid + 1), z.slice(mid));
  } else {
    out.lines.push(xy);
    out.lineZ.push(z);
  }
}

function addRing(positions, out, where) {
  if (positions.length < 3) {
    throw new InputError(`${where}: a polygon ring needs at least 3 positions`);
  }
  let { xy, z } = flatten(positions, out, where);
  const n = positions.length;
  if (xy[0] !== xy[2 * n - 2] || xy[1] !== xy[2 * n - 1]) {
    // RFC 7946 wants rings closed; close an open one rather than reject the file.
    const closed = new Float64Array(2 * n + 2);
    closed.set(xy);
    closed[2 * n] = xy[0];
    closed[2 * n + 1] = xy[1];
    xy = closed;
    const closedZ = new Float64Array(n + 1);
    closedZ.set(z);
    closedZ[n] = z[0];
    z = closedZ;
  }
  out.rings.push(xy);
  out.ringZ.push(z);
}
