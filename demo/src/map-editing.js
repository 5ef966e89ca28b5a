// Clicking on the map: in "point" mode each click is a new point; in "line" mode clicks
// extend a polyline, one constraint segment per click. The caller inserts them through
// the worker's incremental triangulation.
import L from 'leaflet';

export class MapEditing {
  constructor(map, { onPoint, onSegment, onModeChange }) {
    this._map = map;
    this._onPoint = onPoint;
    this._onSegment = onSegment;
    this._onModeChange = onModeChange;
    this._mode = 'pan';
    this._line = null; // the line being drawn: an L.Polyline preview
    map.on('click', (e) => this._click(e.latlng));
    document.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') this.finishLine();
    });
  }

  get mode() {
    return this._mode;
  }

  get drawing() {
    return this._line !== null;
  }

  setMode(mode) {
    this.finishLine();
    this._mode = mode;
    const container = this._map.getContainer();
    container.classList.toggle('editing', mode !== 'pan');
    // A double click would zoom while the user is placing vertices.
    if (mode === 'pan') this._map.doubleClickZoom.enable();
    else this._map.doubleClickZoom.disable();
    this._onModeChange();
  }

  finishLine() {
    if (!this._line) return;
    this._line.remove();
    this._line = null;
    this._onModeChange();
  }

  _click(latlng) {
    const lonLat = [latlng.lng, latlng.lat];
    if (this._mode === 'point') {
      this._onPoint(lonLat);
    } else if (this._mode === 'line') {
      if (!this._line) {
        this._line = L.polyline([latlng],
          { color: '#d7301f', weight: 2, dashArray: '4 4', interactive: false });
        this._line.addTo(this._map);
        this._onModeChange();
        return;
      }
      const points = this._line.getLatLngs();
      const last = points[points.length - 1];
      if (last.equals(latlng)) return;
      this._line.addLatLng(latlng);
      this._onSegment([last.lng, last.lat], lonLat);
    }
  }
}
