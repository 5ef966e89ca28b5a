// Exact decisions about distances and positions along a segment: every double is an integer
// times a power of two, so a few of them are integers (BigInt) over their lowest common unit,
// and sums and products of those are exact. Used where the checker must hold a result to
// the documented bound itself, not to a tolerance around it.

const view = new DataView(new ArrayBuffer(8));

// [mantissa, exponent] with v = mantissa * 2^exponent exactly (mantissa a signed BigInt).
function decompose(v) {
  view.setFloat64(0, v);
  const hi = view.getUint32(0), lo = view.getUint32(4);
  const biased = (hi >>> 20) & 0x7ff;
  let mantissa = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  let exponent = -1074;
  if (biased !== 0) {
    mantissa |= 1n << 52n;
    exponent = biased - 1075;
  }
  return [hi >>> 31 ? -mantissa : mantissa, exponent];
}

// The values as BigInts over their lowest common unit.
export function integers(values) {
  const parts = values.map(decompose);
  const base = Math.min(...parts.map(([m, e]) => (m === 0n ? Infinity : e)));
  return parts.map(([m, e]) => (m === 0n ? 0n : m << BigInt(e - base)));
}

// The spacing of doubles at |v|: from |v| to the next double up.
export function spacing(v) {
  const m = Math.abs(v);
  view.setFloat64(0, m);
  view.setBigUint64(0, view.getBigUint64(0) + 1n);
  return view.getFloat64(0) - m;
}

// The documented bound of the chain of segment [ax, ay, bx, by]: two spacings of doubles at
// its largest |coordinate|.
export function chainBound([ax, ay, bx, by]) {
  return 2 * spacing(Math.max(Math.abs(ax), Math.abs(ay), Math.abs(bx), Math.abs(by)));
}

// Whether (x, y) lies within distance d (a power of two) of the closed segment.
export function withinDistance([ax, ay, bx, by], x, y, d) {
  if ((x === ax && y === ay) || (x === bx && y === by)) return true;
  // Decided in floating point when clearly on one side of d: the distance errs by a few
  // ulps of the coordinates, unless squares underflow (then exactly).
  const dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  if (len2 > 1e-280) {
    const t = Math.min(1, Math.max(0, ((x - ax) * dx + (y - ay) * dy) / len2));
    const approx = Math.hypot(ax + t * dx - x, ay + t * dy - y);
    const error = 16 * Number.EPSILON *
      (Math.abs(ax) + Math.abs(ay) + Math.abs(bx) + Math.abs(by) + Math.abs(x) + Math.abs(y));
    if (Math.abs(approx - d) > error) return approx <= d;
  }
  const [Ax, Ay, Bx, By, X, Y, D] = integers([ax, ay, bx, by, x, y, d]);
  const ex = Bx - Ax, ey = By - Ay, wx = X - Ax, wy = Y - Ay;
  const dot = wx * ex + wy * ey, length2 = ex * ex + ey * ey;
  if (dot <= 0n) return wx * wx + wy * wy <= D * D;
  if (dot >= length2) return (X - Bx) ** 2n + (Y - By) ** 2n <= D * D;
  const cross = ex * wy - ey * wx;
  return cross * cross <= D * D * length2;
}

// The sign of (q - p) . (b - a): whether q lies further along the segment than p.
export function signAlong([ax, ay, bx, by], px, py, qx, qy) {
  const [Ax, Ay, Bx, By, Px, Py, Qx, Qy] = integers([ax, ay, bx, by, px, py, qx, qy]);
  const dot = (Qx - Px) * (Bx - Ax) + (Qy - Py) * (By - Ay);
  return dot > 0n ? 1 : dot < 0n ? -1 : 0;
}

// The next double after v towards +Infinity (direction 1) or -Infinity (-1); v finite.
function nextDouble(v, direction) {
  if (v === 0) return direction * Number.MIN_VALUE;
  view.setFloat64(0, v);
  const away = (v > 0) === (direction > 0);
  view.setBigUint64(0, view.getBigUint64(0) + (away ? 1n : -1n));
  return view.getFloat64(0);
}

// Whether (x, y) is where the lines of s and t cross, each coordinate rounded to the nearest
// double (halfway cases upward): the crossing X lies in [(x + below) / 2, (x + above) / 2).
export function isRoundedCrossing([ax, ay, bx, by], [cx, cy, dx, dy], x, y) {
  const neighbours = [nextDouble(x, -1), nextDouble(x, 1), nextDouble(y, -1), nextDouble(y, 1)];
  const [Ax, Ay, Bx, By, Cx, Cy, Dx, Dy, X, Y, X0, X1, Y0, Y1] =
    integers([ax, ay, bx, by, cx, cy, dx, dy, x, y, ...neighbours]);
  const ex = Bx - Ax, ey = By - Ay, fx = Dx - Cx, fy = Dy - Cy;
  let den = ex * fy - ey * fx;
  if (den === 0n) return false;
  let num = (Cx - Ax) * fy - (Cy - Ay) * fx;
  if (den < 0n) {
    den = -den;
    num = -num;
  }
  // 2 * crossing * den on each axis, against (c + neighbour) * den.
  const twice = [2n * (Ax * den + ex * num), 2n * (Ay * den + ey * num)];
  return (X + X0) * den <= twice[0] && twice[0] < (X + X1) * den &&
    (Y + Y0) * den <= twice[1] && twice[1] < (Y + Y1) * den;
}
