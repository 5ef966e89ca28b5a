// Keeps one mesh on the map, drawn by WebGL or by Leaflet's canvas renderer depending on
// its size (or the user's choice), and restyles it without touching the worker.
import { CanvasMeshLayer } from './canvas-mesh-layer.js';
import { GlMeshLayer, webglKind } from './gl-mesh-layer.js';
import { CANVAS_TRIANGLE_LIMIT } from './mesh-style.js';

export class MeshView {
  constructor(map, style, onNotice) {
    this._map = map;
    this._style = style;
    this._onNotice = onNotice;
    this._mesh = null;
    this._layer = null;
    this._renderer = 'auto';
    this.drawnWith = null;
    this._webgl = undefined; // asked once, when a mesh first wants it
  }

  show(mesh) {
    this._mesh = mesh;
    this._redraw();
  }

  setStyle(style) {
    this._style = style;
    this._layer?.setStyle(style);
  }

  setRenderer(choice) {
    this._renderer = choice;
    if (this._mesh) this._redraw();
  }

  _redraw() {
    const triangles = this._mesh.triangles.length / 3;
    const wantGl = this._renderer === 'webgl' ||
      (this._renderer === 'auto' && triangles > CANVAS_TRIANGLE_LIMIT);
    if (wantGl && this._webgl === undefined) this._webgl = webglKind();
    const kind = wantGl && this._webgl ? GlMeshLayer : CanvasMeshLayer;
    if (this._layer instanceof kind) {
      this._layer.setMesh(this._mesh);
      return;
    }
    if (this._layer) this._map.removeLayer(this._layer);
    this._layer = null;
    if (kind === GlMeshLayer) {
      const antialias = this._webgl === 'WebGL';
      this._layer = new GlMeshLayer(this._mesh, this._style, { antialias }).addTo(this._map);
      this.drawnWith = this._webgl;
      return;
    }
    if (wantGl) {
      this._onNotice('This browser has no usable WebGL: drawing with the slower canvas renderer.');
    }
    this._layer = new CanvasMeshLayer(this._mesh, this._style, this._map).addTo(this._map);
    this.drawnWith = 'Leaflet canvas';
  }
}
