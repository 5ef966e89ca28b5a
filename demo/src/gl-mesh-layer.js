// A Leaflet layer that draws a triangulation with WebGL: one canvas, a little larger than
// the map, the mesh uploaded once and each redraw only a few uniforms. As with Leaflet's own
// vector renderers the canvas moves with the map while it pans and is scaled while it zooms,
// and is redrawn when the move ends: a million triangles pan at the compositor's frame rate
// even where WebGL is software-rendered. Positions are Mercator metres split in float32
// high + low parts (see mesh-buffers.js), made relative to the view centre on the GPU.
import L from 'leaflet';
import { EARTH_RADIUS } from './mercator.js';
import { GROUP_RANGES, MESH_PANE, fillRanges, meshPane } from './mesh-style.js';

const VERTEX_SHADER = `
attribute vec2 high;
attribute vec2 low;
uniform vec2 centreHigh;
uniform vec2 centreLow;
uniform vec2 metresToClip;
uniform vec2 shift; // in clip units, to draw a line again beside itself
void main() {
  vec2 d = (high - centreHigh) + (low - centreLow);
  gl_Position = vec4(d * metresToClip + shift, 0.0, 1.0);
}`;

const FRAGMENT_SHADER = `
precision mediump float;
uniform vec4 colour;
void main() { gl_FragColor = colour; }`;

// How far the canvas reaches past each side of the map, as a fraction of its size.
const PADDING = 0.2;

const SOFTWARE_RENDERERS = /swiftshader|llvmpipe|softpipe|software/i;

function getContext(canvas, antialias) {
  const attributes = { antialias, premultipliedAlpha: true, alpha: true };
  const gl = canvas.getContext('webgl2', attributes) || canvas.getContext('webgl', attributes);
  // WebGL 1 needs an extension for meshes of more than 65,536 vertices.
  const webgl2 = gl instanceof WebGL2RenderingContext;
  if (gl && !webgl2 && !gl.getExtension('OES_element_index_uint')) return null;
  return gl;
}

// Asked once before adding the layer, so that the caller can fall back to the canvas
// renderer. Returns null, 'WebGL' or 'WebGL (software)': software WebGL draws about four
// times faster without multisampling, so that one gets none.
export function webglKind() {
  const gl = getContext(document.createElement('canvas'), true);
  if (!gl) return null;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return SOFTWARE_RENDERERS.test(renderer) ? 'WebGL (software)' : 'WebGL';
}

