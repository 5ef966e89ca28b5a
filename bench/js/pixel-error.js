// The largest error of a terrain mesh over every pixel of its raster, measured the same way for
// every library: each pixel is found in the triangles by its barycentric weights (exact for
// vertices on pixel positions) and compared with the plane through the triangle's corners.
// Also counts the pixels no triangle holds (a mesh must cover its raster).
//   maxPixelError({ xy, triangles, z }, { heights, width, height })
// xy: x, y per vertex in pixel positions; z: the height of each vertex (omitted: read from
// the raster at the vertex, which must then be a pixel).
export function maxPixelError({ xy, triangles, z }, { heights, width, height }) {
  const covered = new Uint8Array(width * height);
  const heightOf = (v) => (z ? z[v] : heights[xy[2 * v + 1] * width + xy[2 * v]]);
  let worst = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    const ax = xy[2 * a], ay = xy[2 * a + 1], bx = xy[2 * b], by = xy[2 * b + 1];
    const cx = xy[2 * c], cy = xy[2 * c + 1];
    const za = heightOf(a), zb = heightOf(b), zc = heightOf(c);
    const area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    // A sliver (three vertices on a breakline, a crossing ulps off it) gives its weights no
    // digits: its pixels lie on its long edge, which a proper triangle shares.
    const longest = Math.max((bx - ax) ** 2 + (by - ay) ** 2, (cx - ax) ** 2 + (cy - ay) ** 2,
      (cx - bx) ** 2 + (cy - by) ** 2);
    if (!(Math.abs(area) > 1e-9 * longest)) continue;
    const sign = area > 0 ? 1 : -1;
    // Off pixel positions (breakline and Steiner vertices) the weights round: a pixel on an
    // edge within that rounding counts as in.
    const slack = 1e-9 * Math.abs(area);
    const x0 = Math.max(0, Math.ceil(Math.min(ax, bx, cx)));
    const x1 = Math.min(width - 1, Math.floor(Math.max(ax, bx, cx)));
    const y0 = Math.max(0, Math.ceil(Math.min(ay, by, cy)));
    const y1 = Math.min(height - 1, Math.floor(Math.max(ay, by, cy)));
    for (let y = y0; y <= y1; y++) {
      for (let x = x0; x <= x1; x++) {
        const wa = sign * ((bx - x) * (cy - y) - (by - y) * (cx - x));
        const wb = sign * ((cx - x) * (ay - y) - (cy - y) * (ax - x));
        const wc = sign * ((ax - x) * (by - y) - (ay - y) * (bx - x));
        if (wa < -slack || wb < -slack || wc < -slack) continue;
        const p = y * width + x;
        covered[p] = 1;
        const e = Math.abs((wa * za + wb * zb + wc * zc) / (sign * area) - heights[p]);
        if (e > worst) worst = e;
      }
    }
  }
  let uncovered = 0;
  for (let p = 0; p < covered.length; p++) uncovered += 1 - covered[p];
  return { maxError: worst, uncovered };
}
