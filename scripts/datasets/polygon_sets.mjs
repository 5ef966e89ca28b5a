#!/usr/bin/env node
// Polygon batches in GeoArrow's layout, for triangulatePolygons(), its tests, its benchmark
// and its demo: the real-world vector tiles of @mapbox/mvt-fixtures, the Natural Earth 10m
// countries (world-atlas) each polygon alone, and those countries cut into tiles by
// geojson-vt. Run as a script, it writes each set as .gpl rings and .gpg polygons (the files of
// tests/cpp/support/polyline_file.h) for the native tests:
//   node scripts/datasets/polygon_sets.mjs [output folder, default build/data]
// Each set is
//   { name, coords, ringOffsets, polygonOffsets, tileOffsets? }
// with coords x, y interleaved (an Int32Array for the mvt-fixtures tiles, whose integers reach
// 2^20 in the OSM QA tiles; an Int16Array for geojson-vt's; else a Float64Array), ring r the
// vertices ringOffsets[r] .. ringOffsets[r + 1], polygon p the rings polygonOffsets[p] ..
// polygonOffsets[p + 1] (its shell first), and, for tiles, tile t the polygons tileOffsets[t] ..
// tileOffsets[t + 1]. Rings are closed, as decoders give them.
import { existsSync, mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { gunzipSync } from 'node:zlib';
import { VectorTile, classifyRings } from '@mapbox/vector-tile';
import { PbfReader } from 'pbf';
import { feature } from 'topojson-client';
import GeoJSONVT from 'geojson-vt';

const require = createRequire(import.meta.url);

// Collects rings (arrays of x, y numbers) into growing arrays, then packs them.
class BatchBuilder {
  constructor(name) {
    this.name = name;
    this.coords = [];
    this.ringOffsets = [0];
    this.polygonOffsets = [0];
    this.tileOffsets = [0];
  }

  // rings: arrays of flat x, y numbers, the shell first.
  addPolygon(rings) {
    for (const ring of rings) {
      for (let i = 0; i < ring.length; i++) this.coords.push(ring[i]);
      this.ringOffsets.push(this.coords.length / 2);
    }
    this.polygonOffsets.push(this.ringOffsets.length - 1);
  }

  endTile() {
    this.tileOffsets.push(this.polygonOffsets.length - 1);
  }

  build(CoordArray = Float64Array, withTiles = false) {
    const set = {
      name: this.name,
      coords: CoordArray.from(this.coords),
      ringOffsets: Uint32Array.from(this.ringOffsets),
      polygonOffsets: Uint32Array.from(this.polygonOffsets),
    };
    if (withTiles) set.tileOffsets = Uint32Array.from(this.tileOffsets);
    return set;
  }
}

const fixturesDir = () =>
  join(require.resolve('@mapbox/mvt-fixtures/package.json'), '..', 'real-world');

// The real-world tiles' file names, region/file, in a stable order.
export function mvtTileFiles() {
  const dir = fixturesDir();
  const files = [];
  for (const region of readdirSync(dir).sort()) {
    for (const file of readdirSync(join(dir, region)).sort()) {
      if (/\.mvt(\.gz)?$/.test(file)) files.push(`${region}/${file}`);
    }
  }
  return files;
}

// A tile's polygons as the MVT spec classifies rings (by signed area: an exterior ring, then
// its interior rings; rings of zero area dropped), each as arrays of flat x, y, layer by layer
// in name order; with layers, each as { layer, extent, rings }.
export function tilePolygons(bytes, { layers = false } = {}) {
  const tile = new VectorTile(new PbfReader(bytes));
  const polygons = [];
  for (const name of Object.keys(tile.layers).sort()) {
    const layer = tile.layers[name];
    for (let i = 0; i < layer.length; i++) {
      const f = layer.feature(i);
      if (f.type !== 3) continue;
      for (const polygon of classifyRings(f.loadGeometry())) {
        const rings = polygon.map((ring) => {
          const flat = new Array(2 * ring.length);
          for (let k = 0; k < ring.length; k++) {
            flat[2 * k] = ring[k].x;
            flat[2 * k + 1] = ring[k].y;
          }
          return flat;
        });
        polygons.push(layers ? { layer: name, extent: layer.extent, rings } : rings);
      }
    }
  }
  return polygons;
}

export function readTile(file) {
  const bytes = readFileSync(join(fixturesDir(), file));
  return file.endsWith('.gz') ? gunzipSync(bytes) : bytes;
}

// Every polygon of the 211 real-world tiles (Mapbox Streets, terrain, OSM QA), tile by tile.
export function mvtFixtures() {
  const b = new BatchBuilder('mvt-fixtures real-world tiles');
  for (const file of mvtTileFiles()) {
    for (const rings of tilePolygons(readTile(file))) b.addPolygon(rings);
    b.endTile();
  }
  return b.build(Int32Array, true);
}

function countries(scale) {
  const file = require.resolve(`world-atlas/countries-${scale}.json`);
  const t = JSON.parse(readFileSync(file, 'utf8'));
  return feature(t, t.objects.countries);
}

// Each polygon of each Natural Earth country (a MultiPolygon's parts alone), lon/lat.
export function naturalEarthPolygons(scale = '10m') {
  const b = new BatchBuilder(`Natural Earth ${scale} countries, each polygon alone`);
  for (const f of countries(scale).features) {
    const g = f.geometry;
    if (!g) continue;
    for (const rings of g.type === 'Polygon' ? [g.coordinates] : g.coordinates) {
      b.addPolygon(rings.map((ring) => ring.flat()));
    }
  }
  return b.build(Float64Array);
}

function ringArea(ring) {
  let sum = 0;
  for (let i = 0, j = ring.length - 2; i < ring.length; j = i, i += 2) {
    sum += (ring[j] - ring[i]) * (ring[i + 1] + ring[j + 1]);
  }
  return sum;
}

// The rings of a tile feature into polygons, as the MVT spec and classifyRings do.
function classifyFlatRings(rings) {
  const polygons = [];
  let polygon = null, ccw;
  for (const ring of rings) {
    const area = ringArea(ring);
    if (area === 0) continue;
    if (ccw === undefined) ccw = area < 0;
    if (ccw === area < 0) {
      if (polygon) polygons.push(polygon);
      polygon = [ring];
    } else if (polygon) {
      polygon.push(ring);
    }
  }
  if (polygon) polygons.push(polygon);
  return polygons;
}

// The Natural Earth 10m countries cut into tiles by geojson-vt (the tiler behind GeoJSON
// sources in Mapbox GL and MapLibre), at the given zooms: every tile that holds polygons.
export function geojsonVtCountries(zooms = [4, 5], scale = '10m') {
  const index = new GeoJSONVT(countries(scale), { maxZoom: Math.max(...zooms), indexMaxZoom: 0 });
  const b = new BatchBuilder(
    `Natural Earth ${scale} countries cut by geojson-vt, z${zooms.join('-')}`);
  for (const z of zooms) {
    for (let x = 0; x < 2 ** z; x++) {
      for (let y = 0; y < 2 ** z; y++) {
        const tile = index.getTile(z, x, y);
        if (!tile) continue;
        for (const f of tile.features) {
          if (f.type !== 3) continue;
          const rings = f.geometry.map((ring) => ring.flat());
          for (const rs of classifyFlatRings(rings)) b.addPolygon(rs);
        }
        b.endTile();
      }
    }
  }
  return b.build(Int16Array, true);
}

export function polygonCount(set) {
  return set.polygonOffsets.length - 1;
}

export function vertexCount(set) {
  return set.coords.length / 2;
}

// Polygon p as earcut takes it: { data, holes } with data x, y numbers (a plain array, as
// Mapbox GL passes them) and holes the vertex index where each interior ring starts.
export function earcutInput(set, p) {
  const { coords, ringOffsets, polygonOffsets } = set;
  const first = ringOffsets[polygonOffsets[p]];
  const data = Array.from(coords.subarray(2 * first, 2 * ringOffsets[polygonOffsets[p + 1]]));
  const holes = [];
  for (let r = polygonOffsets[p] + 1; r < polygonOffsets[p + 1]; r++) {
    holes.push(ringOffsets[r] - first);
  }
  return { data, holes, first };
}

// The three sets by name, decoded once and kept in build/data (decoding the tiles takes
// seconds): 'tiles', 'countries' and 'geojson-vt'.
export const SETS = {
  tiles: mvtFixtures,
  countries: () => naturalEarthPolygons('10m'),
  'geojson-vt': () => geojsonVtCountries([4, 5]),
};

const TYPES = { Int16Array, Int32Array, Float64Array };

const defaultCache = fileURLToPath(new URL('../../build/data', import.meta.url));

// Writes a set as polygons_<name>.gpl (its rings as float64 polylines) and .gpg (rings per
// polygon).
export function writeSetFiles(set, name, outDir) {
  const { coords, ringOffsets, polygonOffsets } = set;
  const rings = ringOffsets.length - 1, points = coords.length / 2;
  const gpl = new DataView(new ArrayBuffer(8 + 4 * rings + 16 * points));
  [0x47, 0x50, 0x4c, 0x31].forEach((byte, i) => gpl.setUint8(i, byte));
  gpl.setUint32(4, rings, true);
  for (let r = 0; r < rings; r++) {
    gpl.setUint32(8 + 4 * r, ringOffsets[r + 1] - ringOffsets[r], true);
  }
  const at = 8 + 4 * rings;
  for (let i = 0; i < 2 * points; i++) gpl.setFloat64(at + 8 * i, coords[i], true);
  writeFileSync(join(outDir, `polygons_${name}.gpl`), new Uint8Array(gpl.buffer));
  const polygons = polygonOffsets.length - 1;
  const gpg = new DataView(new ArrayBuffer(8 + 4 * polygons));
  [0x47, 0x50, 0x47, 0x31].forEach((byte, i) => gpg.setUint8(i, byte));
  gpg.setUint32(4, polygons, true);
  for (let p = 0; p < polygons; p++) {
    gpg.setUint32(8 + 4 * p, polygonOffsets[p + 1] - polygonOffsets[p], true);
  }
  writeFileSync(join(outDir, `polygons_${name}.gpg`), new Uint8Array(gpg.buffer));
}

export function loadSet(name, cacheDir = defaultCache) {
  const file = join(cacheDir, `polygons-${name}.json`);
  const binary = file.replace(/\.json$/, '.bin');
  if (existsSync(file) && existsSync(binary)) {
    const meta = JSON.parse(readFileSync(file, 'utf8'));
    const bytes = readFileSync(binary);
    const set = { name: meta.name };
    let at = bytes.byteOffset;
    for (const { key, type, length } of meta.arrays) {
      const Type = TYPES[type] ?? Uint32Array;
      set[key] = new Type(bytes.buffer.slice(at, at + length * Type.BYTES_PER_ELEMENT));
      at += length * Type.BYTES_PER_ELEMENT;
    }
    return set;
  }
  const set = SETS[name]();
  const keys = ['coords', 'ringOffsets', 'polygonOffsets', 'tileOffsets'].filter((k) => set[k]);
  mkdirSync(dirname(file), { recursive: true });
  writeFileSync(binary, Buffer.concat(keys.map((k) =>
    Buffer.from(set[k].buffer, set[k].byteOffset, set[k].byteLength))));
  writeFileSync(file, JSON.stringify({
    name: set.name,
    arrays: keys.map((key) => ({ key, type: set[key].constructor.name, length: set[key].length })),
  }));
  return set;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const outDir = process.argv[2] ?? defaultCache;
  mkdirSync(outDir, { recursive: true });
  for (const name of ['tiles', 'geojson-vt']) {
    writeSetFiles(loadSet(name, outDir), name.replace('-', '_'), outDir);
  }
}
