// Small meshes drawn as ordinary Leaflet vectors on one shared canvas renderer, fine up to
// some tens of thousands of triangles. Triangles go in polygons of FILL_CHUNK rings: the
// 2D canvas fills one path of 40,000 contours about 80 times slower than 600 paths of 64.
import L from 'leaflet';
import { GROUP_RANGES, cssColour, fillRanges, meshPane } from './mesh-style.js';

const FILL_CHUNK = 64;
const LINE_CHUNK = 1024;

function chunks(count, size, make) {
  const out = [];
  for (let first = 0; first < count; first += size) {
    out.push(make(first, Math.min(size, count - first)));
  }
  return out;
}

export const CanvasMeshLayer = L.LayerGroup.extend({
  initialize(mesh, style, map) {
    L.LayerGroup.prototype.initialize.call(this);
    this._renderer = L.canvas({ padding: 0.3, pane: meshPane(map) });
    this._style = style;
    this.setMesh(mesh);
  },

  setMesh(mesh) {
    this._mesh = mesh;
    const p = mesh.points;
    this._latLngs = new Array(p.length / 2);
    for (let i = 0; i < p.length; i += 2) {
      this._latLngs[i / 2] = L.CRS.EPSG3857.unproject(L.point(p[i], p[i + 1]));
    }
    return this.setStyle(this._style);
  },

  setStyle(s) {
    this._style = s;
    this.clearLayers();
    const m = this._mesh;
    const ll = this._latLngs;
    const renderer = this._renderer;
    const triangleRings = (triangles, first, count) => {
      const rings = new Array(count);
      for (let t = 0; t < count; t++) {
        const i = 3 * (first + t);
        rings[t] = [ll[triangles[i]], ll[triangles[i + 1]], ll[triangles[i + 2]]];
      }
      return rings;
    };
    for (const [array, colour, first, count] of fillRanges(m, s)) {
      if (count === 0) continue;
      const options = {
        renderer, stroke: false, fillColor: cssColour(colour), fillOpacity: 1, interactive: false,
        smoothFactor: 0,
      };
      const rings = (f, n) => triangleRings(m[array], first + f, n);
      for (const part of chunks(count, FILL_CHUNK, rings)) {
        this.addLayer(L.polygon(part, options));
      }
    }
    const lines = [
      [s.edges, m.edges, m.edgeCounts, s.edgeColour, 0.7],
      [s.constraints, m.constraints, m.constraintCounts, s.constraintColour, 1.6],
    ];
    for (const [visible, pairs, counts, colour, weight] of lines) {
      const [first, count] = GROUP_RANGES[s.show](counts);
      if (!visible || count === 0) continue;
      const options = {
        renderer, color: cssColour(colour), opacity: 1, weight, interactive: false, smoothFactor: 0,
      };
      const segments = (f, n) => {
        const part = new Array(n);
        for (let k = 0; k < n; k++) {
          const at = 2 * (first + f + k);
          part[k] = [ll[pairs[at]], ll[pairs[at + 1]]];
        }
        return part;
      };
      for (const part of chunks(count, LINE_CHUNK, segments)) {
        this.addLayer(L.polyline(part, options));
      }
    }
    return this;
  },
});
