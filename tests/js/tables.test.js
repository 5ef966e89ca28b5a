// The tables C++ and JS share have one source, the module (bindings/names.h and
// bindings/output.cpp register them): this test fails when the types, the docs, the tests'
// own lists or the JS constants drift from what the module says.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import createGeocdtModule from '../../web/dist/geocdt.mjs';
import { init, triangulate, Triangulation, voronoi } from 'geocdt';
import { MAX_COORDINATE } from '../../web/input.js';
import { OPTION_NAMES } from '../../web/call-options.js';
import { PHASES } from './support/progress.js';

const read = (path) => readFileSync(new URL(path, import.meta.url), 'utf8');
// The declarations of the package's main entry: index.d.ts and the files it exports.
const indexTypes = read('../../web/index.d.ts');
const exported = [...indexTypes.matchAll(/^export \* from '\.\/(.+)\.js';$/gm)].map((m) => m[1]);
const typesText = [indexTypes, ...exported.map((name) => read(`../../web/${name}.d.ts`))]
  .join('\n');
// The declarations without their comments, which may hold any character.
const types = typesText.replace(/\/\*[\s\S]*?\*\//g, '').replace(/\/\/.*$/gm, '');
const api = read('../../web/API.md');

let wasm;
before(async () => {
  await init();
  wasm = await createGeocdtModule(
    { wasmBinary: readFileSync(new URL('../../web/dist/geocdt.wasm', import.meta.url)) });
});

// An embind enum's names by value; the values must run 0, 1, 2, ... without a gap.
function names(embindEnum) {
  const entries = Object.entries(embindEnum).filter(([name]) => name !== 'values');
  const byValue = [];
  for (const [name, v] of entries) byValue[v.value] = name;
  assert.equal(byValue.length, entries.length, 'values numbered 0, 1, 2, ...');
  assert.ok(!byValue.includes(undefined), 'no gap in the values');
  return byValue;
}

// The string literals of `export type Name = 'a' | 'b' ...;` in web/*.d.ts.
function union(name) {
  const match = types.match(new RegExp(`export type ${name} =([^;]*);`));
  assert.ok(match, `web/*.d.ts declare type ${name}`);
  return [...match[1].matchAll(/'(\w+)'/g)].map((m) => m[1]);
}

// The members of `export interface Name { ... }` in web/*.d.ts.
function members(name) {
  const match = types.match(new RegExp(`export interface ${name}\\b[^{]*\\{([^}]*)\\}`));
  assert.ok(match, `web/*.d.ts declare interface ${name}`);
  return [...match[1].matchAll(/^\s*(\w+)\??:/gm)].map((m) => m[1]);
}

// Every member of `export interface Name`, merged over its declarations, with those of the
// interfaces it extends; nested braces and parentheses (inline types) are not members.
function allMembers(name, text = types) {
  const found = [];
  for (const m of text.matchAll(new RegExp(`export interface ${name}\\b([^{]*)\\{`, 'g'))) {
    let depth = 1;
    let end = m.index + m[0].length;
    for (; depth > 0; end++) depth += { '{': 1, '}': -1 }[text[end]] ?? 0;
    let body = text.slice(m.index + m[0].length, end - 1);
    for (let before = ''; before !== body;) {
      before = body;
      body = body.replace(/\{[^{}]*\}|\([^()]*\)/g, '');
    }
    found.push(...[...body.matchAll(/^\s*(\w+)\??:/gm)].map((x) => x[1]));
    const base = m[1].match(/extends ([\w\s,]+)/);
    if (base) for (const b of base[1].split(',')) found.push(...allMembers(b.trim(), text));
  }
  assert.ok(found.length > 0, `web/*.d.ts declare interface ${name}`);
  return [...new Set(found)];
}

// The option names a call's declarations take, over all its overloads: the members of the
// options parameter's type (the interfaces named in it, and inline objects).
function declaredOptions(declaration, text = types) {
  const names = new Set();
  for (const m of text.matchAll(new RegExp(`${declaration}\\(([^)]*)\\)`, 'g'))) {
    const type = m[1].match(/options\??: ([^]*?),?\s*$/)?.[1];
    if (type === undefined) continue;
    for (const object of type.matchAll(/\{([^}]*)\}/g)) {
      for (const x of object[1].matchAll(/(\w+)\??:/g)) names.add(x[1]);
    }
    for (const x of type.replace(/\{[^}]*\}/g, '').matchAll(/\b([A-Z]\w*Options)\b/g)) {
      for (const member of allMembers(x[1], text)) names.add(member);
    }
  }
  assert.ok(names.size > 0, `web/*.d.ts declare ${declaration}() with options`);
  return [...names];
}

