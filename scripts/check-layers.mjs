// Checks that no include in cpp/ runs upward: a folder of cpp/src includes only headers of
// folders below it in LAYERS (ARCHITECTURE.md draws the same order). The public headers
// (cpp/include/geocdt) hold the API's plain types and sit below everything.
//   node scripts/check-layers.mjs    # prints each include that breaks the order; exit 1 then
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

// Bottom first. A folder may include folders of lower rank only; '.' is the Triangulation
// facade, and voronoi, which clips cells to rings triangulated through it, sits above it.
const LAYERS = [
  ['geocdt', 'base'],
  ['exact'],
  ['mesh'],
  ['delaunay'],
  ['constraints', 'labels', 'values'],
  ['parallel', 'refine'],
  ['terrain'],
  ['.'],
  ['polygons', 'voronoi'],
];

const rank = new Map(LAYERS.flatMap((names, r) => names.map((name) => [name, r])));
const root = fileURLToPath(new URL('..', import.meta.url));
const src = join(root, 'cpp', 'src');

function* sources(dir) {
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) yield* sources(path);
    else if (/\.(h|cpp)$/.test(entry.name)) yield path;
  }
}

const problems = [];
for (const file of sources(src)) {
  const rel = relative(src, file).split(sep);
  const layer = rel.length === 1 ? '.' : rel[0];
  if (!rank.has(layer)) {
    problems.push(`cpp/src/${rel.join('/')}: folder '${layer}' has no place in LAYERS`);
    continue;
  }
  const lines = readFileSync(file, 'utf8').split('\n');
  lines.forEach((line, i) => {
    const include = /^#include "([^"]+)"/.exec(line)?.[1];
    if (include === undefined) return;
    const target = include.includes('/') ? include.split('/')[0] : '.';
    if (target === layer) return;
    const where = `cpp/src/${rel.join('/')}:${i + 1}`;
    if (!rank.has(target)) {
      problems.push(`${where}: includes "${include}" from a folder with no place in LAYERS`);
    } else if (rank.get(target) >= rank.get(layer)) {
      problems.push(`${where}: '${layer}' includes "${include}", which is not below it`);
    }
  });
}

if (problems.length > 0) {
  console.error(problems.join('\n'));
  console.error('check-layers: includes must run downward (scripts/check-layers.mjs, '
    + 'ARCHITECTURE.md)');
  process.exit(1);
}
