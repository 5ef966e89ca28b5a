// Checks the caller's input before it reaches the wasm heap, so that every mistake becomes a
// TypeError or RangeError that names the offending array and index.

export const MAX_COORDINATE = 1e150;

function describe(value) {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an Array';
  if (ArrayBuffer.isView(value)) return `a ${value.constructor.name}`;
  return typeof value === 'object' ? `a ${value.constructor?.name ?? 'object'}` : typeof value;
}

function badValue(v) {
  if (Number.isNaN(v)) return 'NaN';
  if (v === Infinity || v === -Infinity) return String(v);
  return null;
}

function rangeErrorAt(name, i, v, owner) {
  const axis = i % 2 === 0 ? 'x' : 'y';
  const problem = badValue(v) ?? `${v}, beyond the supported |coordinate| <= 1e150`;
  return new RangeError(`geocdt: ${name}[${i}] (${axis} of point ${i >> 1}${owner}) is ${problem}`);
}

// Accepts a Float64Array, a Float32Array or an array of numbers holding x0, y0, x1, y1, ...
// Returns it unchanged (no copy); throws if it is unusable.
export function checkCoordinates(value, name, owner = '') {
  const typed = value instanceof Float64Array || value instanceof Float32Array;
  if (!typed && !Array.isArray(value)) {
    throw new TypeError(
      `geocdt: ${name} must be a Float64Array or an array of numbers (x0, y0, x1, y1, ...), `
      + `got ${describe(value)}`);
  }
  const n = value.length;
  if (n % 2 !== 0) {
    throw new RangeError(
      `geocdt: ${name} has an odd length (${n}): coordinates come in x, y pairs`);
  }
  if (typed) {
    for (let i = 0; i < n; i++) {
      const v = value[i];
      // Written so that NaN fails the test too.
      if (!(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) throw rangeErrorAt(name, i, v, owner);
    }
  } else {
    for (let i = 0; i < n; i++) {
      const v = value[i];
      if (typeof v !== 'number') {
        throw new TypeError(`geocdt: ${name}[${i}] must be a number, got ${describe(v)}`);
      }
      if (!(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) throw rangeErrorAt(name, i, v, owner);
    }
  }
  return value;
}

// { points, polylines } -> checked arrays. Both are optional.
export function checkInput(input) {
  if (input === null || typeof input !== 'object' || Array.isArray(input)
    || ArrayBuffer.isView(input)) {
    throw new TypeError(
      `geocdt: triangulate() takes an object { points, polylines }, got ${describe(input)}`);
  }
  const points = input.points == null ? new Float64Array(0)
    : checkCoordinates(input.points, 'points');
  let polylines = [];
  if (input.polylines != null) {
    if (!Array.isArray(input.polylines)) {
      throw new TypeError(
        'geocdt: polylines must be an array of Float64Array or number[], '
        + `got ${describe(input.polylines)}`);
    }
    polylines = input.polylines.map((line, i) =>
      checkCoordinates(line, `polylines[${i}]`, ` of polyline ${i}`));
  }
  return { points, polylines };
}

const KEEP = { all: 0, inside: 1 };
const FILL = { evenodd: 0, nonzero: 1 };

// Options -> the numbers the binding takes.
export function checkOptions(options) {
  if (options == null) return { keep: 0, fill: 0, insideFlags: false };
  if (typeof options !== 'object') {
    throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
  }
  const { keep = 'all', fillRule = 'evenodd', insideFlags = false } = options;
  if (typeof keep !== 'string' || !Object.hasOwn(KEEP, keep)) {
    throw new TypeError(
      `geocdt: options.keep must be 'all' or 'inside', got ${JSON.stringify(keep)}`);
  }
  if (typeof fillRule !== 'string' || !Object.hasOwn(FILL, fillRule)) {
    throw new TypeError(
      `geocdt: options.fillRule must be 'evenodd' or 'nonzero', got ${JSON.stringify(fillRule)}`);
  }
  if (typeof insideFlags !== 'boolean') {
    throw new TypeError(
      `geocdt: options.insideFlags must be a boolean, got ${describe(insideFlags)}`);
  }
  return { keep: KEEP[keep], fill: FILL[fillRule], insideFlags: insideFlags || keep === 'inside' };
}