const sorted = (list) => [...list].sort();

test('status codes: every failure the core reports is a documented error code', () => {
  const codes = names(wasm.StatusCode);
  assert.equal(codes[0], 'Ok');
  const documented = union('GeocdtErrorCode');
  // No longer returned (tangles are snap-rounded); kept so that the codes after it keep their
  // numbers, and named in web/API.md's history.
  const retired = ['ConstraintUnresolved'];
  for (const code of codes.slice(1)) {
    const inputMistake = code === 'InvalidArgument' || code === 'InvalidCoordinate';
    if (retired.includes(code)) {
      assert.ok(!documented.includes(code), `${code} is no longer in GeocdtErrorCode`);
    } else if (!inputMistake) {
      assert.ok(documented.includes(code), `${code} in GeocdtErrorCode`);
    }
    assert.ok(api.includes(`'${code}'`), `web/API.md names ${code}`);
  }
  for (const code of documented) assert.ok(api.includes(`'${code}'`), `web/API.md names ${code}`);
});

test('location kinds, keep, fill rules and phases', () => {
  // 'invalid' (a NaN or infinite coordinate) never reaches JS: locate() throws a RangeError.
  const kinds = names(wasm.LocationKind);
  assert.ok(kinds.includes('invalid'));
  assert.deepEqual(sorted(kinds.filter((k) => k !== 'invalid')), sorted(union('LocationKind')));
  assert.deepEqual(sorted(names(wasm.Keep)), sorted(union('Keep')));
  assert.deepEqual(sorted(names(wasm.FillRule)), sorted(union('FillRule')));
  assert.deepEqual(names(wasm.Phase), union('ProgressPhase'));
  assert.deepEqual(names(wasm.Phase), PHASES);
  assert.deepEqual(sorted(names(wasm.Interpolation)), sorted(union('Interpolation')));
  // voronoi()'s clips: 'rings' and 'hull' by name, a box as its four numbers.
  assert.deepEqual(names(wasm.VoronoiClip), ['rings', 'hull', 'box']);
  assert.deepEqual(union('VoronoiClip'), ['rings', 'hull']);
  for (const phase of PHASES) assert.ok(api.includes(`'${phase}'`), `web/API.md names ${phase}`);
  const t = new Triangulation();
  assert.equal(t.locate(0, 0).kind, names(wasm.LocationKind)[0]);
  t.dispose();
});

