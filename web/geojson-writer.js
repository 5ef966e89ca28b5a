// A mesh written as GeoJSON text to a Node stream: the FeatureCollection of meshToGeoJSON(), as
// JSON.stringify() would write it, one feature a line, without making its objects or a string
// a feature. Each vertex's position becomes text once (a vertex is in about six triangles), and
// each distinct head of a feature (its id and properties) once; the features are then copied
// together byte by byte into chunks that go to the stream. Making strings instead (a template a
// feature, joined by the thousands) spent half of the CLI's time collecting them.
import { once } from 'node:events';
import { triangleFields } from './geojson.js';

const kChunkBytes = 1 << 20;
const ascii = (text) => Buffer.from(text, 'latin1');
const kHeadStart = '{"type":"Feature",'.length;
const kRingStart = ascii('"geometry":{"type":"Polygon","coordinates":[[');
// Bytes a feature writes besides its head, ring and positions: ',\n' before it, three
// commas between positions and, without regions, '"id":' with up to ten digits and a comma.
const kFeatureExtra = 32;
const kFeatureEnd = ascii(']]}}');

// A native copy costs a view's allocation: past about 24 bytes (a position, a head) it pays
// (bench/EXPERIMENTS.md, G6).
function copyBytes(into, at, from, start, end) {
  if (end - start > 24) {
    into.set(from.subarray(start, end), at);
    return at + end - start;
  }
  for (let i = start; i < end; i++) into[at++] = from[i];
  return at;
}

// Every vertex's position as text in one buffer, as JSON.stringify() writes position(v) of
// triangleFields(): vertex v is bytes at[v] .. at[v + 1].
function positionTexts(mesh, position) {
  const count = mesh.points.length / 2;
  const at = new Uint32Array(count + 1);
  let bytes = Buffer.allocUnsafe(Math.max(64, 48 * count));
  let used = 0;
  for (let v = 0; v < count; v++) {
    const text = JSON.stringify(position(v));
    if (used + text.length > bytes.length) {
      const size = Math.max(used + text.length, Math.floor(1.5 * bytes.length));
      const bigger = Buffer.allocUnsafe(size);
      bytes.copy(bigger, 0, 0, used);
      bytes = bigger;
    }
    at[v] = used;
    used += bytes.latin1Write(text, used);
  }
  at[count] = used;
  return { bytes, at };
}

// writeGeoJSON(mesh, stream, progress): progress(done, total) hears how many triangles are out.
export async function writeGeoJSON(mesh, stream, progress) {
  const { triangles, regionFeatures } = mesh;
  const count = triangles.length / 3;
  const fields = triangleFields(mesh);
  const { bytes: positions, at } = positionTexts(mesh, fields.position);
  // A feature's text up to its geometry, by key: with the regions' features its id and
  // properties are the region's. Without, the id is the triangle's index, written each time
  // between the head's two parts.
  const byRegion = regionFeatures !== undefined;
  const heads = new Map();
  const headOf = (t) => {
    const key = fields.key(t);
    let head = heads.get(key);
    if (head === undefined) {
      const id = byRegion ? fields.id(t) : undefined;
      const properties = JSON.stringify(fields.properties(t));
      const idText = id === undefined ? '' : `"id":${JSON.stringify(id)},`;
      head = Buffer.from(`{"type":"Feature",${idText}"properties":${properties},`, 'utf8');
      heads.set(key, head);
    }
    return head;
  };
  const write = async (chunk) => {
    if (!stream.write(chunk)) await once(stream, 'drain');
  };
  await write('{"type":"FeatureCollection","features":[');
  let chunk = Buffer.allocUnsafe(kChunkBytes);
  let used = 0;
  for (let t = 0; t < count; t++) {
    const head = headOf(t);
    const a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
    const need = head.length + kFeatureExtra + kRingStart.length + kFeatureEnd.length
      + 2 * (at[a + 1] - at[a]) + (at[b + 1] - at[b]) + (at[c + 1] - at[c]);
    if (used + need > chunk.length) {
      await write(chunk.subarray(0, used));
      chunk = Buffer.allocUnsafe(Math.max(kChunkBytes, need));
      used = 0;
    }
    if (t > 0) chunk[used++] = 44;  // ',' between features, each on a line of its own
    chunk[used++] = 10;
    if (byRegion) {
      used = copyBytes(chunk, used, head, 0, head.length);
    } else {
      used = copyBytes(chunk, used, head, 0, kHeadStart);
      used += chunk.latin1Write(`"id":${t},`, used);
      used = copyBytes(chunk, used, head, kHeadStart, head.length);
    }
    used = copyBytes(chunk, used, kRingStart, 0, kRingStart.length);
    used = copyBytes(chunk, used, positions, at[a], at[a + 1]);
    chunk[used++] = 44;
    used = copyBytes(chunk, used, positions, at[b], at[b + 1]);
    chunk[used++] = 44;
    used = copyBytes(chunk, used, positions, at[c], at[c + 1]);
    chunk[used++] = 44;
    used = copyBytes(chunk, used, positions, at[a], at[a + 1]);
    used = copyBytes(chunk, used, kFeatureEnd, 0, kFeatureEnd.length);
    if ((t + 1) % 20_000 === 0) progress(t + 1, count);
  }
  await write(chunk.subarray(0, used));
  progress(count, count);
  await write('\n]}\n');
}
