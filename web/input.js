// The shape of the caller's input, checked in O(1) per array before anything is copied: the
// values themselves are checked by the core while it reads them, and a bad one comes back as
// a RangeError built here that names the array, the index, the axis and the value.

export const MAX_COORDINATE = 1e150;

export function describe(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an Array';
  if (typeof value !== 'object') return typeof value;
  const name = value.constructor?.name || 'object';
  return `${/^(?!Uint)[AEIOUaeiou]/.test(name) ? 'an' : 'a'} ${name}`;  // a Uint32Array
}

// [[x, y], ...] (GeoJSON's positions) where flat x, y numbers belong: the likeliest mistake
// of a caller coming from GeoJSON, told as such rather than as an odd length or a bad number.
function isPositionArray(value) {
  return Array.isArray(value) && value.length > 0
    && (Array.isArray(value[0]) || ArrayBuffer.isView(value[0]));
}

const isBigIntArray = (value) =>
  value instanceof BigInt64Array || value instanceof BigUint64Array;

// A numeric typed array (Float64Array, Float32Array, Int32Array, Uint8Array, ...), which one
// TypedArray.set() copies into the heap.
export function isNumericTypedArray(value) {
  return ArrayBuffer.isView(value) && !(value instanceof DataView) && !isBigIntArray(value);
}

// A typed array whose buffer was transferred (to a worker, by postMessage or
// structuredClone) reads as empty; said as such, not as an empty input or an engine error
// from the copy. Only an empty view can be detached, and only a detached buffer refuses
// slice().
export function checkAttached(value, name) {
  if (!ArrayBuffer.isView(value) || value.byteLength !== 0) return;
  try {
    value.buffer.slice(0, 0);
  } catch {
    throw new TypeError(`geocdt: ${name} is ${describe(value)} whose ArrayBuffer was detached `
      + '(transferred to a worker or by structuredClone): it no longer holds any data');
  }
}

// x0, y0, x1, y1, ... in a plain array or any numeric typed array. Returns it unchanged.
export function checkCoordinates(value, name) {
  if (!Array.isArray(value) && !isNumericTypedArray(value)) {
    throw new TypeError(`geocdt: ${name} must be a Float64Array or an array of numbers `
      + `(x0, y0, x1, y1, ...), or another numeric typed array; got ${describe(value)}`);
  }
  checkAttached(value, name);
  if (isPositionArray(value)) {
    throw new TypeError(`geocdt: ${name} holds ${describe(value[0])} at index 0: coordinates `
      + `are flat (x0, y0, x1, y1, ...), not [x, y] positions; pass ${name}.flat() or a `
      + 'Float64Array');
  }
  if (value.length % 2 !== 0) {
    throw new RangeError(
      `geocdt: ${name} has an odd length (${value.length}): coordinates come in x, y pairs`);
  }
  return value;
}

// Offsets: a Uint32Array, Int32Array, Uint16Array, Uint8Array or array of integers, with
// n + 1 entries for n `things`, each an offset into their `parts` (vertex, polyline).
export function checkOffsets(offsets, name, things, parts) {
  const integers = offsets instanceof Uint32Array || offsets instanceof Int32Array
    || offsets instanceof Uint16Array || offsets instanceof Uint8Array;
  if (!integers && !Array.isArray(offsets)) {
    throw new TypeError(`geocdt: ${name} must be a Uint32Array (or Int32Array, or an array of `
      + `integers) of n + 1 ${parts} offsets, got ${describe(offsets)}`);
  }
  checkAttached(offsets, name);
  if (offsets.length === 0) {
    throw new RangeError(`geocdt: ${name} is empty: n ${things} take n + 1 offsets`);
  }
  return offsets;
}