export const GlMeshLayer = L.Layer.extend({
  options: { pane: MESH_PANE },

  initialize(mesh, style, { antialias = true } = {}) {
    this._mesh = mesh;
    this._style = style;
    this._antialias = antialias;
  },

  onAdd(map) {
    meshPane(map);
    const canvas = L.DomUtil.create('canvas', 'leaflet-zoom-animated geocdt-gl');
    const gl = getContext(canvas, this._antialias);
    this._canvas = canvas;
    this._gl = gl;
    // A GPU reset loses the context: build everything again when the browser restores it.
    canvas.addEventListener('webglcontextlost', (e) => e.preventDefault());
    canvas.addEventListener('webglcontextrestored', () => {
      this._program = buildProgram(gl);
      this._upload();
      this._reset();
    });
    this._program = buildProgram(gl);
    this._upload();
    this.getPane().appendChild(canvas);
    this._reset();
  },

  onRemove() {
    const gl = this._gl;
    this._deleteBuffers();
    gl.deleteProgram(this._program.program);
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    L.DomUtil.remove(this._canvas);
  },

  getEvents() {
    // (Leaflet's viewreset always comes with a moveend: one redraw is enough.)
    return {
      moveend: this._reset,
      resize: this._reset,
      zoom: this._followZoom,
      zoomanim: this._animateZoom,
    };
  },

  // A new mesh in the same context: edits replace the buffers, not the canvas.
  setMesh(mesh) {
    this._mesh = mesh;
    if (!this._map) return;
    this._deleteBuffers();
    this._upload();
    this._draw();
  },

  _deleteBuffers() {
    for (const b of Object.values(this._buffers)) this._gl.deleteBuffer(b);
  },

  setStyle(style) {
    this._style = style;
    if (this._map) this._draw();
  },

  _upload() {
    const gl = this._gl;
    const m = this._mesh;
    const buffer = (target, data) => {
      const b = gl.createBuffer();
      gl.bindBuffer(target, b);
      gl.bufferData(target, data, gl.STATIC_DRAW);
      return b;
    };
    this._buffers = {
      positions: buffer(gl.ARRAY_BUFFER, m.positions),
      triangles: buffer(gl.ELEMENT_ARRAY_BUFFER, m.triangles),
      edges: buffer(gl.ELEMENT_ARRAY_BUFFER, m.edges),
      constraints: buffer(gl.ELEMENT_ARRAY_BUFFER, m.constraints),
    };
    if (m.surfaceTriangles) {
      this._buffers.surfaceTriangles = buffer(gl.ELEMENT_ARRAY_BUFFER, m.surfaceTriangles);
    }
  },

  // Puts the canvas over the map's current view (plus padding) and draws it there.
  _reset() {
    const map = this._map;
    if (!map) return;
    const size = map.getSize();
    const padded = size.multiplyBy(1 + 2 * PADDING).round();
    const ratio = window.devicePixelRatio || 1;
    const canvas = this._canvas;
    const topLeft = size.multiplyBy(-PADDING).round();
    L.DomUtil.setPosition(canvas, map.containerPointToLayerPoint(topLeft));
    const pixelWidth = Math.round(padded.x * ratio), pixelHeight = Math.round(padded.y * ratio);
    if (canvas.width !== pixelWidth || canvas.height !== pixelHeight) {
      canvas.width = Math.round(padded.x * ratio);
      canvas.height = Math.round(padded.y * ratio);
      canvas.style.width = `${padded.x}px`;
      canvas.style.height = `${padded.y}px`;
    }
    this._halfCanvas = padded.divideBy(2);
    this._drawnCentre = map.containerPointToLatLng(topLeft.add(this._halfCanvas));
    this._drawnZoom = map.getZoom();
    this._draw();
  },

  _animateZoom(e) {
    this._scaleTo(e.center, e.zoom);
  },

  _followZoom() {
    this._scaleTo(this._map.getCenter(), this._map.getZoom());
  },

  // Until the next redraw, shows the last frame scaled and moved to the view at centre and
  // zoom: where the drawn centre lands at that zoom, minus the scaled half canvas.
  _scaleTo(centre, zoom) {
    const map = this._map;
    const scale = map.getZoomScale(zoom, this._drawnZoom);
    const topLeft = map
      .project(this._drawnCentre, zoom)
      .subtract(this._halfCanvas.multiplyBy(scale))
      .subtract(map._getNewPixelOrigin(centre, zoom));
    L.DomUtil.setTransform(this._canvas, topLeft, scale);
  },

  _draw() {
    const gl = this._gl;
    const { program, attributes, uniforms } = this._program;
    const width = parseFloat(this._canvas.style.width);
    const height = parseFloat(this._canvas.style.height);
    const centre = L.CRS.EPSG3857.project(this._drawnCentre);
    const metresToPixels = (256 * 2 ** this._drawnZoom) / (2 * Math.PI * EARTH_RADIUS);

    gl.viewport(0, 0, this._canvas.width, this._canvas.height);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.useProgram(program);
    const cx = Math.fround(centre.x);
    const cy = Math.fround(centre.y);
    gl.uniform2f(uniforms.centreHigh, cx, cy);
    gl.uniform2f(uniforms.centreLow, centre.x - cx, centre.y - cy);
    const toClip = 2 * metresToPixels;
    gl.uniform2f(uniforms.metresToClip, toClip / width, toClip / height);

    gl.bindBuffer(gl.ARRAY_BUFFER, this._buffers.positions);
    gl.enableVertexAttribArray(attributes.high);
    gl.enableVertexAttribArray(attributes.low);
    gl.vertexAttribPointer(attributes.high, 2, gl.FLOAT, false, 16, 0);
    gl.vertexAttribPointer(attributes.low, 2, gl.FLOAT, false, 16, 8);

    const m = this._mesh;
    const s = this._style;
    gl.uniform2f(uniforms.shift, 0, 0);
    for (const [array, colour, first, count] of fillRanges(m, s)) {
      if (count === 0) continue;
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this._buffers[array]);
      gl.uniform4fv(uniforms.colour, premultiply(colour));
      gl.drawElements(gl.TRIANGLES, 3 * count, gl.UNSIGNED_INT, 12 * first);
    }
    // Edges a pixel or two apart would only grey the map out (and cost the most to draw):
    // fade them in as the map zooms in.
    const edgePixels = m.typicalEdge * metresToPixels;
    const fade = Math.min(1, (edgePixels - 1.5) / 12);
    const edgeColour = [...s.edgeColour.slice(0, 3), s.edgeColour[3] * Math.max(0.15, fade)];
    // WebGL lines are one pixel wide: constraints are drawn three times, a pixel apart.
    const [px, py] = [2 / width, 2 / height];
    const lines = [
      [s.edges && fade > 0, this._buffers.edges, m.edgeCounts, edgeColour, [[0, 0]]],
      [s.constraints, this._buffers.constraints, m.constraintCounts, s.constraintColour,
        [[0, 0], [px, 0], [0, py]]],
    ];
    for (const [visible, buffer, counts, colour, shifts] of lines) {
      if (!visible) continue;
      const [first, count] = GROUP_RANGES[s.show](counts);
      if (count === 0) continue;
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffer);
      gl.uniform4fv(uniforms.colour, premultiply(colour));
      for (const [x, y] of shifts) {
        gl.uniform2f(uniforms.shift, x, y);
        gl.drawElements(gl.LINES, 2 * count, gl.UNSIGNED_INT, 8 * first);
      }
    }
  },
});

function premultiply([r, g, b, a]) {
  return [r * a, g * a, b * a, a];
}

function buildProgram(gl) {
  const compile = (type, source) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new Error(gl.getShaderInfoLog(shader));
    }
    return shader;
  };
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, VERTEX_SHADER));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, FRAGMENT_SHADER));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error(gl.getProgramInfoLog(program));
  }
  const attributes = {
    high: gl.getAttribLocation(program, 'high'),
    low: gl.getAttribLocation(program, 'low'),
  };
  const uniforms = {};
  for (const name of ['centreHigh', 'centreLow', 'metresToClip', 'shift', 'colour']) {
    uniforms[name] = gl.getUniformLocation(program, name);
  }
  return { program, attributes, uniforms };
}
