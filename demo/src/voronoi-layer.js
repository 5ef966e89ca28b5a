// Voronoi cells on one canvas over the map: each site's cell (GeoArrow arrays in Web Mercator
// metres, as geocdt.voronoi() returns them) filled in a colour of its own, outlined, with the
// sites as dots. Redrawn whole after every move or zoom: a few hundred thousand cells a second.
import L from 'leaflet';
import { EARTH_RADIUS } from './mercator.js';

// A colour per site, spread around the hue circle by the golden angle.
export function siteColour(i) {
  return `hsl(${(i * 137.508) % 360} 70% 62%)`;
}

export const VoronoiLayer = L.Layer.extend({
  onAdd(map) {
    this._map = map;
    this._canvas = L.DomUtil.create('canvas', 'leaflet-zoom-hide voronoi-canvas');
    map.getPanes().overlayPane.appendChild(this._canvas);
    map.on('moveend zoomend resize', this._redraw, this);
    this._redraw();
  },

  onRemove(map) {
    map.off('moveend zoomend resize', this._redraw, this);
    this._canvas.remove();
  },

  // cells: voronoi()'s result; sites: the sites' x, y in metres.
  setCells(cells, sites) {
    this._cells = cells;
    this._sites = sites;
    if (this._map) this._redraw();
  },

  _redraw() {
    const map = this._map;
    const size = map.getSize();
    const ratio = window.devicePixelRatio || 1;
    const canvas = this._canvas;
    canvas.width = size.x * ratio;
    canvas.height = size.y * ratio;
    canvas.style.width = `${size.x}px`;
    canvas.style.height = `${size.y}px`;
    L.DomUtil.setPosition(canvas, map.containerPointToLayerPoint([0, 0]));
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, size.x, size.y);
    if (!this._cells) return;
    // Web Mercator metres -> container pixels at this zoom (Leaflet's EPSG:3857 transform).
    const world = 256 * 2 ** map.getZoom();
    const k = world / (2 * Math.PI * EARTH_RADIUS);
    const origin = map.getPixelBounds().min;
    const px = (x) => world / 2 + k * x - origin.x;
    const py = (y) => world / 2 - k * y - origin.y;
    const { coords, ringOffsets, polygonOffsets, siteOffsets } = this._cells;
    const sites = siteOffsets.length - 1;
    ctx.lineWidth = 0.6;
    ctx.strokeStyle = 'rgba(30, 35, 40, 0.75)';
    for (let i = 0; i < sites; i++) {
      if (siteOffsets[i + 1] === siteOffsets[i]) continue;
      ctx.beginPath();
      for (let r = polygonOffsets[siteOffsets[i]]; r < polygonOffsets[siteOffsets[i + 1]]; r++) {
        for (let p = ringOffsets[r]; p < ringOffsets[r + 1]; p++) {
          const x = px(coords[2 * p]), y = py(coords[2 * p + 1]);
          if (p === ringOffsets[r]) ctx.moveTo(x, y);
          else ctx.lineTo(x, y);
        }
        ctx.closePath();
      }
      ctx.fillStyle = siteColour(i);
      ctx.fill('evenodd');
      ctx.stroke();
    }
    if (sites > 20_000) return;
    ctx.fillStyle = '#1d2327';
    for (let i = 0; i < sites; i++) {
      ctx.fillRect(px(this._sites[2 * i]) - 1.5, py(this._sites[2 * i + 1]) - 1.5, 3, 3);
    }
  },
});
