// The demo's data path without a browser: the bundled-data codec and the GeoJSON reader.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { buildAllDatasets } from '../../demo/scripts/bundle-data.mjs';
import { decodeDataset, encodeDataset } from '../../demo/src/dataset-codec.js';
import { parseGeoJSONText } from '../../demo/src/geojson-input.js';

test('the dataset codec returns exactly the quantized coordinates it was given', () => {
  const line = [0, 0, 1, -1, 3_600_000, 1_700_000, 3_599_999, 0, 127, 128, -5, 16_384];
  const encoded = encodeDataset([
    {
      name: 'a', role: 'ring', scale: [0.5, 0.25], translate: [-180, -90],
      lines: [line, [7, 7, 7, 8]],
    },
    { name: 'b', role: 'line', scale: [1, 1], translate: [0, 0], lines: [[-3, 4, 5, -6]] },
  ]);
  const [a, b] = decodeDataset(encoded.buffer);
  assert.equal(a.name, 'a');
  assert.equal(a.role, 'ring');
  const lonLat = (q, i) => (i % 2 === 0 ? q * 0.5 - 180 : q * 0.25 - 90);
  assert.deepEqual([...a.lines[0]], line.map(lonLat));
  assert.deepEqual([...a.lines[1]], [7 * 0.5 - 180, 7 * 0.25 - 90, 7 * 0.5 - 180, 8 * 0.25 - 90]);
  assert.deepEqual([...b.lines[0]], [-3, 4, 5, -6]);
  assert.throws(() => decodeDataset(encoded.slice(0, encoded.length - 1).buffer), /truncated/);
});

test('the bundled world datasets hold closed land rings, borders and rivers, in a few MB', () => {
  const files = buildAllDatasets();
  let bytes = 0;
  for (const [name, data] of Object.entries(files)) {
    bytes += data.length;
    const layers = decodeDataset(data.buffer);
    assert.deepEqual(layers.map((l) => [l.name, l.role]),
      [['land', 'ring'], ['borders', 'line'], ['rivers', 'line']]);
    for (const ring of layers[0].lines) {
      const n = ring.length;
      const closed = ring[0] === ring[n - 2] && ring[1] === ring[n - 1];
      assert.ok(n >= 8 && closed, `${name}: an open land ring`);
    }
    for (const layer of layers.slice(1)) {
      assert.ok(layer.lines.length > 100, `${name}: ${layer.name}`);
      for (const line of layer.lines) {
        const n = line.length;
        const closed = line[0] === line[n - 2] && line[1] === line[n - 1];
        assert.ok(n >= 4 && !closed, `${name}: a closed ${layer.name} line`);
      }
    }
    for (const layer of layers) {
      for (const line of layer.lines) {
        for (let i = 0; i < line.length; i += 2) {
          const onGlobe = Math.abs(line[i]) <= 180 && Math.abs(line[i + 1]) <= 90;
          assert.ok(onGlobe, `${name}: off the globe`);
          // Lines crossing the antimeridian were cut there: only the ring around the South
          // Pole still runs from one side of the map to the other, along its bottom edge.
          if (i > 0 && Math.abs(line[i] - line[i - 2]) > 180) {
            assert.ok(layer.role === 'ring' && line[i + 1] < -80,
              `${name}: a ${layer.name} edge across the world at ${line[i + 1]}`);
          }
        }
      }
    }
  }
  assert.ok(bytes < 4e6, `${bytes} bytes of data`);
});

test('GeoJSON is read into points, rings and lines, with clear errors', () => {
  const input = parseGeoJSONText(JSON.stringify({
    type: 'FeatureCollection',
    features: [
      // left open
      { type: 'Feature', geometry: { type: 'Polygon', coordinates: [[[0, 0], [1, 0], [1, 1]]] } },
      // closed
      {
        type: 'Feature',
        geometry: { type: 'LineString', coordinates: [[0, 0], [2, 0], [2, 2], [0, 0]] },
      },
      { type: 'Feature', geometry: null },
      {
        type: 'Feature',
        geometry: {
          type: 'GeometryCollection', geometries: [{ type: 'Point', coordinates: [3, 4] }],
        },
      },
    ],
  }));
  assert.deepEqual(input.points, [3, 4]);
  assert.deepEqual(input.rings.map((r) => [...r]), [[0, 0, 1, 0, 1, 1, 0, 0]]);
  // A closed LineString is cut in two open lines: a constraint, never a ring.
  assert.deepEqual(input.lines.map((l) => [...l]), [[0, 0, 2, 0, 2, 2], [2, 2, 0, 0]]);

  const fails = (text, pattern) => assert.throws(() => parseGeoJSONText(text),
    (e) => e.name === 'InputError' && pattern.test(e.message));
  fails('{"type": "Feature"', /not valid JSON/);
  fails('42', /not a GeoJSON object/);
  fails('{"type": "FeatureCollection", "features": []}', /no coordinates/);
  fails('{"type": "Circle", "coordinates": [0, 0]}', /unknown GeoJSON type "Circle"/);
  fails('{"type": "LineString", "coordinates": [[0, 0]]}', /at least 2 positions/);
  fails('{"type": "Polygon", "coordinates": [[0, 0], [1, 1]]}',
    /Polygon "coordinates" are malformed/);
  fails('{"type": "Point", "coordinates": [0, null]}', /not two finite numbers/);
  fails('{"type": "Point", "coordinates": [2000000, 6000000]}', /not lon\/lat/);
});
