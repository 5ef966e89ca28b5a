// The geocdt command line: GeoJSON file in, FeatureCollection of triangles out.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cellsToGeoJSON, init, meshToGeoJSON, triangulateGeoJSON, voronoiGeoJSON } from 'geocdt';
import { ProgressDisplay } from '../../web/progress-display.js';
import { uniform } from './support/inputs.js';

const cli = fileURLToPath(new URL('../../web/cli.js', import.meta.url));
const fixture = fileURLToPath(new URL('./fixtures/small.geojson', import.meta.url));
const dir = mkdtempSync(join(tmpdir(), 'geocdt-cli-'));

before(() => init());

function run(args, input) {
  return spawnSync(process.execPath, [cli, ...args],
    { encoding: 'utf8', input, maxBuffer: 1 << 30 });
}

function multiPointFile(n) {
  const xy = uniform(n, 5);
  const coordinates = [];
  for (let i = 0; i < xy.length; i += 2) coordinates.push([xy[i], xy[i + 1]]);
  const path = join(dir, `points-${n}.geojson`);
  const geometry = { type: 'MultiPoint', coordinates };
  writeFileSync(path, JSON.stringify({ type: 'Feature', properties: {}, geometry }));
  return path;
}

test('writes the same FeatureCollection as the API', () => {
  const input = multiPointFile(300);
  const out = join(dir, 'out.geojson');
  const p = run([input, '-o', out]);
  assert.equal(p.status, 0, p.stderr);
  assert.equal(p.stderr, '', 'small inputs print nothing');
  const written = JSON.parse(readFileSync(out, 'utf8'));
  const arrays = triangulateGeoJSON(JSON.parse(readFileSync(input, 'utf8')), { output: 'arrays' });
  const expected = meshToGeoJSON(arrays);
  assert.deepEqual(written, expected);
});

test('keeps ids, properties and heights as the API does, with or without inside flags', () => {
  const geojson = JSON.parse(readFileSync(fixture, 'utf8'));
  geojson.features[0].id = 'island';
  const input = join(dir, 'regions.geojson');
  writeFileSync(input, JSON.stringify(geojson));
  for (const flags of [[], ['--inside-flags']]) {
    const out = join(dir, 'regions-out.geojson');
    const p = run([input, '-o', out, ...flags]);
    assert.equal(p.status, 0, p.stderr);
    const written = JSON.parse(readFileSync(out, 'utf8'));
    assert.deepEqual(written, triangulateGeoJSON(geojson, { insideFlags: flags.length > 0 }));
    const island = written.features.filter((f) => f.id === 'island');
    assert.ok(island.length > 0 && island.every((f) => f.properties.name === 'island'));
    const outside = flags.length > 0 ? { inside: false } : null;  // outside every polygon
    assert.ok(written.features.some((f) => !('id' in f)
      && JSON.stringify(f.properties) === JSON.stringify(outside)));
    const well = written.features.flatMap((f) => f.geometry.coordinates[0])
      .find(([x, y]) => x === 1 && y === 1);
    assert.deepEqual(well, [1, 1, 250]);
  }
});

test('--per-feature fills each polygon alone, as triangulateGeoJSON({ perFeature }) does', () => {
  const geojson = JSON.parse(readFileSync(fixture, 'utf8'));
  const overlap = { type: 'Feature', id: 'bow tie', properties: { name: 'crossing' }, geometry: {
    type: 'Polygon', coordinates: [[[0, 0], [4, 4], [4, 0], [0, 4], [0, 0]]] } };
  geojson.features.push(overlap);
  const input = join(dir, 'per-feature.geojson');
  writeFileSync(input, JSON.stringify(geojson));
  for (const fillRule of ['evenodd', 'nonzero']) {
    const p = run([input, '--per-feature', '--fill-rule', fillRule, '--keep', 'inside']);
    assert.equal(p.status, 0, p.stderr);
    const expected = triangulateGeoJSON(geojson, { perFeature: true, fillRule });
    assert.ok(expected.features.some((f) => f.id === 'bow tie'));
    assert.deepEqual(JSON.parse(p.stdout), expected);
  }
  for (const flags of [['--keep', 'all'], ['--inside-flags'], ['--min-angle', '20']]) {
    const p = run([input, '--per-feature', ...flags]);
    assert.equal(p.status, 2);
    assert.match(p.stderr, /--per-feature keeps the inside of each polygon alone/);
  }
});

