// The wasm module's side of every call: the heap's views, the binding's Input and Output,
// input written into buffers the binding owns, output arrays sliced out of the heap, the
// output's status thrown as an error, and the options turned into the binding's values. The
// calls themselves are in kernel.js.
import {
  enumNames, fillRuleOption, meshOptions, progressReporter, refineOptions,
} from './call-options.js';
import { GeocdtError, outOfMemoryError, statusError } from './errors.js';
import { describe, isNumericTypedArray, polygonOffsetError, offsetError } from './input.js';

// Copies numbers (x, y pairs, or values) into the heap at element `at` of heap (a
// Float64Array over the memory); the core judges them (a NaN coordinate is refused, a NaN
// value means none). A typed array goes in with one set(); a plain array is checked for
// numbers as it is copied (set() would turn null into 0 and '1' into 1), which once warm
// costs about what set() does (bench/EXPERIMENTS.md, L2).
export function copyNumbers(heap, at, values, name) {
  if (isNumericTypedArray(values)) {
    heap.set(values, at);
    return;
  }
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    if (typeof v !== 'number') {
      throw new TypeError(`geocdt: ${name}[${i}] must be a number, got ${describe(v)}`);
    }
    heap[at + i] = v;
  }
}

export function copyOffsets(heap, at, offsets, name) {
  if (isNumericTypedArray(offsets)) {
    heap.set(offsets, at);
    return;
  }
  for (let i = 0; i < offsets.length; i++) {
    const v = offsets[i];
    if (!Number.isInteger(v) || v < 0 || v > 0xffffffff) {
      throw new RangeError(
        `geocdt: ${name}[${i}] must be an integer from 0 to 2^32 - 1, got ${v}`);
    }
    heap[at + i] = v;
  }
}

export class KernelHeap {
  // threads: what the core may use for a large batch of points (1 in the single-threaded
  // build).
  constructor(wasm, threads = 1) {
    this.wasm = wasm;
    this.threads = threads;
    this.output = new wasm.Output();
    this.outputAddress = this.output.objectAddress();
    this.input = new wasm.Input();
    this.scratch = this.alloc(6 * 8);
    this.busy = false;
    this.statusCodes = enumNames(wasm.StatusCode);
    this.locationKinds = enumNames(wasm.LocationKind);
    this.phases = enumNames(wasm.Phase);
    this.interpolation = wasm.Interpolation;
    this.keep = wasm.Keep;
    this.fillRule = wasm.FillRule;
    this.voronoiClip = wasm.VoronoiClip;
    const types = enumNames(wasm.ElementType);
    this.fields = {};
    wasm.fieldNames().forEach((name, id) => {
      this.fields[name] = { id, Type: globalThis[`${types[wasm.elementType(id).value]}Array`] };
    });
  }

  // The memory's current views. In the threaded build a pool thread can grow the memory, and
  // the glue renews its views only on a thread that grows it: look at the memory itself.
  heap() {
    const memory = this.wasm.wasmMemory;
    if (memory !== undefined && this.wasm.HEAPU8.buffer !== memory.buffer) {
      this.wasm.HEAPU8 = new Uint8Array(memory.buffer);
      this.wasm.HEAPU32 = new Uint32Array(memory.buffer);
      this.wasm.HEAPF64 = new Float64Array(memory.buffer);
    }
    return this.wasm;
  }

  // A byte address in the heap; pointers past 2 GB come back negative from the export.
  alloc(bytes) {
    const address = this.wasm._malloc(Math.max(bytes, 8)) >>> 0;
    if (address === 0) throw outOfMemoryError(`cannot reserve ${bytes} bytes`);
    return address;
  }

  memory() {
    return {
      heapBytes: this.heap().HEAPU8.length,
      allocatedBytes: this.wasm.allocatedBytes(),
      peakBytes: this.wasm.peakBytes(),
    };
  }

  // A call into the core that may call back into JS (onProgress): a call made from there
  // would find the binding's buffers in use.
  enter() {
    this.idle();
    this.busy = true;
  }

  idle() {
    if (this.busy) {
      throw new GeocdtError('Busy', 'geocdt: called from inside an onProgress callback; '
        + 'wait for the running call to return');
    }
  }

  leave() {
    this.busy = false;
  }