// A negative offset of an Int32Array, which would wrap past 2^31 on its way into the binding's
// unsigned ones (an array's are checked as they are copied).
function checkSignedOffsets(offsets, name) {
  if (!(offsets instanceof Int32Array)) return;
  const i = offsets.findIndex((v) => v < 0);
  if (i < 0) return;
  const why = i === 0 ? 'offsets cannot be negative'
    : `below ${name}[${i - 1}] = ${offsets[i - 1]}`;
  throw new RangeError(`geocdt: ${name}[${i}] is ${offsets[i]}: ${why}`);
}

// The flat polylines form: { coords, offsets } in GeoArrow's layout.
function checkFlatPolylines({ coords, offsets }, name) {
  checkCoordinates(coords, `${name}.coords`);
  checkOffsets(offsets, `${name}.offsets`, 'polylines', 'vertex');
  return { coords, offsets, count: offsets.length - 1, points: coords.length / 2 };
}

// Polylines as an array of arrays, or { coords, offsets }, named `name` in errors ->
// { arrays, count, points } or { coords, offsets, count, points }.
export function checkPolylines(polylines, name = 'polylines') {
  if (polylines == null) return { arrays: [], count: 0, points: 0 };
  if (typeof polylines === 'object' && !Array.isArray(polylines)
    && !ArrayBuffer.isView(polylines) && 'coords' in polylines) {
    return checkFlatPolylines(polylines, name);
  }
  if (!Array.isArray(polylines)) {
    throw new TypeError(`geocdt: ${name} must be an array of Float64Array or number[] (one `
      + `per polyline), or { coords, offsets }; got ${describe(polylines)}`);
  }
  if (typeof polylines[0] === 'number') {
    throw new TypeError(`geocdt: ${name} must be an array of polylines (Float64Array or `
      + `number[] each), got numbers: for one polyline, pass [line]`);
  }
  let total = 0;
  for (let i = 0; i < polylines.length; i++) {
    total += checkCoordinates(polylines[i], `${name}[${i}]`).length;
  }
  return { arrays: polylines, count: polylines.length, points: total / 2 };
}

// options.valuesPerPoint: a whole number from 1 (the default) up.
export function checkValuesPerPoint(options) {
  const k = options?.valuesPerPoint ?? 1;
  if (!Number.isInteger(k) || k < 1 || k > 65536) {
    throw new RangeError('geocdt: options.valuesPerPoint must be a whole number from 1 to 65536, '
      + `got ${typeof k === 'number' ? k : describe(k)}`);
  }
  return k;
}

// valuesPerPoint numbers per point, in any numeric array (NaN: none).
export function checkValues(values, points, valuesPerPoint, name = 'values') {
  if (!Array.isArray(values) && !isNumericTypedArray(values)) {
    throw new TypeError(`geocdt: ${name} must be a Float64Array or an array of numbers `
      + `(valuesPerPoint per point), or another numeric typed array; got ${describe(values)}`);
  }
  checkAttached(values, name);
  if (values.length !== points * valuesPerPoint) {
    const per = valuesPerPoint === 1 ? '' : ` (${valuesPerPoint} per point)`;
    throw new RangeError(`geocdt: ${name} has ${values.length} numbers for ${points} points`
      + `${per}${name === 'values' ? ': the points, then the polylines\' points' : ''}`);
  }
  return values;
}

// bbox's four numbers: finite, within MAX_COORDINATE, and minX < maxX, minY < maxY (or equal,
// where flatX / flatY: a raster of one column / one row).
function checkBbox(bbox, flatX, flatY) {
  for (let i = 0; i < 4; i++) {
    if (typeof bbox[i] !== 'number' || !Number.isFinite(bbox[i])) {
      throw new RangeError(`geocdt: options.bbox[${i}] must be a finite number, got ${bbox[i]}`);
    }
    if (Math.abs(bbox[i]) > MAX_COORDINATE) {
      throw new RangeError(`geocdt: options.bbox[${i}] is ${problem(bbox[i])}`);
    }
  }
  const x = flatX ? bbox[0] <= bbox[2] : bbox[0] < bbox[2];
  const y = flatY ? bbox[1] <= bbox[3] : bbox[1] < bbox[3];
  if (!x || !y) {
    throw new RangeError(`geocdt: options.bbox [${Array.from(bbox).join(', ')}] must have `
      + `minX ${flatX ? '<=' : '<'} maxX and minY ${flatY ? '<=' : '<'} maxY`);
  }
}

