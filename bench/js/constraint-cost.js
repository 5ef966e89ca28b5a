// What constraints cost in wasm: each dataset's polylines triangulated as constraints, against
// the same points with no constraints, by geocdt and by delaunator, in alternating rounds in
// one process (medians). Natural Earth 10m comes from world-atlas; the GSHHG regions from .gpl
// files (scripts/datasets/all.sh), when they are there.
//   node --expose-gc bench/js/constraint-cost.js [--data DIR] [--rounds N] [--module PATH]
//                                               [--compare PATH]
// --module imports another build of the package (its web/index.node.js) instead of this one;
// --compare runs another build's constrained triangulation alongside, in the same rounds.
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { alternate } from './timing.js';
import { countryArcs, countryRings } from './datasets.js';
import * as peers from './peers.js';

const n = (x) => x.toLocaleString('en-US');
const ms = (x) => (x < 10 ? x.toFixed(2) : x.toFixed(0));

// A .gpl file: "GPL1", uint32 P, uint32 count[P], then float64 x, y of every point.
export function readPolylineFile(path) {
  const bytes = readFileSync(path);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (bytes.toString('latin1', 0, 4) !== 'GPL1') throw new Error(`${path}: not a .gpl file`);
  const count = view.getUint32(4, true);
  const polylines = [];
  let at = 8 + 4 * count;
  for (let i = 0; i < count; i++) {
    const points = view.getUint32(8 + 4 * i, true);
    const xy = new Float64Array(2 * points);
    for (let k = 0; k < 2 * points; k++, at += 8) xy[k] = view.getFloat64(at, true);
    polylines.push(xy);
  }
  return polylines;
}

// Every polyline's points in one flat array, as the unconstrained contenders get them.
function flatPoints(polylines) {
  const total = polylines.reduce((s, l) => s + l.length, 0);
  const xy = new Float64Array(total);
  let at = 0;
  for (const l of polylines) {
    xy.set(l, at);
    at += l.length;
  }
  return xy;
}

function describeStats(r) {
  const s = r.stats;
  const points = r.inputToVertex.length;
  return `${(s.walkSteps / s.locates).toFixed(2)} steps/locate, ` +
    `${(s.flips / points).toFixed(2)} flips/pt, ${n(s.crossings)} crossings, ` +
    `core ${ms(s.coreMilliseconds)} ms`;
}

// Rows for one dataset: constrained, points alone, delaunator, with the ratios; with other,
// another build's constrained run too.
export async function constraintCost(geocdt, name, polylines, rounds, other) {
  const xy = flatPoints(polylines);
  const contenders = [
    { name: 'geocdt, constrained', run: () => geocdt.triangulate({ polylines }),
      describe: describeStats },
    { name: 'geocdt, points alone', run: () => geocdt.triangulate({ points: xy }),
      describe: describeStats },
    { name: 'delaunator, points', run: () => peers.delaunator(xy), describe: peers.summary },
  ];
  if (other) {
    contenders.push({ name: 'other build, constrained',
      run: () => other.triangulate({ polylines }), describe: describeStats });
  }
  const results = await alternate(contenders, rounds);
  const base = results['delaunator, points']?.ms;
  const alone = results['geocdt, points alone']?.ms;
  const rows = Object.entries(results).map(([who, r]) => r.error
    ? [who, 'FAILED', '', '', r.error]
    : [who, ms(r.ms), `${(r.ms / base).toFixed(2)}×`, `${(r.ms / alone).toFixed(2)}×`,
      r.summary]);
  console.log(`### ${name}: ${n(xy.length / 2)} points, ${n(polylines.length)} polylines ` +
    `(${rounds} rounds, medians)\n`);
  const line = (cells) => `| ${cells.join(' | ')} |`;
  const header = ['run', 'ms', 'vs delaunator', 'vs geocdt points alone', 'result'];
  console.log([line(header), line(header.map(() => '---')), ...rows.map(line)].join('\n'));
  console.log();
}

// The datasets: Natural Earth 10m always, the GSHHG regions found in dataDir.
export function constraintDatasets(dataDir) {
  const sets = [countryRings('10m'), countryArcs('10m')];
  const regions = [['gshhg_region.gpl', 'GSHHG Europe'], ['gshhg_asia.gpl', 'GSHHG Asia']];
  for (const [file, name] of regions) {
    const path = `${dataDir}/${file}`;
    if (existsSync(path)) sets.push({ name, polylines: readPolylineFile(path) });
    else console.log(`(${name}: ${path} is missing; scripts/datasets/all.sh makes it.)\n`);
  }
  return sets;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const option = (flag, fallback) => {
    const i = process.argv.indexOf(flag);
    return i >= 0 ? process.argv[i + 1] : fallback;
  };
  const dataDir = option('--data', fileURLToPath(new URL('../../build/data', import.meta.url)));
  const rounds = Number(option('--rounds', 5));
  const module = option('--module', null);
  const geocdt = await import(module ? pathToFileURL(module).href : 'geocdt');
  await geocdt.init();
  const compare = option('--compare', null);
  const other = compare ? await import(pathToFileURL(compare).href) : null;
  await other?.init();
  console.log('## What constraints cost: constrained vs the same points alone\n');
  for (const { name, polylines } of constraintDatasets(dataDir))
    await constraintCost(geocdt, name, polylines, rounds, other);
}
