#!/usr/bin/env node
// Writes the real vector datasets of the constraint benchmarks and tests as .gpl files:
//   ne_<scale>_rings.gpl    every ring of every country separately, so shared borders overlap
//   ne_<scale>_arcs.gpl     the mesh of country borders and coasts, each shared arc once
//   us_counties_rings.gpl   every ring of every US county (us-atlas counties-10m)
// for the Natural Earth scales 10m, 50m and 110m (world-atlas). Coordinates are lon/lat.
// Each rings file has a .gpg beside it that groups its rings into polygons: one per country
// (or county), in the order of the features, with all the rings of its Polygon or
// MultiPolygon.
// Usage: node scripts/datasets/natural_earth.mjs [output folder, default build/data]
import { mkdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import topojson from 'topojson-client';
import { writePolygons, writePolylines } from './dataset_file.mjs';

const require = createRequire(import.meta.url);
const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');

function loadTopology(name) {
  return JSON.parse(readFileSync(require.resolve(name), 'utf8'));
}

// Rings as topojson-client decodes them: closed, the first point repeated at the end; and
// how many each feature has.
function ringsOf(topology, objectName) {
  const rings = [];
  const perFeature = [];
  const { features } = topojson.feature(topology, topology.objects[objectName]);
  for (const { geometry } of features) {
    const polygons = geometry?.type === 'Polygon' ? [geometry.coordinates]
      : geometry?.type === 'MultiPolygon' ? geometry.coordinates : [];
    const before = rings.length;
    for (const polygon of polygons) rings.push(...polygon);
    perFeature.push(rings.length - before);
  }
  return { rings, perFeature };
}

function arcsOf(topology, objectName) {
  return topojson.mesh(topology, topology.objects[objectName]).coordinates;
}

function main() {
  const outDir = resolve(process.argv[2] ?? join(repoRoot, 'build', 'data'));
  mkdirSync(outDir, { recursive: true });
  const rows = [];
  const writeRings = (name, { rings, perFeature }) => {
    write(`${name}.gpl`, rings);
    writePolygons(join(outDir, `${name}.gpg`), perFeature);
  };
  const write = (name, polylines) => {
    const open = polylines.filter((l) => {
      const a = l[0], b = l[l.length - 1];
      return l.length < 2 || a[0] !== b[0] || a[1] !== b[1];
    }).length;
    const counts = writePolylines(join(outDir, name), polylines);
    rows.push({ file: name, ...counts, open });
  };
  for (const scale of ['10m', '50m', '110m']) {
    const topology = loadTopology(`world-atlas/countries-${scale}.json`);
    writeRings(`ne_${scale}_rings`, ringsOf(topology, 'countries'));
    write(`ne_${scale}_arcs.gpl`, arcsOf(topology, 'countries'));
  }
  writeRings('us_counties_rings', ringsOf(loadTopology('us-atlas/counties-10m.json'), 'counties'));

  console.log(`Wrote to ${outDir}:`);
  console.log('| file | polylines | points | open polylines |');
  console.log('|---|---:|---:|---:|');
  for (const r of rows) console.log(`| ${r.file} | ${r.polylines} | ${r.points} | ${r.open} |`);
}

main();