// Every pixel on a place of its own, as the core maps them (x = minX + (maxX - minX) i /
// (width - 1), the last column at maxX; rows from maxY down): a bbox within ulps of flat maps
// neighbours together.
function checkPixelPlaces({ minX, minY, maxX, maxY }, { width, height }) {
  const place = (i, last, from, to) => (i === last ? to : from + (to - from) * (i / last));
  for (let i = 1; i < width; i++) {
    if (!(place(i, width - 1, minX, maxX) > place(i - 1, width - 1, minX, maxX))) {
      throw new RangeError(`geocdt: options.bbox is too narrow for ${width} columns: columns `
        + `${i - 1} and ${i} land on the same x`);
    }
  }
  for (let j = 1; j < height; j++) {
    if (!(place(j, height - 1, maxY, minY) < place(j - 1, height - 1, maxY, minY))) {
      throw new RangeError(`geocdt: options.bbox is too low for ${height} rows: rows ${j - 1} `
        + `and ${j} land on the same y`);
    }
  }
}

// rasterize()'s options: { bbox: [minX, minY, maxX, maxY], width, height }, within what a
// Float32Array in the wasm heap can hold.
export function checkRaster(options, valuesPerPoint) {
  if (options === null || typeof options !== 'object') {
    throw new TypeError('geocdt: rasterize() takes { bbox: [minX, minY, maxX, maxY], width, '
      + `height, method }, got ${describe(options)}`);
  }
  const { bbox, width, height } = options;
  if ((!Array.isArray(bbox) && !isNumericTypedArray(bbox)) || bbox.length !== 4) {
    throw new TypeError(
      `geocdt: options.bbox must be [minX, minY, maxX, maxY], got ${describe(bbox)}`);
  }
  checkBbox(bbox, false, false);
  for (const [name, v] of [['width', width], ['height', height]]) {
    if (!Number.isInteger(v) || v < 1) {
      throw new RangeError(`geocdt: options.${name} must be a whole number from 1 up, got ${v}`);
    }
  }
  if (4 * width * height * valuesPerPoint >= 2 ** 31) {
    throw new RangeError(`geocdt: a ${width} x ${height} raster of ${valuesPerPoint} value(s) `
      + 'per pixel needs 2 GB or more: make it smaller');
  }
  return { bbox, width, height };
}

// { points, polylines, polygons, values } -> { points, lines, polygons, values } with lines
// either { arrays, count, points } (an array per polyline) or { coords, offsets, count,
// points }. All are optional; polygons and values stay undefined when not given.
// valuesPerPoint: checkValuesPerPoint()'s.
export function checkInput(input, valuesPerPoint = 1, call = 'triangulate') {
  if (input === null || typeof input !== 'object' || Array.isArray(input)
    || ArrayBuffer.isView(input)) {
    const hint = Array.isArray(input) || ArrayBuffer.isView(input)
      ? ` (for points alone: ${call}({ points }))` : '';
    throw new TypeError(`geocdt: ${call}() takes an object { points, polylines }, got `
      + `${describe(input)}${hint}`);
  }
  const points = input.points == null ? new Float64Array(0)
    : checkCoordinates(input.points, 'points');
  const lines = checkPolylines(input.polylines);
  const polygons = input.polygons == null ? undefined
    : checkOffsets(input.polygons, 'polygons', 'polygons', 'polyline');
  if (input.z != null) {
    throw new TypeError('geocdt: input.z is now input.values (valuesPerPoint numbers per point, '
      + '1 by default), and the result\'s z is its values');
  }
  const values = input.values == null ? undefined
    : checkValues(input.values, points.length / 2 + lines.points, valuesPerPoint);
  return { points, lines, polygons, values };
}

const badCoordinate = (v) => !(v >= -MAX_COORDINATE && v <= MAX_COORDINATE);

