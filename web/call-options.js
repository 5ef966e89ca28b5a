// The calls' options, checked and turned into what the binding takes. The names that keep,
// fillRule and method accept come from the module's enums (passed in): no table is kept here.
import { describe } from './input.js';

// The options each call takes, by the name its errors give it. A name not listed is refused,
// not ignored: a misspelt option would otherwise leave its default in place without a word.
// tests/js/tables.test.js checks these lists against the declarations in web/*.d.ts.
const MESH = ['keep', 'fillRule', 'insideFlags', 'segmentSources'];
const TRIANGULATE = [...MESH, 'valuesPerPoint', 'refine', 'onProgress'];
const VORONOI = ['clip', 'fillRule', 'lloyd'];
export const OPTION_NAMES = {
  'init()': ['threads', 'warmUp', 'wasmUrl', 'wasmBinary'],
  'createWorker()': ['threads'],
  'triangulate()': TRIANGULATE,
  'triangulateGeoJSON()': [...TRIANGULATE, 'output', 'perFeature'],
  'triangulatePolygons()': ['fillRule'],
  'triangulateRaster()': ['maxError', 'maxTriangles', 'maxVertices', 'decimate', 'noData',
    'breaklines', 'breaklineHeights', 'minAngle', 'bbox'],
  'voronoi()': VORONOI,
  'voronoiGeoJSON()': [...VORONOI, 'output'],
  'new Triangulation()': ['valuesPerPoint'],
  'insertPoints()': ['onProgress'],
  'insertPolyline()': ['onProgress'],
  'interpolate()': ['method'],
  'rasterize()': ['bbox', 'width', 'height', 'method'],
  'refine()': ['minAngle', 'maxArea', 'maxSteinerPoints', 'keep', 'fillRule'],
  'results()': [...MESH, 'polygons', 'onProgress'],
  'options.refine': ['minAngle', 'maxArea', 'maxSteinerPoints'],
  'options.lloyd': ['iterations', 'tolerance'],
};

// How many single-character edits turn a into b, when at most 2 (else 3).
function editsApart(a, b) {
  if (Math.abs(a.length - b.length) > 2) return 3;
  let row = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const next = [i];
    for (let j = 1; j <= b.length; j++) {
      next[j] = Math.min(row[j] + 1, next[j - 1] + 1, row[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1));
    }
    row = next;
  }
  return Math.min(row[b.length], 3);
}

// Throws a TypeError for the first own key of options that `what` (a key of OPTION_NAMES)
// does not take; also: names the caller's side takes besides (the worker's transfer).
export function checkOptionNames(options, what, also = []) {
  if (options === null || typeof options !== 'object') return;
  const names = [...OPTION_NAMES[what], ...also];
  for (const key of Object.keys(options)) {
    if (names.includes(key)) continue;
    const near = names.find((n) => n.toLowerCase() === key.toLowerCase())
      ?? names.find((n) => editsApart(key, n) <= 2);
    const hint = near === undefined ? '' : ` (did you mean '${near}'?)`;
    throw new TypeError(`geocdt: ${what} has no option '${key}'${hint}; it takes `
      + `${names.join(', ')}`);
  }
}

// An embind enum's names, indexed by value.
export function enumNames(embindEnum) {
  const names = [];
  for (const [name, value] of Object.entries(embindEnum)) {
    if (name !== 'values') names[value.value] = name;
  }
  return names;
}

// options[what], one of embindEnum's names -> its enum value.
function choice(what, value, embindEnum) {
  if (typeof value === 'string' && value !== 'values' && Object.hasOwn(embindEnum, value)) {
    return embindEnum[value];
  }
  const names = enumNames(embindEnum).map((n) => `'${n}'`).join(' or ');
  throw new TypeError(`geocdt: options.${what} must be ${names}, got ${JSON.stringify(value)}`);
}

function checkObject(options) {
  if (typeof options !== 'object') {
    throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
  }
}

