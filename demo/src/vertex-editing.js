// (Requests name the vertex `vertex`: `id` is the request's own, in the worker protocol.)
// "Edit" mode: a click picks the nearest point or line vertex of the triangulation, shown as a
// handle that can be dragged (the mesh follows live: each drag step moves the vertex in the
// worker, a step at a time); Delete removes the picked point, Shift+Delete (or the panel's
// buttons) the lines through the picked vertex.
import L from 'leaflet';

const HANDLE = L.divIcon({ className: 'vertex-handle', iconSize: [14, 14] });

export class VertexEditing {
  // request(type, payload) runs a worker request and redraws with its reply (a promise);
  // onSelect(picked or null) tells the panel what is picked.
  constructor(map, { request, onSelect }) {
    this._map = map;
    this._request = request;
    this._onSelect = onSelect;
    this._active = false;
    this._picked = null; // { id, lonLat, point, lines }
    this._handle = null;
    this._moving = false; // a move is in flight in the worker
    this._next = null; // the latest drag position not sent yet
    map.on('click', (e) => this._active && this._pick(e.latlng));
    document.addEventListener('keydown', (e) => {
      if (!this._active || !this._picked || (e.key !== 'Delete' && e.key !== 'Backspace')) return;
      if (e.shiftKey) this.removeLines();
      else this.removePoint();
    });
  }

  get picked() {
    return this._picked;
  }

  setActive(active) {
    this._active = active;
    if (!active) this._select(null);
  }

  async _pick(latlng) {
    const reply = await this._request('pick', { lonLat: [latlng.lng, latlng.lat] }, false);
    this._select(reply?.picked ?? null);
  }

  _select(picked) {
    this._handle?.remove();
    this._handle = null;
    this._picked = picked;
    if (picked) {
      const [lng, lat] = picked.lonLat;
      this._handle = L.marker([lat, lng], { icon: HANDLE, draggable: true, keyboard: false });
      this._handle.on('drag', (e) => this._dragTo(e.target.getLatLng()));
      this._handle.on('dragend', (e) => this._dragTo(e.target.getLatLng()));
      this._handle.addTo(this._map);
    }
    this._onSelect(picked);
  }

  // Live: one move in flight at a time, then the latest position the drag reached.
  async _dragTo(latlng) {
    this._next = [latlng.lng, latlng.lat];
    if (this._moving || !this._picked) return;
    this._moving = true;
    try {
      while (this._next) {
        const lonLat = this._next;
        this._next = null;
        await this._request('movePoint', { vertex: this._picked.id, lonLat }, true);
        this._picked.lonLat = lonLat;
      }
    } finally {
      this._moving = false;
    }
  }

  async removePoint() {
    const picked = this._picked;
    if (!picked?.point) return;
    this._select(null);
    await this._request('removePoint', { vertex: picked.id }, true);
  }

  async removeLines() {
    const picked = this._picked;
    if (!picked?.lines.length) return;
    this._select(null);
    await this._request('removeLines', { vertex: picked.id }, true);
  }
}