function problem(v) {
  if (typeof v === 'number' && (Number.isNaN(v) || !Number.isFinite(v))) return String(v);
  return `${v}, beyond the supported |coordinate| <= 1e150`;
}

// The RangeError for point `point` of `values` (x, y pairs) named `name`, whose coordinates
// start at index `start`; owner says whose point it is (' of polyline 2'). null when neither
// coordinate is bad (the caller then falls back to the core's message).
export function coordinateError(values, name, start, point, owner) {
  for (let axis = 0; axis < 2; axis++) {
    const i = start + 2 * point + axis;
    const v = values[i];
    if (badCoordinate(v)) {
      return new RangeError(`geocdt: ${name}[${i}] (${axis ? 'y' : 'x'} of point ${point}`
        + `${owner}) is ${problem(v)}`);
    }
  }
  return null;
}

// triangulatePolygons()'s input: GeoArrow's polygon layout. Returns it unchanged; the offsets'
// order and range and the coordinates' values are checked by the core as it reads them.
export function checkPolygons(polygons) {
  if (polygons === null || typeof polygons !== 'object' || Array.isArray(polygons)
    || ArrayBuffer.isView(polygons)) {
    throw new TypeError('geocdt: triangulatePolygons() takes { coords, ringOffsets, '
      + `polygonOffsets } (GeoArrow's polygon layout), got ${describe(polygons)}`);
  }
  const { coords, ringOffsets, polygonOffsets } = polygons;
  checkCoordinates(coords, 'coords');
  checkOffsets(ringOffsets, 'ringOffsets', 'rings', 'vertex');
  checkOffsets(polygonOffsets, 'polygonOffsets', 'polygons', 'ring');
  checkSignedOffsets(ringOffsets, 'ringOffsets');
  checkSignedOffsets(polygonOffsets, 'polygonOffsets');
  return { coords, ringOffsets, polygonOffsets };
}

// earcut()'s input, (data, holeIndices, dim) as earcut takes it -> a batch of one polygon.
export function checkEarcutInput(data, holeIndices, dim) {
  if (!Array.isArray(data) && !isNumericTypedArray(data)) {
    throw new TypeError('geocdt: earcut(data, holeIndices, dim) takes data as an array of '
      + `numbers or a numeric typed array, got ${describe(data)}`);
  }
  checkAttached(data, 'data');
  if (typeof dim !== 'number') {
    throw new TypeError(`geocdt: earcut() dim must be a number, got ${describe(dim)}`);
  }
  if (!Number.isInteger(dim) || dim < 2) {
    throw new RangeError(`geocdt: earcut() dim must be an integer from 2 up, got ${dim}`);
  }
  // GeoJSON positions ([[x, y], ...]) are the likely mistake: named before the length.
  if (Array.isArray(data) && data.length > 0 && typeof data[0] !== 'number') {
    throw new TypeError(`geocdt: earcut() data[0] must be a number, got ${describe(data[0])} `
      + '(data is flat: x0, y0, x1, y1, ...)');
  }
  if (data.length % dim !== 0) {
    throw new RangeError(`geocdt: earcut() data has ${data.length} numbers, not a multiple of `
      + `dim = ${dim}`);
  }
  const points = data.length / dim;
  const holes = holeIndices ?? [];
  if (!Array.isArray(holes) && !isNumericTypedArray(holes)) {
    throw new TypeError('geocdt: earcut() holeIndices must be an array of vertex indices, got '
      + `${describe(holeIndices)}`);
  }
  const ringOffsets = new Uint32Array(holes.length + 2);
  for (let i = 0; i < holes.length; i++) {
    const start = holes[i];
    const before = i === 0 ? 0 : holes[i - 1];
    if (typeof start !== 'number') {
      throw new TypeError(`geocdt: earcut() holeIndices[${i}] must be a number, got `
        + `${describe(start)}`);
    }
    if (!Number.isInteger(start) || start < before || start > points) {
      throw new RangeError(`geocdt: earcut() holeIndices[${i}] is ${start}: hole ${i} must `
        + `start at a vertex index from ${before} to ${points}`);
    }
    ringOffsets[i + 1] = start;
  }
  ringOffsets[holes.length + 1] = points;
  return {
    coords: data, ringOffsets, polygonOffsets: new Uint32Array([0, holes.length + 1]),
  };
}

