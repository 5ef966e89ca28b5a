// Draws a terrain mesh on a canvas: each triangle filled with its height's colour, lit by its
// slope from the north-west (a shaded relief of the mesh itself), then optionally its edges,
// and the breaklines on top. Vertices are in pixel positions of the DEM; `scale` canvas pixels
// per DEM pixel.

// Low ground green, then ochre and brown, high ground pale.
const kStops = [[0, [70, 120, 70]], [0.35, [160, 170, 90]], [0.65, [150, 110, 70]],
  [1, [235, 230, 220]]];

function tint(t) {
  for (let k = 1; k < kStops.length; k++) {
    const [t1, c1] = kStops[k];
    if (t <= t1 || k === kStops.length - 1) {
      const [t0, c0] = kStops[k - 1];
      const f = Math.min(1, Math.max(0, (t - t0) / (t1 - t0)));
      return c0.map((c, i) => c + f * (c1[i] - c));
    }
  }
  return kStops[0][1];
}

// The colour of each triangle: tint by mean height, times Lambert shading (z exaggerated).
function triangleColours(mesh, { low, high, metresPerPixel, exaggeration }) {
  const { points: p, triangles: t, values: z } = mesh;
  const colours = new Uint8Array(t.length);  // r, g, b per triangle
  const light = [-0.5, -0.5, 0.7071];  // from the north-west (rows grow southwards), 45 degrees
  const k = exaggeration / metresPerPixel;
  for (let i = 0; i < t.length; i += 3) {
    const a = t[i], b = t[i + 1], c = t[i + 2];
    const ux = p[2 * b] - p[2 * a], uy = p[2 * b + 1] - p[2 * a + 1], uz = (z[b] - z[a]) * k;
    const vx = p[2 * c] - p[2 * a], vy = p[2 * c + 1] - p[2 * a + 1], vz = (z[c] - z[a]) * k;
    let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    if (nz < 0) { nx = -nx; ny = -ny; nz = -nz; }
    const length = Math.hypot(nx, ny, nz) || 1;
    const lambert = Math.max(0, (nx * light[0] + ny * light[1] + nz * light[2]) / length);
    const shade = 0.35 + 0.75 * lambert;
    const colour = tint(((z[a] + z[b] + z[c]) / 3 - low) / (high - low));
    for (let j = 0; j < 3; j++) colours[i + j] = Math.min(255, colour[j] * shade);
  }
  return colours;
}

// Fills triangle (x0, y0), (x1, y1), (x2, y2) (canvas pixels) into image with one colour: the
// pixels whose centres it holds.
function fillTriangle(image, width, height, x, y, r, g, b) {
  const order = [0, 1, 2].sort((i, j) => y[i] - y[j]);
  const [ax, bx, cx] = order.map((i) => x[i]);
  const [ay, by, cy] = order.map((i) => y[i]);
  const rowStart = Math.max(0, Math.ceil(ay - 0.5)), rowEnd = Math.min(height - 1,
    Math.floor(cy - 0.5));
  for (let row = rowStart; row <= rowEnd; row++) {
    const yc = row + 0.5;
    const xa = ax + (cx - ax) * (cy > ay ? (yc - ay) / (cy - ay) : 0);
    const xb = yc < by
      ? ax + (bx - ax) * (by > ay ? (yc - ay) / (by - ay) : 0)
      : bx + (cx - bx) * (cy > by ? (yc - by) / (cy - by) : 0);
    const left = Math.max(0, Math.ceil(Math.min(xa, xb) - 0.5));
    const right = Math.min(width - 1, Math.floor(Math.max(xa, xb) - 0.5));
    let at = 4 * (row * width + left);
    for (let col = left; col <= right; col++, at += 4) {
      image[at] = r;
      image[at + 1] = g;
      image[at + 2] = b;
      image[at + 3] = 255;
    }
  }
}

export function drawTerrain(canvas, mesh, style) {
  const { scale, wireframe, breaklines } = style;
  const ctx = canvas.getContext('2d');
  const { width, height } = canvas;
  const image = ctx.createImageData(width, height);
  const colours = triangleColours(mesh, style);
  const { points: p, triangles: t } = mesh;
  const x = [0, 0, 0], y = [0, 0, 0];
  for (let i = 0; i < t.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      x[k] = (p[2 * t[i + k]] + 0.5) * scale;
      y[k] = (p[2 * t[i + k] + 1] + 0.5) * scale;
    }
    fillTriangle(image.data, width, height, x, y, colours[i], colours[i + 1], colours[i + 2]);
  }
  ctx.putImageData(image, 0, 0);
  if (wireframe) {
    ctx.beginPath();
    for (let i = 0; i < t.length; i += 3) {
      for (let k = 0; k < 3; k++) {
        const a = t[i + k], b = t[i + (k + 1) % 3];
        ctx.moveTo((p[2 * a] + 0.5) * scale, (p[2 * a + 1] + 0.5) * scale);
        ctx.lineTo((p[2 * b] + 0.5) * scale, (p[2 * b + 1] + 0.5) * scale);
      }
    }
    ctx.strokeStyle = 'rgba(20, 30, 40, 0.35)';
    ctx.lineWidth = 0.5;
    ctx.stroke();
  }
  ctx.strokeStyle = '#d7301f';
  ctx.lineWidth = 2;
  for (const line of breaklines) {
    ctx.beginPath();
    for (let k = 0; k < line.length; k += 2) {
      const px = (line[k] + 0.5) * scale, py = (line[k + 1] + 0.5) * scale;
      if (k === 0) ctx.moveTo(px, py);
      else ctx.lineTo(px, py);
    }
    ctx.stroke();
  }
}

// The smallest angle of the mesh's triangles, in degrees.
export function smallestAngle({ points: p, triangles: t }) {
  let worst = 180;
  for (let i = 0; i < t.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const a = t[i + k], b = t[i + (k + 1) % 3], c = t[i + (k + 2) % 3];
      const ux = p[2 * b] - p[2 * a], uy = p[2 * b + 1] - p[2 * a + 1];
      const vx = p[2 * c] - p[2 * a], vy = p[2 * c + 1] - p[2 * a + 1];
      worst = Math.min(worst,
        Math.atan2(Math.abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / Math.PI);
    }
  }
  return worst;
}