  // Writes { points, lines, polygons, values } (from checkInput) into the binding's Input.
  // polylineCount: what the polygons may index (this call's polylines, or a Triangulation's);
  // polygonsName: where the polygons were given, for errors; valuesName: the values'.
  writeInput({ points, lines, polygons, values }, polylineCount = lines.count,
    polygonsName = 'polygons', valuesName = 'values', linesName = 'polylines') {
    const input = this.input;
    const polygonCount = polygons === undefined ? -1 : polygons.length - 1;
    const valueCount = values === undefined ? 0 : values.length;
    if (!input.resize(points.length / 2, lines.points, lines.count, polygonCount, valueCount)) {
      const bytes = 8 * (points.length + 2 * lines.points + valueCount)
        + 4 * (lines.count + 1 + polygonCount + 1);
      throw outOfMemoryError(`the input alone needs ${bytes} bytes`);
    }
    const { HEAPF64: f64, HEAPU32: u32 } = this.heap();
    copyNumbers(f64, input.pointsAddress() / 8, points, 'points');
    if (polygons !== undefined) {
      copyOffsets(u32, input.polygonOffsetsAddress() / 4, polygons, polygonsName);
      const bad = input.badPolygonOffset(polylineCount);
      if (bad >= 0) throw polygonOffsetError(polygons, bad, polylineCount, polygonsName);
    }
    if (values !== undefined) copyNumbers(f64, input.valuesAddress() / 8, values, valuesName);
    if (lines.count === 0 && lines.points === 0) return;
    let at = input.lineCoordsAddress() / 8;
    const offsets = input.lineOffsetsAddress() / 4;
    if (lines.arrays === undefined) {
      copyNumbers(f64, at, lines.coords, `${linesName}.coords`);
      copyOffsets(u32, offsets, lines.offsets, `${linesName}.offsets`);
      const bad = input.badOffset();
      if (bad >= 0) throw offsetError(lines, bad, linesName);
      return;
    }
    u32[offsets] = 0;
    for (let i = 0; i < lines.arrays.length; i++) {
      const line = lines.arrays[i];
      copyNumbers(f64, at, line, `${linesName}[${i}]`);
      at += line.length;
      u32[offsets + i + 1] = u32[offsets + i] + line.length / 2;
    }
  }

  // Throws the pending status of the output as an exception, after freeing its arrays.
  // coordinate(polyline, point) names a bad input coordinate (polyline -1: the points).
  check(ok, coordinate) {
    if (ok) return;
    const o = this.output;
    const code = this.statusCodes[o.code().value];
    const index = o.index(), segment = o.segment();
    // The core names the point (index) or the polyline (index) and its point (segment); the
    // caller's own array then gives the axis and the value.
    const precise = code === 'InvalidCoordinate'
      && coordinate(segment < 0 ? -1 : index, segment < 0 ? index : segment);
    const message = o.message();
    o.clear();
    if (!precise) throw statusError(code, message, index, segment);
    precise.code = code;
    if (index >= 0) precise.index = index;
    if (segment >= 0) precise.segment = segment;
    throw precise;
  }

  read(name) {
    const { id, Type } = this.fields[name];
    const o = this.output;
    const n = o.size(id);
    if (n === 0) return new Type(0);
    const start = o.data(id) / Type.BYTES_PER_ELEMENT;
    return new Type(this.heap().HEAPU8.buffer).slice(start, start + n);
  }

  // Without constraints every flag is 0: a fresh zeroed array costs no copy and, until it is
  // written, no memory.
  readConstrained() {
    const { id } = this.fields.constrained;
    if (this.output.size(this.fields.constraintEdges.id) > 0) return this.read('constrained');
    return new Uint8Array(this.output.size(id));
  }

  // The arrays every mesh has: points, triangles, halfedges, constrained.
  readTriangles() {
    return {
      points: this.read('points'),
      triangles: this.read('triangles'),
      halfedges: this.read('halfedges'),
      constrained: this.readConstrained(),
    };
  }

  // Copies the output's mesh out, then frees it; the flags say which optional arrays to take
  // (the Steiner records come whenever there are any, or refinement was asked for).
  takeMesh({ inputToVertex, inside, regions, values, steiner, segmentSources, vertexIds }) {
    try {
      const mesh = this.readTriangles();
      if (inputToVertex) mesh.inputToVertex = this.read('inputToVertex');
      if (vertexIds) mesh.vertexIds = this.read('vertexIds');
      mesh.constraintEdges = this.read('constraintEdges');
      mesh.sourceOffsets = this.read('sourceOffsets');
      mesh.sources = this.read('sources');
      if (segmentSources) {
        mesh.segmentOffsets = this.read('segmentOffsets');
        mesh.segmentSources = this.read('segmentSources');
      }
      if (inside) mesh.inside = this.read('inside');
      if (regions) mesh.regions = this.read('regions');
      if (values) mesh.values = this.read('values');
      if (steiner || this.output.size(this.fields.steiner.id) > 0) {
        mesh.steiner = this.read('steiner');
        mesh.steinerParents = this.read('steinerParents');
        mesh.steinerWeights = this.read('steinerWeights');
      }
      mesh.stats = this.output.stats();
      return mesh;
    } finally {
      this.output.clear();
    }
  }

  // The calls' options for the binding, by the module's enums (call-options.js).
  meshOptions(options) {
    return meshOptions(options, { keep: this.keep, fill: this.fillRule });
  }

  fillRuleOption(options) {
    return fillRuleOption(options, this.fillRule);
  }

  refineOptions(refine, name) {
    return refineOptions(refine, name);
  }

  progress(onProgress) {
    return progressReporter(onProgress, this.phases);
  }
}