// The RangeError for the first bad coordinate of ring `ring` (an index into ringOffsets) of
// coords (dim numbers a point), or null when it has none; where: { polygon, ring } (the
// ring's place in its polygon), or null for a ring in no polygon.
export function polygonCoordinateError(coords, dim, name, ringOffsets, ring, where) {
  const owner = where === null ? `, in ring ${ring}`
    : `, in polygon ${where.polygon} ring ${where.ring}`;
  for (let k = ringOffsets[ring]; k < ringOffsets[ring + 1]; k++) {
    for (let axis = 0; axis < 2; axis++) {
      const i = dim * k + axis;
      if (badCoordinate(coords[i])) {
        return new RangeError(`geocdt: ${name}[${i}] (${axis ? 'y' : 'x'} of point ${k}`
          + `${owner}) is ${problem(coords[i])}`);
      }
    }
  }
  return null;
}

// The RangeError for polygons[i], the first that breaks their layout; name: where they were
// given ('polygons', 'options.polygons').
export function polygonOffsetError(polygons, i, polylines, name) {
  const v = polygons[i];
  const why = i > 0 && v < polygons[i - 1] ? `below ${name}[${i - 1}] = ${polygons[i - 1]}`
    : `past the ${polylines} polylines`;
  return new RangeError(`geocdt: ${name}[${i}] is ${v}: ${why}`);
}

// The RangeError for offsets[i], the first that breaks the flat layout of polylines named
// `name`.
export function offsetError({ offsets, points }, i, name = 'polylines') {
  const v = offsets[i];
  let why;
  if (i === 0 && v !== 0) why = 'the first offset must be 0';
  else if (i > 0 && v < offsets[i - 1]) why = `below offsets[${i - 1}] = ${offsets[i - 1]}`;
  else if (v > points) why = `past the ${points} points of ${name}.coords`;
  else why = `the last offset must be the number of points in ${name}.coords (${points})`;
  return new RangeError(`geocdt: ${name}.offsets[${i}] is ${v}: ${why}`);
}

// The most threads init() and createWorker() take.
export const kMaxThreads = 64;

// The error for a threads option that is neither 'auto' nor an integer from 1 to kMaxThreads,
// or null when it is right (or absent).
export function threadsError(threads) {
  if (threads !== undefined && threads !== 'auto' && typeof threads !== 'number') {
    return new TypeError(
      `geocdt: options.threads must be a number or 'auto', got ${describe(threads)}`);
  }
  if (typeof threads === 'number' && !(Number.isInteger(threads) && threads >= 1
    && threads <= kMaxThreads)) {
    return new RangeError(
      `geocdt: options.threads must be an integer from 1 to ${kMaxThreads}, got ${threads}`);
  }
  return null;
}

// triangulateRaster()'s raster: { heights, width, height }, heights row by row in any numeric
// typed array or an array of numbers (NaN is checked by the core, which knows noData).
export function checkHeightmap(raster) {
  if (raster === null || typeof raster !== 'object' || Array.isArray(raster)
    || ArrayBuffer.isView(raster)) {
    throw new TypeError('geocdt: triangulateRaster() takes { heights, width, height }, got '
      + `${describe(raster)}`);
  }
  const { heights, width, height } = raster;
  if (!Array.isArray(heights) && !isNumericTypedArray(heights)) {
    throw new TypeError('geocdt: raster.heights must be a numeric typed array (Float32Array, '
      + `Int16Array, ...) or an array of numbers, row by row; got ${describe(heights)}`);
  }
  checkAttached(heights, 'raster.heights');
  for (const [name, v] of [['width', width], ['height', height]]) {
    if (!Number.isInteger(v) || v < 1) {
      throw new RangeError(`geocdt: raster.${name} must be a whole number from 1 up, got `
        + `${typeof v === 'number' ? v : describe(v)}`);
    }
  }
  if (heights.length !== width * height) {
    throw new RangeError(`geocdt: raster.heights has ${heights.length} numbers, but a ${width} `
      + `x ${height} raster has ${width * height}`);
  }
  if (width * height >= 2 ** 31) {
    throw new RangeError(`geocdt: a ${width} x ${height} raster has 2^31 pixels or more: cut `
      + 'it into tiles');
  }
  return { heights, width, height };
}

