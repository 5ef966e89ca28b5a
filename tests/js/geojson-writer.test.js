// The CLI's GeoJSON writer: the exact text of meshToGeoJSON()'s FeatureCollection with each
// feature as JSON.stringify() writes it, one a line, whatever crosses its chunks' bounds.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { once } from 'node:events';
import { Writable } from 'node:stream';
import { init, meshToGeoJSON, triangulate, triangulateGeoJSON } from 'geocdt';
import { writeGeoJSON } from '../../web/geojson-writer.js';
import { uniform } from './support/inputs.js';

before(() => init());

// The writer's text, through a stream that asks it to wait for 'drain' every 64 KB.
async function written(mesh) {
  const chunks = [];
  const stream = new Writable({
    highWaterMark: 1 << 16,
    write(chunk, _encoding, done) {
      chunks.push(Buffer.from(chunk));
      setImmediate(done);
    },
  });
  const reports = [];
  await writeGeoJSON(mesh, stream, (done, total) => reports.push([done, total]));
  stream.end();
  await once(stream, 'finish');
  const count = mesh.triangles.length / 3;
  assert.deepEqual(reports.at(-1), [count, count], 'the last report: every triangle');
  return Buffer.concat(chunks).toString('utf8');
}

function expected(collection) {
  return '{"type":"FeatureCollection","features":[\n'
    + collection.features.map((f) => JSON.stringify(f)).join(',\n') + '\n]}\n';
}

test('a mesh of triangulate(): ids are the triangles, properties its flags and regions',
  async () => {
    const square = [0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8, 0.2, 0.2];
    const mesh = triangulate({ points: uniform(20_000, 3), polylines: [square],
      polygons: [0, 1] }, { insideFlags: true });
    const text = await written(mesh);
    assert.ok(text.length > 3 << 20, `${text.length} bytes: several chunks`);
    assert.equal(text, expected(meshToGeoJSON(mesh)));
  });

test('triangulateGeoJSON()\'s mesh: the features\' ids and properties, heights, UTF-8',
  async () => {
    const ring = (x, y, r) => [[x - r, y - r], [x + r, y - r], [x + r, y + r, 7.5],
      [x - r, y + r], [x - r, y - r]];
    const big = { name: 'x'.repeat(1_500_000) };  // one head longer than a chunk
    const geojson = { type: 'FeatureCollection', features: [
      { type: 'Feature', id: 'Côte', properties: { name: 'Côte d’Ivoire', 国: 1 },
        geometry: { type: 'Polygon', coordinates: [ring(0, 0, 1)] } },
      { type: 'Feature', properties: null,
        geometry: { type: 'Polygon', coordinates: [ring(3, 0, 1)] } },
      { type: 'Feature', id: 42, properties: big,
        geometry: { type: 'Polygon', coordinates: [ring(6, 0, 1)] } },
      { type: 'Feature', properties: {},
        geometry: { type: 'MultiPoint', coordinates: [[1, 5], [-2, -4], [9, 3]] } },
    ] };
    for (const options of [{}, { insideFlags: true }, { keep: 'inside' }]) {
      const mesh = triangulateGeoJSON(geojson, { ...options, output: 'arrays' });
      if (options.insideFlags !== true) delete mesh.inside;  // as the GeoJSON output does
      assert.equal(await written(mesh), expected(triangulateGeoJSON(geojson, options)),
        JSON.stringify(options));
    }
  });
