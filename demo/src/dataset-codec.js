// The demo's bundled map data: quantized lon/lat polylines, delta- and varint-encoded so
// that Natural Earth 10m plus rivers stays around a megabyte and decodes in milliseconds.
//
// Layout: "GCD1", u32 header byte length, UTF-8 JSON header, then one varint stream.
// The header lists layers { name, role: 'ring' | 'line', scale, translate, lengths }:
// lengths[i] is the point count of line i; lon = q * scale[0] + translate[0] (same for lat).
// In the stream each line starts with its absolute first point, then point-to-point deltas,
// every number zigzag-encoded.

const MAGIC = 'GCD1';

export function encodeDataset(layers) {
  const header = {
    layers: layers.map(({ name, role, scale, translate, lines }) => ({
      name, role, scale, translate, lengths: lines.map((l) => l.length / 2),
    })),
  };
  const bytes = [];
  for (const layer of layers) {
    for (const line of layer.lines) {
      let px = 0;
      let py = 0;
      for (let i = 0; i < line.length; i += 2) {
        pushVarint(bytes, zigzag(line[i] - px));
        pushVarint(bytes, zigzag(line[i + 1] - py));
        px = line[i];
        py = line[i + 1];
      }
    }
  }
  const json = new TextEncoder().encode(JSON.stringify(header));
  const out = new Uint8Array(8 + json.length + bytes.length);
  out.set(new TextEncoder().encode(MAGIC), 0);
  new DataView(out.buffer).setUint32(4, json.length, true);
  out.set(json, 8);
  out.set(bytes, 8 + json.length);
  return out;
}

// Returns [{ name, role, lines: [Float64Array lon0, lat0, ...] }].
export function decodeDataset(buffer) {
  const bytes = new Uint8Array(buffer);
  if (new TextDecoder().decode(bytes.subarray(0, 4)) !== MAGIC) {
    throw new Error('the bundled dataset is corrupt (bad magic number)');
  }
  const headerLength = new DataView(bytes.buffer, bytes.byteOffset).getUint32(4, true);
  const header = JSON.parse(new TextDecoder().decode(bytes.subarray(8, 8 + headerLength)));
  let at = 8 + headerLength;
  const readNumber = () => {
    let value = 0;
    let shift = 0;
    for (;;) {
      if (at >= bytes.length) throw new Error('the bundled dataset is truncated');
      const b = bytes[at++];
      value += (b & 0x7f) * 2 ** shift;
      if (b < 0x80) break;
      shift += 7;
    }
    return value % 2 === 0 ? value / 2 : -(value + 1) / 2;
  };
  return header.layers.map(({ name, role, scale, translate, lengths }) => {
    const lines = lengths.map((n) => {
      const line = new Float64Array(2 * n);
      let qx = 0;
      let qy = 0;
      for (let i = 0; i < 2 * n; i += 2) {
        qx += readNumber();
        qy += readNumber();
        line[i] = qx * scale[0] + translate[0];
        line[i + 1] = qy * scale[1] + translate[1];
      }
      return line;
    });
    return { name, role, lines };
  });
}

function zigzag(v) {
  return v >= 0 ? 2 * v : -2 * v - 1;
}

function pushVarint(bytes, v) {
  if (!Number.isSafeInteger(v)) throw new RangeError(`cannot encode ${v}: not an integer`);
  while (v >= 0x80) {
    bytes.push((v % 0x80) | 0x80);
    v = Math.floor(v / 0x80);
  }
  bytes.push(v);
}
