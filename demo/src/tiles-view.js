// Draws a region's tiles: each polygon's triangles filled in its layer's colour with WebGL,
// translucent so that where triangles overlap (earcut's, on the polygons it gets wrong) the
// colour is deeper
// (a region has up to 1.3 million triangles: a 2D canvas took minutes to fill that many
// paths without a GPU), from geocdt's arrays or earcut's, optionally their edges, and on a 2D
// canvas above, outlines around chosen polygons. The buffers are built once per fill, in tile
// units; panning and zooming only draw again.

const PALETTE = [[143, 184, 222], [166, 212, 159], [232, 216, 168], [217, 179, 230],
  [242, 184, 128], [176, 196, 177], [201, 173, 167], [154, 209, 212], [229, 224, 89],
  [189, 178, 255], [255, 198, 255], [202, 255, 191]];
const TILE = [255, 255, 255];

const VERTEX = `#version 300 es
in vec2 position;
in vec3 colour;
uniform vec4 view;  // scale x, scale y, offset x, offset y: clip = position * scale + offset
out vec3 fill;
void main() {
  gl_Position = vec4(position * view.xy + view.zw, 0.0, 1.0);
  fill = colour;
}`;

const FRAGMENT = `#version 300 es
precision mediump float;
in vec3 fill;
uniform float alpha;
out vec4 colour;
void main() {
  colour = vec4(fill, alpha);
}`;

function compile(gl) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, VERTEX], [gl.FRAGMENT_SHADER, FRAGMENT]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new Error(`WebGL shader: ${gl.getShaderInfoLog(shader)}`);
    }
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error(`WebGL program: ${gl.getProgramInfoLog(program)}`);
  }
  return program;
}

export class TileView {
  constructor(canvas, overlay) {
    this.canvas = canvas;
    this.overlay = overlay;
    // Opaque: the fills' translucency is for overlaps within the canvas, not with the page.
    const gl = canvas.getContext('webgl2', { antialias: true, alpha: false });
    if (!gl) throw new Error('this page draws with WebGL 2, which this browser does not offer');
    this.gl = gl;
    this.program = compile(gl);
    this.buffers = { position: gl.createBuffer(), colour: gl.createBuffer(),
      edges: gl.createBuffer() };
    this.count = 0;
    this.edgeCount = 0;
    this.scale = 1;
    this.offset = [0, 0];
    this.outlines = null;
    this.showEdges = false;
    this.grid = { columns: 1, rows: 1, extent: 4096, place: [] };
  }

  setRegion(region, grid) {
    this.region = region;
    this.grid = { ...grid, extent: region.tiles[0]?.extent ?? 4096 };
    this.polygonTile = new Uint32Array(region.polygonOffsets.length - 1);
    for (let t = 0; t + 1 < region.tileOffsets.length; t++) {
      this.polygonTile.fill(t, region.tileOffsets[t], region.tileOffsets[t + 1]);
    }
    this.fit();
  }

  tileOrigin(t) {
    const [cx, cy] = this.grid.place[t];
    return [cx * this.grid.extent, cy * this.grid.extent];
  }

