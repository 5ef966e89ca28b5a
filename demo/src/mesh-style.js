// How the mesh is drawn, shared by the WebGL and the canvas layers.

// Both mesh layers draw in this pane, under Leaflet's overlay pane (the line being drawn).
export const MESH_PANE = 'geocdt-mesh';

export function meshPane(map) {
  if (!map.getPane(MESH_PANE)) map.createPane(MESH_PANE).style.zIndex = 350;
  return MESH_PANE;
}

// Meshes up to this many triangles go to Leaflet's canvas renderer; larger ones to WebGL.
export const CANVAS_TRIANGLE_LIMIT = 40_000;

export const DEFAULT_STYLE = {
  show: 'all', // 'all' | 'inside' | 'outside' | 'surface' (with values)
  fill: true,
  edges: true,
  constraints: true,
  insideFill: [0.86, 0.8, 0.62, 0.85], // land
  outsideFill: [0.62, 0.78, 0.9, 0.55], // sea
  edgeColour: [0.2, 0.25, 0.3, 0.35],
  constraintColour: [0.84, 0.12, 0.1, 0.95],
};

// Edges come grouped [inside only | both sides | outside only] (see mesh-buffers.js):
// each view of the mesh is one [first, count] range of them.
export const GROUP_RANGES = {
  all: ([a, b, c]) => [0, a + b + c],
  surface: ([a, b, c]) => [0, a + b + c],
  inside: ([a, b]) => [0, a + b],
  outside: ([a, b, c]) => [a, b + c],
};

export function cssColour([r, g, b, a]) {
  return `rgba(${Math.round(r * 255)}, ${Math.round(g * 255)}, ${Math.round(b * 255)}, ${a})`;
}

// The surface view's colours: bins of the vertex values, low (blue) to high (red).
export const SURFACE_BINS = 16;

export function surfaceColour(bin) {
  const u = bin / (SURFACE_BINS - 1);
  return [Math.min(1, 2 * u), 0.35 + 0.5 * Math.sin(Math.PI * u), Math.min(1, 2 - 2 * u), 0.9];
}

// What to fill: [the mesh's triangle array, colour, first triangle, count] ranges.
export function fillRanges(m, s) {
  if (!s.fill) return [];
  if (s.show === 'surface' && m.surfaceCounts) {
    let first = 0;
    return Array.from(m.surfaceCounts, (count, bin) => {
      const range = ['surfaceTriangles', surfaceColour(bin), first, count];
      first += count;
      return range;
    });
  }
  const ranges = [];
  if (s.show !== 'outside') ranges.push(['triangles', s.insideFill, 0, m.insideTriangles]);
  if (s.show !== 'inside') {
    ranges.push(['triangles', s.outsideFill, m.insideTriangles,
      m.triangles.length / 3 - m.insideTriangles]);
  }
  return ranges;
}
