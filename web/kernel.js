// The only code that talks to the wasm module. Input is copied into the heap once, the core
// runs, and each output array is copied out with one slice of a heap view: callers get plain
// typed arrays they own, and no heap view outlives the call (memory growth would detach it).
import { outOfMemoryError, statusError } from './errors.js';

// Same order as geocdt::wasm::Field in bindings/output.h.
const FIELD = {
  points: 0, triangles: 1, halfedges: 2, constrained: 3, constraintEdges: 4,
  sourceOffsets: 5, sources: 6, inside: 7, inputToVertex: 8, vertexIds: 9,
};
// Same order as Output::stat in bindings/output.cpp.
const STAT_NAMES = ['inserted', 'duplicates', 'walkSteps', 'locates', 'flips', 'walkFallbacks',
  'gridSize', 'crossings', 'polylines', 'segments'];
const now = () => globalThis.performance?.now() ?? Date.now();
const LOCATION_KINDS = ['empty', 'outside', 'face', 'edge', 'vertex'];
const VERTICES_PER_KIND = [0, 2, 3, 2, 1];

export class Kernel {
  constructor(wasm) {
    this.wasm = wasm;
    this.output = new wasm.Output();
    this.scratch = this.alloc(5 * 8);
  }

  // A byte address in the heap; pointers past 2 GB come back negative from the export.
  alloc(bytes) {
    if (bytes >= 2 ** 32) throw outOfMemoryError(`the input alone needs ${bytes} bytes`);
    const address = this.wasm._malloc(Math.max(bytes, 8)) >>> 0;
    if (address === 0) throw outOfMemoryError(`cannot reserve ${bytes} bytes for the input`);
    return address;
  }

  free(address) {
    this.wasm._free(address);
  }

  memory() {
    return {
      heapBytes: this.wasm.HEAPU8.length,
      allocatedBytes: this.wasm.allocatedBytes(),
      peakBytes: this.wasm.peakBytes(),
    };
  }

  // Copies coordinate arrays into one heap block: all coordinates, then one uint32 point
  // count per array. Returns the block's address and where each part starts.
  writeCoordinates(arrays) {
    let doubles = 0;
    for (const a of arrays) doubles += a.length;
    const block = this.alloc(doubles * 8 + arrays.length * 4);
    const f64 = this.wasm.HEAPF64;
    const u32 = this.wasm.HEAPU32;
    let at = block / 8;
    const counts = block + doubles * 8;
    for (let i = 0; i < arrays.length; i++) {
      f64.set(arrays[i], at);
      at += arrays[i].length;
      u32[counts / 4 + i] = arrays[i].length / 2;
    }
    return { block, counts };
  }

  // Throws the pending status of the output as an exception, after freeing its arrays.
  check(ok) {
    if (ok) return;
    const o = this.output;
    const error = statusError(o.code(), o.message(), o.index(), o.segment());
    o.clear();
    throw error;
  }

  read(field, Type) {
    const o = this.output;
    const n = o.size(FIELD[field]);
    if (n === 0) return new Type(0);
    const start = o.data(FIELD[field]) / Type.BYTES_PER_ELEMENT;
    const heap = new Type(this.wasm.HEAPU8.buffer);
    return heap.slice(start, start + n);
  }

  // Without constraints every flag is 0: a fresh zeroed array costs no copy and, until it is
  // written, no memory.
  readConstrained() {
    if (this.output.size(FIELD.constraintEdges) > 0) return this.read('constrained', Uint8Array);
    return new Uint8Array(this.output.size(FIELD.constrained));
  }

  stats() {
    const stats = {};
    for (let i = 0; i < STAT_NAMES.length; i++) stats[STAT_NAMES[i]] = this.output.stat(i);
    return stats;
  }

  // Copies the output's mesh out, then frees it.
  takeMesh(withInputToVertex, withInside) {
    try {
      const mesh = {
        points: this.read('points', Float64Array),
        triangles: this.read('triangles', Uint32Array),
        halfedges: this.read('halfedges', Int32Array),
        constrained: this.readConstrained(),
        inputToVertex: withInputToVertex ? this.read('inputToVertex', Uint32Array) : undefined,
        constraintEdges: this.read('constraintEdges', Uint32Array),
        sourceOffsets: this.read('sourceOffsets', Uint32Array),
        sources: this.read('sources', Uint32Array),
        inside: withInside ? this.read('inside', Uint8Array) : undefined,
        stats: this.stats(),
      };
      if (!withInputToVertex) delete mesh.inputToVertex;
      if (!withInside) delete mesh.inside;
      return mesh;
    } finally {
      this.output.clear();
    }
  }

  // points: checked coordinates; polylines: array of checked coordinates; o: checkOptions().
  triangulate(points, polylines, o) {
    const { block, counts } = this.writeCoordinates([points, ...polylines]);
    let ok;
    const started = now();
    try {
      ok = this.wasm.triangulateInto(this.output, block, points.length / 2,
        block + points.length * 8, counts + 4, polylines.length, o.keep, o.fill, o.insideFlags);
    } finally {
      this.free(block);
    }
    const coreMilliseconds = now() - started;
    this.check(ok);
    const mesh = this.takeMesh(true, o.insideFlags);
    mesh.stats.coreMilliseconds = coreMilliseconds;
    return mesh;
  }

  createIncremental() {
    return new this.wasm.Incremental();
  }

  // Inserts checked coordinates into an Incremental; returns their vertex ids.
  insert(incremental, coordinates, polyline) {
    const { block } = this.writeCoordinates([coordinates]);
    let ok;
    try {
      const count = coordinates.length / 2;
      ok = polyline ? incremental.insertPolyline(this.output, block, count)
        : incremental.insertPoints(this.output, block, count);
    } finally {
      this.free(block);
    }
    this.check(ok);
    try {
      return this.read('vertexIds', Uint32Array);
    } finally {
      this.output.clear();
    }
  }

  mesh(incremental, o) {
    const started = now();
    const ok = incremental.mesh(this.output, o.keep, o.fill, o.insideFlags);
    const coreMilliseconds = now() - started;
    this.check(ok);
    const mesh = this.takeMesh(false, o.insideFlags);
    mesh.stats.coreMilliseconds = coreMilliseconds;
    return mesh;
  }

  incrementalStats(incremental) {
    incremental.stats(this.output);
    const stats = this.stats();
    this.output.clear();
    return stats;
  }

  locate(incremental, x, y) {
    incremental.locate(x, y, this.scratch);
    const slots = this.wasm.HEAPF64.subarray(this.scratch / 8, this.scratch / 8 + 5);
    const kind = slots[0];
    return {
      kind: LOCATION_KINDS[kind],
      triangle: slots[1],
      vertices: Array.from(slots.subarray(2, 2 + VERTICES_PER_KIND[kind])),
    };
  }
}
