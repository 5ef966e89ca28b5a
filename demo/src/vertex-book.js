// The worker's record of what can be edited in its incremental Triangulation: where each
// point and line vertex is (by id, in projected metres), which ids are points, and the ids of
// each line. Crossings and Steiner points are not in it: they move with what made them.
import { MAX_LATITUDE, unprojectXY } from './mercator.js';

export class VertexBook {
  constructor() {
    this.places = new Map(); // id -> [x, y]
    this.points = new Set();
    this.lines = []; // { ids, live }
  }

  addPoints(ids, xy) {
    ids.forEach((id, i) => {
      this.places.set(id, [xy[2 * i], xy[2 * i + 1]]);
      this.points.add(id);
    });
  }

  addLine(ids, xy) {
    ids.forEach((id, i) => this.places.set(id, [xy[2 * i], xy[2 * i + 1]]));
    this.lines.push({ ids: Array.from(ids), live: true });
  }

  // The live lines through vertex id, by polyline number.
  linesOf(id) {
    const out = [];
    this.lines.forEach((line, k) => line.live && line.ids.includes(id) && out.push(k));
    return out;
  }

  // The nearest editable vertex among those locate() named at (x, y), as the panel shows it.
  pick(location, x, y) {
    let best = null;
    let bestDistance = Infinity;
    for (const id of location.vertices) {
      const place = this.places.get(id);
      if (!place || !(this.points.has(id) || this.linesOf(id).length > 0)) continue;
      const d = Math.hypot(place[0] - x, place[1] - y);
      if (d < bestDistance) [best, bestDistance] = [id, d];
    }
    if (best === null) return null;
    const [lon, lat] = unprojectXY(this.places.get(best));
    return {
      id: best,
      lonLat: [lon, Math.max(-MAX_LATITUDE, Math.min(MAX_LATITUDE, lat))],
      point: this.points.has(best),
      lines: this.linesOf(best),
    };
  }
}
