// Extracts GSHHG/WDBII river lines with GMT into a small TopoJSON file under
// demo/data/. Run by hand when the bundled rivers change (needs Debian `gmt` and
// `gmt-gshhg-full`); the output is committed so that building the demo needs no GMT.
//
//   node demo/scripts/extract-rivers.mjs c 1,2       -> demo/data/rivers-c.topo.json
//   node demo/scripts/extract-rivers.mjs i 1,2,3,4   -> demo/data/rivers-i.topo.json
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';

const QUANTUM = 1e-4; // degrees, about 11 m: finer than GSHHG's intermediate resolution

const [resolution = 'i', levelList = '1,2,3,4'] = process.argv.slice(2);
const levels = new Set(levelList.split(',').map(Number));

const gmtArgs = ['coast', '-Rd', ...[...levels].map((l) => `-I${l}`), `-D${resolution}`, '-M'];
// GMT drops a gmt.history file in its working directory: keep it out of the tree.
const text = execFileSync('gmt', gmtArgs, { encoding: 'utf8', maxBuffer: 1 << 28, cwd: tmpdir() });

// GSHHG stores rivers in bins, so one river comes out cut at every bin edge.
const segments = [];
let current = null;
for (const line of text.split('\n')) {
  if (line.startsWith('>')) {
    const level = Number(/Level\s+(\d+)/.exec(line)?.[1]);
    current = levels.has(level) ? { level, points: [] } : null;
    if (current) segments.push(current);
  } else if (current && line.trim()) {
    const [lon, lat] = line.trim().split(/\s+/).map(Number);
    const p = [Math.round((lon + 180) / QUANTUM), Math.round((lat + 90) / QUANTUM)];
    const last = current.points[current.points.length - 1];
    if (!last || last[0] !== p[0] || last[1] !== p[1]) current.points.push(p);
  }
}

const lines = joinAtBinEdges(segments.filter((s) => s.points.length >= 2));
const arcs = lines.map((l) => deltaEncode(l.points));
const topology = {
  type: 'Topology',
  transform: { scale: [QUANTUM, QUANTUM], translate: [-180, -90] },
  objects: {
    rivers: {
      type: 'GeometryCollection',
      geometries: lines.map((l, i) => ({
        type: 'LineString', arcs: [i], properties: { level: l.level },
      })),
    },
  },
  arcs,
};
const out = new URL(`../data/rivers-${resolution}.topo.json`, import.meta.url);
writeFileSync(out, JSON.stringify(topology));
const pointCount = lines.reduce((n, l) => n + l.points.length, 0);
console.log(`${segments.length} bin segments -> ${lines.length} lines, ${pointCount} points ` +
  `-> ${out.pathname}`);

function key(p) {
  return `${p[0]},${p[1]}`;
}

// Chains segments of the same level whose end meets another's start.
function joinAtBinEdges(parts) {
  const byStart = new Map();
  for (const s of parts) {
    const k = `${s.level}:${key(s.points[0])}`;
    if (!byStart.has(k)) byStart.set(k, []);
    byStart.get(k).push(s);
  }
  const used = new Set();
  const hasPredecessor = new Set();
  for (const s of parts) {
    const k = `${s.level}:${key(s.points[s.points.length - 1])}`;
    for (const next of byStart.get(k) ?? []) if (next !== s) hasPredecessor.add(next);
  }
  const chains = [];
  const follow = (first) => {
    const points = [...first.points];
    used.add(first);
    for (;;) {
      const k = `${first.level}:${key(points[points.length - 1])}`;
      const next = (byStart.get(k) ?? []).find((s) => !used.has(s));
      if (!next) break;
      used.add(next);
      for (let i = 1; i < next.points.length; i++) points.push(next.points[i]);
    }
    chains.push({ level: first.level, points });
  };
  for (const s of parts) if (!used.has(s) && !hasPredecessor.has(s)) follow(s);
  for (const s of parts) if (!used.has(s)) follow(s); // closed loops
  return chains;
}

function deltaEncode(points) {
  const arc = [points[0]];
  for (let i = 1; i < points.length; i++) {
    arc.push([points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]]);
  }
  return arc;
}