test('output fields: the module\'s arrays are the result\'s, typed and documented', () => {
  const fields = wasm.fieldNames();
  const elementTypes = names(wasm.ElementType);
  // Every optional array asked for: inside flags, region labels (polygons), values, Steiner
  // records (refine) and segment sources.
  const r = triangulate({
    points: [0, 0, 1, 0, 0, 1], polylines: [[0, 0, 1, 1]], polygons: [0, 1],
    values: [1, 2, 3, 4, 5],
  }, { insideFlags: true, refine: { minAngle: 0 }, segmentSources: true });
  // Not in results: the incremental insertions' and rasterize()'s return values; voronoi()'s
  // (checked below).
  const cellFields = ['coords', 'ringOffsets', 'polygonOffsets', 'siteOffsets', 'sites'];
  const returned = ['vertexIds', 'raster', ...cellFields];
  const documented = [...members('Mesh'), ...members('TriangulateResult')];
  for (const field of fields) {
    if (returned.includes(field)) continue;
    const Type = globalThis[`${elementTypes[wasm.elementType(fields.indexOf(field)).value]}Array`];
    assert.ok(r[field] instanceof Type, `${field} is a ${Type.name}`);
    assert.ok(documented.includes(field), `web/*.d.ts document ${field}`);
    assert.ok(api.includes(`| \`${field}\` | ${Type.name} |`), `web/API.md's table has ${field}`);
  }
  assert.deepEqual(sorted(Object.keys(r).filter((k) => k !== 'stats')),
    sorted(fields.filter((f) => !returned.includes(f))));
  // voronoi()'s arrays, the moved sites coming back as `points`.
  const cells = voronoi({ points: [0, 0, 1, 0, 0, 1] }, { clip: 'hull', lloyd: true });
  const cellsDocumented = members('VoronoiCells');
  for (const field of cellFields) {
    const Type = globalThis[`${elementTypes[wasm.elementType(fields.indexOf(field)).value]}Array`];
    const name = field === 'sites' ? 'points' : field;
    assert.ok(cells[name] instanceof Type, `${name} is a ${Type.name}`);
    assert.ok(cellsDocumented.includes(name), `web/*.d.ts document ${name}`);
    assert.ok(api.includes(`| \`${name}\` | ${Type.name} |`), `web/API.md's table has ${name}`);
  }
  assert.deepEqual(sorted(Object.keys(cells.stats)), sorted(members('VoronoiStats')));
  for (const stat of Object.keys(cells.stats)) {
    assert.ok(api.includes(`\`${stat}\``), `web/API.md names ${stat}`);
  }
});

test('statistics: the module\'s counters are the documented ones', () => {
  const core = Object.keys(new wasm.Output().stats());
  assert.deepEqual(sorted(core), sorted(members('CoreStats')));
  const t = new Triangulation();
  assert.deepEqual(sorted(Object.keys(t.stats)), sorted(core));
  t.dispose();
  const all = Object.keys(triangulate({ points: [0, 0, 1, 0, 0, 1] }).stats);
  assert.deepEqual(sorted(all), sorted([...core, ...members('Stats')]));
  for (const stat of all) assert.ok(api.includes(`| \`${stat}\` |`), `web/API.md lists ${stat}`);
});

test('option names: what each call accepts is what its declarations say', () => {
  const workerTypes = read('../../web/worker.d.ts').replace(/\/\*[\s\S]*?\*\//g, '')
    .replace(/\/\/.*$/gm, '');
  const declared = {
    'init()': declaredOptions('function init'),
    'createWorker()': declaredOptions('function createWorker', workerTypes),
    'triangulate()': declaredOptions('function triangulate'),
    'triangulateGeoJSON()': declaredOptions('function triangulateGeoJSON'),
    'triangulatePolygons()': declaredOptions('function triangulatePolygons'),
    'triangulateRaster()': declaredOptions('function triangulateRaster'),
    'voronoi()': declaredOptions('function voronoi'),
    'voronoiGeoJSON()': declaredOptions('function voronoiGeoJSON'),
    'new Triangulation()': declaredOptions('constructor'),
    'insertPoints()': declaredOptions('insertPoints'),
    'insertPolyline()': declaredOptions('insertPolyline'),
    'interpolate()': declaredOptions('interpolate'),
    'rasterize()': declaredOptions('rasterize'),
    'refine()': declaredOptions('refine'),
    'results()': declaredOptions('results'),
    'options.refine': allMembers('RefineOptions'),
    'options.lloyd': allMembers('LloydOptions'),
  };
  assert.deepEqual(sorted(Object.keys(OPTION_NAMES)), sorted(Object.keys(declared)));
  for (const [call, names] of Object.entries(declared)) {
    assert.deepEqual(sorted(OPTION_NAMES[call]), sorted(names), call);
  }
});

test('the coordinate bound', () => {
  assert.equal(MAX_COORDINATE, wasm.maxCoordinate);
  assert.ok(api.includes('1e150') && typesText.includes('1e150'));
});
