// The options of voronoi(), checked, with the clip made explicit: what the domain is, and how
// many of Lloyd's relaxation steps to take.
import { describe, MAX_COORDINATE } from './input.js';

// lloyd: true takes this many steps.
export const kLloydIterations = 10;
const kMaxLloydIterations = 100000;

// The bounding box of x, y pairs (NaN when one is NaN: the core then names the bad site).
function bounds(points) {
  let xmin = Infinity, ymin = Infinity, xmax = -Infinity, ymax = -Infinity;
  for (let i = 0; i < points.length; i += 2) {
    const x = points[i], y = points[i + 1];
    if (!(x >= xmin)) xmin = Number.isNaN(x) ? NaN : x;
    if (!(x <= xmax)) xmax = Number.isNaN(x) ? NaN : x;
    if (!(y >= ymin)) ymin = Number.isNaN(y) ? NaN : y;
    if (!(y <= ymax)) ymax = Number.isNaN(y) ? NaN : y;
    if (Number.isNaN(x) || Number.isNaN(y)) return [NaN, NaN, NaN, NaN];
  }
  return [xmin, ymin, xmax, ymax];
}

function checkBox(clip) {
  if (clip.length !== 4) {
    throw new RangeError('geocdt: options.clip must be [xmin, ymin, xmax, ymax], got '
      + `${clip.length} numbers`);
  }
  const box = Array.from(clip);
  box.forEach((v, i) => {
    if (typeof v !== 'number') {
      throw new TypeError(`geocdt: options.clip[${i}] must be a number, got ${describe(v)}`);
    }
    if (!(v >= -MAX_COORDINATE && v <= MAX_COORDINATE)) {
      throw new RangeError(`geocdt: options.clip[${i}] is ${v}: the box's coordinates must be `
        + 'finite with |value| <= 1e150');
    }
  });
  if (!(box[0] < box[2]) || !(box[1] < box[3])) {
    throw new RangeError('geocdt: options.clip [xmin, ymin, xmax, ymax] must have xmin < xmax '
      + `and ymin < ymax, got [${box.join(', ')}]`);
  }
  return box;
}

function checkLloyd(lloyd) {
  if (lloyd === undefined || lloyd === false) return { iterations: 0, tolerance: 0 };
  if (lloyd === true) return { iterations: kLloydIterations, tolerance: 0 };
  if (lloyd === null || typeof lloyd !== 'object') {
    throw new TypeError('geocdt: options.lloyd must be a boolean or { iterations, tolerance }, '
      + `got ${describe(lloyd)}`);
  }
  const { iterations = kLloydIterations, tolerance = 0 } = lloyd;
  if (typeof iterations !== 'number' || typeof tolerance !== 'number') {
    throw new TypeError('geocdt: options.lloyd.iterations and options.lloyd.tolerance must be '
      + `numbers, got ${describe(iterations)} and ${describe(tolerance)}`);
  }
  if (!Number.isInteger(iterations) || iterations < 1 || iterations > kMaxLloydIterations) {
    throw new RangeError('geocdt: options.lloyd.iterations must be an integer from 1 to '
      + `${kMaxLloydIterations}, got ${iterations}`);
  }
  if (!(tolerance >= 0 && tolerance < Infinity)) {
    throw new RangeError(
      `geocdt: options.lloyd.tolerance must be a finite number >= 0, got ${tolerance}`);
  }
  return { iterations, tolerance };
}

// options: voronoi()'s; points: the sites (checked coordinates); ringCount: the polylines given.
// -> { clip: 'rings' | 'hull' | 'box', box, fillRule, lloydIterations, lloydTolerance }. Without
// a clip, the rings when there are any, else the sites' bounding box (when it has no area, the
// sites are collinear and so is their hull: every cell is empty).
export function checkVoronoiOptions(options, points, ringCount) {
  if (options != null && typeof options !== 'object') {
    throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
  }
  const { clip, fillRule = 'evenodd', lloyd } = options ?? {};
  if (fillRule !== 'evenodd' && fillRule !== 'nonzero') {
    throw new TypeError(
      `geocdt: options.fillRule must be 'evenodd' or 'nonzero', got ${JSON.stringify(fillRule)}`);
  }
  let kind;
  let box = [0, 0, 0, 0];
  if (clip === undefined) {
    if (ringCount > 0) {
      kind = 'rings';
    } else {
      box = bounds(points);
      kind = box[0] < box[2] && box[1] < box[3] ? 'box' : 'hull';
    }
  } else if (clip === 'rings') {
    if (ringCount === 0) {
      throw new RangeError("geocdt: options.clip is 'rings' but input.polylines holds no ring");
    }
    kind = 'rings';
  } else if (clip === 'hull') {
    kind = 'hull';
  } else if (Array.isArray(clip) || ArrayBuffer.isView(clip)) {
    box = checkBox(clip);
    kind = 'box';
  } else {
    throw new TypeError("geocdt: options.clip must be 'rings', 'hull' or [xmin, ymin, xmax, "
      + `ymax], got ${describe(clip)}`);
  }
  const { iterations, tolerance } = checkLloyd(lloyd);
  return { clip: kind, box, fillRule, lloydIterations: iterations, lloydTolerance: tolerance };
}
