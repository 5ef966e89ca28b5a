// The Voronoi page's module worker: holds the domain (the land rings of a bundled dataset, or
// a dropped GeoJSON's polygons), projected to Web Mercator, and makes the cells of the sites the
// page sends, clipped to it, with geocdt.voronoi(). The cells go back as transferred buffers.
import { init, voronoi } from 'geocdt';
import { decodeDataset } from './dataset-codec.js';
import { parseGeoJSONText } from './geojson-input.js';
import { projectLonLat } from './mercator.js';

// The domain's rings, projected, and where the page can scatter sites (lon/lat bounds).
let domain = { rings: [], bounds: [-180, -60, 180, 80] };

self.onmessage = async ({ data: request }) => {
  try {
    await init({ threads: 'auto' });
    const reply = await handle(request);
    const transfer = reply.cells ? [reply.cells.coords.buffer, reply.cells.ringOffsets.buffer,
      reply.cells.polygonOffsets.buffer, reply.cells.siteOffsets.buffer] : [];
    if (reply.cells?.points) transfer.push(reply.cells.points.buffer);
    self.postMessage({ id: request.id, ok: true, ...reply }, transfer);
  } catch (e) {
    const userFacing = e?.name === 'InputError'
      || ((e instanceof TypeError || e instanceof RangeError) && /^geocdt:/.test(e.message));
    self.postMessage({ id: request.id, ok: false, error: String(e?.message ?? e),
      kind: userFacing ? 'input' : 'internal' });
  }
};

function boundsOf(lines) {
  const b = [Infinity, Infinity, -Infinity, -Infinity];
  for (const xy of lines) {
    for (let i = 0; i < xy.length; i += 2) {
      b[0] = Math.min(b[0], xy[i]);
      b[1] = Math.min(b[1], xy[i + 1]);
      b[2] = Math.max(b[2], xy[i]);
      b[3] = Math.max(b[3], xy[i + 1]);
    }
  }
  return b;
}

async function handle(request) {
  switch (request.type) {
    case 'dataset': {
      const started = performance.now();
      const response = await fetch(request.url);
      if (!response.ok) throw new Error(`could not load ${request.url}: HTTP ${response.status}`);
      const land = decodeDataset(await response.arrayBuffer()).find((l) => l.role === 'ring');
      domain = { rings: land.lines.map((l) => projectLonLat(l)), bounds: [-180, -60, 180, 80] };
      return { rings: domain.rings.length, loadMs: performance.now() - started };
    }
    case 'geojson': {
      const { points, rings } = parseGeoJSONText(new TextDecoder().decode(request.bytes));
      if (rings.length > 0) {
        domain = { rings: rings.map((r) => projectLonLat(r)), bounds: boundsOf(rings) };
      }
      return { rings: domain.rings.length, sites: projectLonLat(Float64Array.from(points)),
        bounds: domain.bounds };
    }
    case 'cells': {
      const started = performance.now();
      const clip = request.clip === 'box' ? request.box : request.clip;
      const polylines = request.clip === 'rings' ? domain.rings : undefined;
      const cells = voronoi({ points: request.sites, polylines },
        { clip, lloyd: request.lloyd > 0 ? { iterations: request.lloyd } : undefined });
      return { cells, ms: performance.now() - started };
    }
    default:
      throw new Error(`unknown request ${request.type}`);
  }
}
