// Spherical Web Mercator (EPSG:3857) in metres, the projection of Leaflet's L.CRS.EPSG3857,
// written out so that the worker can project without loading Leaflet (which needs a DOM).
// The tests check it against L.CRS.EPSG3857.project.

export const EARTH_RADIUS = 6378137;
export const MAX_LATITUDE = 85.0511287798; // where the square world map ends

const RAD = Math.PI / 180;

// Projects lon/lat pairs from `from` into x/y pairs in `to` (may be the same array).
export function projectLonLat(from, to = new Float64Array(from.length)) {
  for (let i = 0; i < from.length; i += 2) {
    const lat = Math.max(-MAX_LATITUDE, Math.min(MAX_LATITUDE, from[i + 1]));
    const sin = Math.sin(lat * RAD);
    to[i] = EARTH_RADIUS * from[i] * RAD;
    to[i + 1] = (EARTH_RADIUS * Math.log((1 + sin) / (1 - sin))) / 2;
  }
  return to;
}

// The inverse of projectLonLat for one x, y pair: [lon, lat] (for the editing handles).
export function unprojectXY([x, y]) {
  return [x / EARTH_RADIUS / RAD, (2 * Math.atan(Math.exp(y / EARTH_RADIUS)) - Math.PI / 2) / RAD];
}