// triangulateRaster()'s options, checked: numbers for the binding (0 for no limit), and the
// breaklines as checkInput() gives polylines. raster: checkHeightmap()'s (its width and height).
export function checkRasterOptions(options, raster) {
  if (options != null && typeof options !== 'object') {
    throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
  }
  const {
    maxError = 0, maxTriangles, maxVertices, noData, minAngle = 0, decimate = false, bbox,
    breaklines, breaklineHeights,
  } = options ?? {};
  const number = (name, v) => {
    if (typeof v !== 'number') {
      throw new TypeError(`geocdt: options.${name} must be a number, got ${describe(v)}`);
    }
  };
  number('maxError', maxError);
  if (!(maxError >= 0) || maxError === Infinity) {
    throw new RangeError(`geocdt: options.maxError must be a finite number from 0 up, got ${
      maxError}`);
  }
  const count = (name, v) => {
    if (v === undefined) return 0;
    number(name, v);
    if (!Number.isInteger(v) || v < 1) {
      throw new RangeError(`geocdt: options.${name} must be a whole number from 1 up, got ${v}`);
    }
    return v;
  };
  if (noData !== undefined) number('noData', noData);
  number('minAngle', minAngle);
  if (!(minAngle >= 0 && minAngle < 60)) {
    throw new RangeError('geocdt: options.minAngle must be a number of degrees from 0 to less '
      + `than 60, got ${minAngle}`);
  }
  if (typeof decimate !== 'boolean') {
    throw new TypeError('geocdt: options.decimate must be true or false, got '
      + `${describe(decimate)}`);
  }
  const checked = {
    maxError,
    decimate,
    maxTriangles: count('maxTriangles', maxTriangles),
    maxVertices: count('maxVertices', maxVertices),
    hasNoData: noData !== undefined,
    noData: noData ?? 0,
    minAngle,
    hasBbox: bbox !== undefined,
    minX: 0, minY: 0, maxX: 0, maxY: 0,
  };
  if (bbox !== undefined) {
    if ((!Array.isArray(bbox) && !isNumericTypedArray(bbox)) || bbox.length !== 4) {
      throw new TypeError(
        `geocdt: options.bbox must be [minX, minY, maxX, maxY], got ${describe(bbox)}`);
    }
    checkBbox(bbox, raster.width === 1, raster.height === 1);
    [checked.minX, checked.minY, checked.maxX, checked.maxY] = bbox;
    checkPixelPlaces(checked, raster);
  }
  const lines = checkPolylines(breaklines, 'options.breaklines');
  if (Array.isArray(breaklineHeights) && breaklineHeights.some((h) => typeof h === 'object')) {
    throw new TypeError('geocdt: options.breaklineHeights must be flat: one number per '
      + 'breakline point, the breaklines one after the other');
  }
  const heights = breaklineHeights == null ? undefined
    : checkValues(breaklineHeights, lines.points, 1, 'options.breaklineHeights');
  if (heights !== undefined) {
    for (let i = 0; i < heights.length; i++) {
      if (heights[i] === Infinity || heights[i] === -Infinity) {
        throw new RangeError(`geocdt: options.breaklineHeights[${i}] is ${heights[i]}: a height `
          + 'must be finite (NaN takes the raster\'s)');
      }
    }
  }
  return { options: checked, lines, heights };
}