  // count: the triangles in all; triangles(p, emit) calls emit(ax, ay, bx, by, cx, cy), in
  // tile coordinates, for each triangle of polygon p. The tiles' squares go first.
  setFill(count, triangles) {
    const { polygonLayers } = this.region;
    const tiles = this.grid.place.length;
    const n = 3 * (count + 2 * tiles);
    const position = new Float32Array(2 * n), colour = new Uint8Array(3 * n);
    const edges = new Float32Array(12 * count);  // three lines a triangle
    let at = 0, e = 0;
    const vertex = (x, y, rgb) => {
      position[2 * at] = x;
      position[2 * at + 1] = y;
      colour.set(rgb, 3 * at);
      at++;
    };
    const { extent } = this.grid;
    for (let t = 0; t < tiles; t++) {
      const [x, y] = this.tileOrigin(t);
      for (const [u, v] of [[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]]) {
        vertex(x + u * extent, y + v * extent, TILE);
      }
    }
    for (let p = 0; p < polygonLayers.length; p++) {
      const [ox, oy] = this.tileOrigin(this.polygonTile[p]);
      const rgb = PALETTE[polygonLayers[p] % PALETTE.length];
      triangles(p, (ax, ay, bx, by, cx, cy) => {
        vertex(ox + ax, oy + ay, rgb);
        vertex(ox + bx, oy + by, rgb);
        vertex(ox + cx, oy + cy, rgb);
        edges.set([ox + ax, oy + ay, ox + bx, oy + by, ox + bx, oy + by, ox + cx, oy + cy,
          ox + cx, oy + cy, ox + ax, oy + ay], e);
        e += 12;
      });
    }
    const gl = this.gl;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.position);
    gl.bufferData(gl.ARRAY_BUFFER, position.subarray(0, 2 * at), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.colour);
    gl.bufferData(gl.ARRAY_BUFFER, colour.subarray(0, 3 * at), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.edges);
    gl.bufferData(gl.ARRAY_BUFFER, edges.subarray(0, e), gl.STATIC_DRAW);
    this.count = at;
    this.edgeCount = e / 2;
  }

  // Outlines around the rings of polygons (the wrong ones), or none.
  setOutlines(polygons) {
    this.outlines = polygons.length === 0 ? null : polygons;
  }

  // The bounding box of polygon p, in world units.
  polygonBox(p) {
    const { coords, ringOffsets, polygonOffsets } = this.region;
    const [ox, oy] = this.tileOrigin(this.polygonTile[p]);
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (let i = ringOffsets[polygonOffsets[p]]; i < ringOffsets[polygonOffsets[p + 1]]; i++) {
      minX = Math.min(minX, coords[2 * i]);
      maxX = Math.max(maxX, coords[2 * i]);
      minY = Math.min(minY, coords[2 * i + 1]);
      maxY = Math.max(maxY, coords[2 * i + 1]);
    }
    return [ox + minX, oy + minY, ox + maxX, oy + maxY];
  }

  resize() {
    const ratio = globalThis.devicePixelRatio || 1;
    for (const c of [this.canvas, this.overlay]) {
      c.width = Math.round(this.canvas.clientWidth * ratio);
      c.height = Math.round(this.canvas.clientHeight * ratio);
    }
  }

  fit() {
    const { columns, rows, extent } = this.grid;
    this.zoomTo([0, 0, columns * extent, rows * extent]);
  }

  zoomTo([x0, y0, x1, y1]) {
    this.resize();
    const w = this.canvas.width, h = this.canvas.height;
    const margin = 0.05 * Math.max(x1 - x0, y1 - y0) + 1;
    this.scale = Math.min(w / (x1 - x0 + 2 * margin), h / (y1 - y0 + 2 * margin));
    this.offset = [(x0 + x1) / 2 - w / (2 * this.scale), (y0 + y1) / 2 - h / (2 * this.scale)];
  }

  // Zooms by factor around canvas pixel (px, py).
  zoomAt(px, py, factor) {
    const [wx, wy] = [this.offset[0] + px / this.scale, this.offset[1] + py / this.scale];
    this.scale *= factor;
    this.offset = [wx - px / this.scale, wy - py / this.scale];
  }

  pan(dx, dy) {
    this.offset = [this.offset[0] - dx / this.scale, this.offset[1] - dy / this.scale];
  }

  draw() {
    const gl = this.gl, w = this.canvas.width, h = this.canvas.height;
    gl.viewport(0, 0, w, h);
    gl.clearColor(0.957, 0.945, 0.918, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.useProgram(this.program);
    // World (y down, as in tiles) to clip space (y up).
    const sx = 2 * this.scale / w, sy = -2 * this.scale / h;
    gl.uniform4f(gl.getUniformLocation(this.program, 'view'), sx, sy,
      -1 - this.offset[0] * sx, 1 - this.offset[1] * sy);
    const position = gl.getAttribLocation(this.program, 'position');
    const colour = gl.getAttribLocation(this.program, 'colour');
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.position);
    gl.enableVertexAttribArray(position);
    gl.vertexAttribPointer(position, 2, gl.FLOAT, false, 0, 0);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.colour);
    gl.enableVertexAttribArray(colour);
    gl.vertexAttribPointer(colour, 3, gl.UNSIGNED_BYTE, true, 0, 0);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    const alpha = gl.getUniformLocation(this.program, 'alpha');
    gl.uniform1f(alpha, 1);
    gl.drawArrays(gl.TRIANGLES, 0, 6 * this.grid.place.length);  // the tiles, opaque
    gl.uniform1f(alpha, 0.6);
    gl.drawArrays(gl.TRIANGLES, 6 * this.grid.place.length,
      this.count - 6 * this.grid.place.length);
    if (this.showEdges) {
      gl.disableVertexAttribArray(colour);
      gl.vertexAttrib3f(colour, 0.15, 0.2, 0.25);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.buffers.edges);
      gl.vertexAttribPointer(position, 2, gl.FLOAT, false, 0, 0);
      gl.uniform1f(alpha, 0.35);
      gl.drawArrays(gl.LINES, 0, this.edgeCount);
    }
    gl.disable(gl.BLEND);
    this.drawOutlines();
  }

  drawOutlines() {
    const c = this.overlay.getContext('2d');
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.clearRect(0, 0, this.overlay.width, this.overlay.height);
    if (!this.outlines) return;
    const { coords, ringOffsets, polygonOffsets } = this.region;
    const s = this.scale, [ox0, oy0] = this.offset;
    c.strokeStyle = '#d7301f';
    c.lineWidth = 3;
    c.beginPath();
    for (const p of this.outlines) {
      const [ox, oy] = this.tileOrigin(this.polygonTile[p]);
      for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) {
        for (let i = ringOffsets[r]; i < ringOffsets[r + 1]; i++) {
          const x = (ox + coords[2 * i] - ox0) * s, y = (oy + coords[2 * i + 1] - oy0) * s;
          if (i === ringOffsets[r]) c.moveTo(x, y);
          else c.lineTo(x, y);
        }
        c.closePath();
      }
    }
    c.stroke();
  }
}
