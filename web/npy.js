// Readers for NumPy's .npy arrays and .npz files (a zip archive of .npy arrays), for the CLI's
// rasters (and the tests', benchmarks' and demo's elevation models): little-endian numeric
// arrays in C order; stored or deflated zip entries. Node only (node:zlib inflates).
//   readNpy(bytes) -> { data: TypedArray, shape: [rows, columns, ...] }
//   readNpz(bytes) -> { name: { data, shape }, ... }
import { inflateRawSync } from 'node:zlib';

// NumPy's type codes and the typed arrays that hold them.
const kTypes = {
  '|i1': Int8Array, '|u1': Uint8Array, '<i2': Int16Array, '<u2': Uint16Array,
  '<i4': Int32Array, '<u4': Uint32Array, '<f4': Float32Array, '<f8': Float64Array,
};

// The entries of a zip archive: name -> raw bytes of the member (inflated when deflated).
function unzip(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  // The end-of-central-directory record: its signature, searched from the end (a comment may
  // follow it).
  let end = bytes.length - 22;
  while (end >= 0 && view.getUint32(end, true) !== 0x06054b50) end--;
  if (end < 0) throw new Error('npz: not a zip archive (no end of central directory)');
  const count = view.getUint16(end + 10, true);
  let at = view.getUint32(end + 16, true);
  const entries = {};
  for (let i = 0; i < count; i++) {
    if (view.getUint32(at, true) !== 0x02014b50) throw new Error('npz: broken central directory');
    const method = view.getUint16(at + 10, true);
    const compressed = view.getUint32(at + 20, true);
    const nameLength = view.getUint16(at + 28, true);
    const extraLength = view.getUint16(at + 30, true);
    const commentLength = view.getUint16(at + 32, true);
    const local = view.getUint32(at + 42, true);
    const name = new TextDecoder().decode(bytes.subarray(at + 46, at + 46 + nameLength));
    // The member's data follows its local header, whose name and extra field may differ in
    // length from the central directory's.
    const start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
    const raw = bytes.subarray(start, start + compressed);
    if (method === 0) entries[name] = raw;
    else if (method === 8) entries[name] = inflateRawSync(raw);
    else throw new Error(`npz: ${name} uses zip method ${method} (only stored and deflated)`);
    at += 46 + nameLength + extraLength + commentLength;
  }
  return entries;
}

// One .npy array: its header (a Python dict literal) gives the type, the order and the shape.
export function readNpy(bytes, name = 'the array') {
  if (bytes[0] !== 0x93 || new TextDecoder().decode(bytes.subarray(1, 6)) !== 'NUMPY') {
    throw new Error(`npz: ${name} is not a .npy array`);
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const major = bytes[6];
  const headerLength = major === 1 ? view.getUint16(8, true) : view.getUint32(8, true);
  const headerStart = major === 1 ? 10 : 12;
  const header = new TextDecoder().decode(
    bytes.subarray(headerStart, headerStart + headerLength));
  const descr = /'descr':\s*'([^']+)'/.exec(header)?.[1];
  const fortran = /'fortran_order':\s*True/.test(header);
  const shapeText = /'shape':\s*\(([^)]*)\)/.exec(header)?.[1];
  const Type = kTypes[descr];
  if (Type === undefined) throw new Error(`npz: ${name} has element type ${descr}`);
  if (fortran) throw new Error(`npz: ${name} is in Fortran order`);
  const shape = shapeText.split(',').map((s) => s.trim()).filter((s) => s !== '').map(Number);
  const length = shape.reduce((a, b) => a * b, 1);
  const start = headerStart + headerLength;
  // A copy, aligned for the typed array whatever the member's offset in the archive.
  const data = new Type(length);
  new Uint8Array(data.buffer).set(bytes.subarray(start, start + length * Type.BYTES_PER_ELEMENT));
  return { data, shape };
}

export function readNpz(bytes) {
  const arrays = {};
  for (const [name, member] of Object.entries(unzip(bytes))) {
    arrays[name.replace(/\.npy$/, '')] = readNpy(member, name);
  }
  return arrays;
}