// keep, fillRule, insideFlags and segmentSources; enums: the module's Keep and FillRule.
export function meshOptions(options, { keep: keepEnum, fill: fillEnum }) {
  if (options == null) {
    return {
      keep: keepEnum.all, fill: fillEnum.evenodd, insideFlags: false, segmentSources: false,
    };
  }
  checkObject(options);
  const { keep = 'all', fillRule = 'evenodd', insideFlags = false, segmentSources = false }
    = options;
  const k = choice('keep', keep, keepEnum);
  const f = choice('fillRule', fillRule, fillEnum);
  const flag = (what, value) => {
    if (typeof value !== 'boolean') {
      throw new TypeError(`geocdt: options.${what} must be a boolean, got ${describe(value)}`);
    }
  };
  flag('insideFlags', insideFlags);
  flag('segmentSources', segmentSources);
  return { keep: k, fill: f, insideFlags: insideFlags || k === keepEnum.inside, segmentSources };
}

// options.fillRule alone (triangulatePolygons()'s only option) -> the module's enum value.
export function fillRuleOption(options, fillEnum) {
  if (options == null) return fillEnum.evenodd;
  checkObject(options);
  const { fillRule = 'evenodd' } = options;
  return choice('fillRule', fillRule, fillEnum);
}

// options.method, 'linear' or 'natural' -> the module's enum value.
export function methodOption(options, interpolationEnum) {
  if (options != null) checkObject(options);
  return choice('method', options?.method ?? 'linear', interpolationEnum);
}

// options.refine -> { refine, minAngle, maxArea, maxSteinerPoints } for the binding (0 for
// no area bound and the default cap). true asks for the defaults.
export function refineOptions(refine, name = 'options.refine') {
  if (refine == null || refine === false) {
    return { refine: false, minAngle: 20, maxArea: 0, maxSteinerPoints: 0 };
  }
  if (refine === true) refine = {};
  if (typeof refine !== 'object') {
    throw new TypeError(`geocdt: ${name} must be an object or true, got ${describe(refine)}`);
  }
  const { minAngle = 20, maxArea, maxSteinerPoints } = refine;
  const number = (what, value) => {
    if (typeof value !== 'number') {
      throw new TypeError(`geocdt: ${name}.${what} must be a number, got ${describe(value)}`);
    }
  };
  number('minAngle', minAngle);
  if (!(minAngle >= 0 && minAngle < 60)) {
    throw new RangeError(
      `geocdt: ${name}.minAngle must be a number of degrees from 0 to less than 60, `
      + `got ${minAngle}`);
  }
  if (maxArea !== undefined) {
    number('maxArea', maxArea);
    if (!(maxArea > 0)) {
      throw new RangeError(`geocdt: ${name}.maxArea must be a positive number, got ${maxArea}`);
    }
  }
  if (maxSteinerPoints !== undefined) {
    number('maxSteinerPoints', maxSteinerPoints);
    if (!Number.isInteger(maxSteinerPoints) || maxSteinerPoints < 1) {
      throw new RangeError(`geocdt: ${name}.maxSteinerPoints must be a positive integer, `
        + `got ${maxSteinerPoints}`);
    }
  }
  return {
    refine: true,
    minAngle,
    maxArea: maxArea === undefined || maxArea === Infinity ? 0 : maxArea,
    maxSteinerPoints: maxSteinerPoints ?? 0,
  };
}

// The binding's onProgress: (phase index, fraction) -> the caller's onProgress({ phase,
// fraction }), phases naming the indices. An exception from the caller's function stops
// further reports and is thrown once the core has returned (the core itself never sees it).
export function progressReporter(onProgress, phases) {
  if (onProgress == null) return { callback: undefined, rethrow() {} };
  if (typeof onProgress !== 'function') {
    throw new TypeError(
      `geocdt: options.onProgress must be a function, got ${describe(onProgress)}`);
  }
  let failure = null;
  return {
    callback(phase, fraction) {
      if (failure !== null) return;
      try {
        onProgress({ phase: phases[phase], fraction });
      } catch (error) {
        failure = { error };
      }
    },
    rethrow() {
      if (failure !== null) throw failure.error;
    },
  };
}