test('reads stdin and writes stdout', () => {
  const geojson = readFileSync(multiPointFile(50), 'utf8');
  const p = run(['-'], geojson);
  assert.equal(p.status, 0, p.stderr);
  assert.equal(JSON.parse(p.stdout).features.length,
    triangulateGeoJSON(JSON.parse(geojson)).features.length);
});

test('--stats and progress for a big input go to stderr', () => {
  const out = join(dir, 'big.geojson');
  const p = run([multiPointFile(250_000), '-o', out, '--stats']);
  assert.equal(p.status, 0, p.stderr);
  assert.match(p.stderr, /geocdt: read 250,000 points/);
  assert.match(p.stderr, /geocdt: triangulated: [\d,]+ triangles in \d+ ms/);
  assert.match(p.stderr, /geocdt: writing 100%/);
  // Not a terminal: plain lines, one per phase and quarter, never a bar.
  // Which phases get a line depends on how long each takes (reports are 100 ms apart); their
  // order does not.
  const phases = ['sort', 'points', 'constraints', 'export'];
  const lines = [...p.stderr.matchAll(/^geocdt: triangulating: (\w+) (\d+)%$/gm)];
  assert.ok(lines.length >= 2, p.stderr);
  const order = lines.map((m) => phases.indexOf(m[1]));
  assert.ok(order.every((k, i) => k >= 0 && (i === 0 || k >= order[i - 1])), p.stderr);
  assert.match(p.stderr, /^geocdt: triangulating: export 100%$/m);
  assert.doesNotMatch(p.stderr, /\r|\[#/);
  assert.match(p.stderr, /inserted\s+250,000/);
  assert.ok(JSON.parse(readFileSync(out, 'utf8')).features.length > 490_000);
});

test('--threads: the points on two threads, the same triangles', () => {
  const file = multiPointFile(100_000);
  const outs = ['1', '2'].map((threads) => {
    const out = join(dir, `threads-${threads}.geojson`);
    const p = run([file, '-o', out, '--threads', threads, '--stats', '--quiet']);
    assert.equal(p.status, 0, p.stderr);
    assert.match(p.stderr, new RegExp(`threads\\s+${threads}\\b`));
    return readFileSync(out, 'utf8');
  });
  const corners = (text) => JSON.parse(text).features
    .map((f) => JSON.stringify(f.geometry.coordinates[0].slice(0, 3).sort())).sort();
  assert.deepEqual(corners(outs[1]), corners(outs[0]));
  const bad = run([file, '--threads', '0']);
  assert.notEqual(bad.status, 0);
  assert.match(bad.stderr, /--threads must be auto or a number from 1 to 64, not 0/);
});

test('--keep inside with polygons', () => {
  const out = join(dir, 'inside.geojson');
  const p = run([fixture, '-o', out, '--keep', 'inside', '--inside-flags']);
  assert.equal(p.status, 0, p.stderr);
  const fc = JSON.parse(readFileSync(out, 'utf8'));
  assert.ok(fc.features.length > 0);
  assert.ok(fc.features.every((f) => f.properties.inside === true));
});

test('--min-angle, --max-area and --max-steiner refine the triangles', () => {
  const out = join(dir, 'refined.geojson');
  const p = run([fixture, '-o', out, '--keep', 'inside', '--min-angle', '30', '--max-area', '1e9',
    '--max-steiner', '100000', '--stats', '--quiet']);
  assert.equal(p.status, 0, p.stderr);
  assert.match(p.stderr, /steinerPoints\s+[1-9]/);
  assert.match(p.stderr, /refineCapped\s+0/);
  const fc = JSON.parse(readFileSync(out, 'utf8'));
  const plain = JSON.parse(readFileSync(join(dir, 'inside.geojson'), 'utf8'));
  assert.ok(fc.features.length > plain.features.length);
  const bad = run([fixture, '--min-angle', '75']);
  assert.equal(bad.status, 1);
  assert.match(bad.stderr, /minAngle must be a number of degrees/);
});

test('usage errors exit 2, bad input exits 1, both with a message', () => {
  let p = run([]);
  assert.equal(p.status, 2);
  assert.match(p.stderr, /no input file/);
  p = run([fixture, '--keep', 'outside']);
  assert.equal(p.status, 2);
  assert.match(p.stderr, /--keep must be all or inside/);
  p = run([fixture, '--frobnicate']);
  assert.equal(p.status, 2);
  assert.match(p.stderr, /unknown option --frobnicate/);
  p = run([join(dir, 'missing.geojson')]);
  assert.equal(p.status, 1);
  assert.match(p.stderr, /ENOENT/);
  p = run(['-'], '{"type": "FeatureCollection", "features": [');
  assert.equal(p.status, 1);
  assert.match(p.stderr, /- is not valid JSON/);
  p = run(['-'], '{"type": "Point", "coordinates": [1, "x"]}');
  assert.equal(p.status, 1);
  assert.match(p.stderr, /geometry.coordinates\[1\] must be a number/);
});

test('--help and --version', () => {
  assert.match(run(['--help']).stdout, /Usage: geocdt/);
  const pkg = new URL('../../package.json', import.meta.url);
  const version = JSON.parse(readFileSync(pkg, 'utf8')).version;
  assert.equal(run(['--version']).stdout.trim(), version);
});

test('geocdt voronoi writes voronoiGeoJSON()\'s cells', () => {
  const geojson = JSON.parse(readFileSync(fixture, 'utf8'));
  geojson.features.push({ type: 'Feature', id: 'p', properties: { name: 'site' },
    geometry: { type: 'MultiPoint', coordinates: [[1, 1], [2, 3], [0.5, 2]] } });
  const input = join(dir, 'sites.geojson');
  writeFileSync(input, JSON.stringify(geojson));
  const out = join(dir, 'cells.geojson');
  const p = run(['voronoi', input, '-o', out, '--clip', 'hull', '--lloyd', '2', '--stats']);
  assert.equal(p.status, 0, p.stderr);
  assert.match(p.stderr, /lloydIterations +2/);
  const expected = cellsToGeoJSON(voronoiGeoJSON(geojson,
    { clip: 'hull', lloyd: { iterations: 2 }, output: 'arrays' }));
  assert.deepEqual(JSON.parse(readFileSync(out, 'utf8')), JSON.parse(JSON.stringify(expected)));
  const bad = run(['voronoi', input, '--clip', '1,2,3']);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /--clip must be rings, hull or xmin,ymin,xmax,ymax/);
  const refused = run(['voronoi', input, '--clip', '1,1,0,0']);
  assert.equal(refused.status, 1);
  assert.match(refused.stderr, /xmin < xmax/);
});

test('on a terminal, progress is one bar redrawn in place', () => {
  const written = [];
  const display = new ProgressDisplay({ write: (s) => written.push(s) }, true);
  display.update('triangulating: points', 0);
  display.update('triangulating: points', 0.004);  // the same bar: not drawn again
  display.update('triangulating: points', 0.5);
  display.update('writing', 1);
  display.line('done in 1.00 s');
  assert.equal(written.length, 5, JSON.stringify(written));
  assert.ok(written.slice(0, 3).every((s) => s.startsWith('\r') && s.endsWith('\x1b[K')));
  assert.match(written[1], /triangulating: points +\[#{15}-{15}\] 50%/);
  assert.match(written[2], /writing +\[#{30}\] 100%/);
  assert.equal(written[3], '\r\x1b[K', 'the bar is cleared before a message');
  assert.equal(written[4], 'geocdt: done in 1.00 s\n');
});

test('elsewhere, a line when a step starts and at each quarter', () => {
  const written = [];
  const display = new ProgressDisplay({ write: (s) => written.push(s) }, false);
  for (const f of [0, 0.1, 0.26, 0.3, 0.74, 0.75, 1]) display.update('writing', f);
  display.update('done', 1);
  // 0.3 is in the quarter 0.26 entered; 0.74 enters the third, 0.75 the fourth.
  assert.deepEqual(written, ['geocdt: writing 0%\n', 'geocdt: writing 26%\n',
    'geocdt: writing 74%\n', 'geocdt: writing 75%\n', 'geocdt: writing 100%\n',
    'geocdt: done 100%\n']);
});
