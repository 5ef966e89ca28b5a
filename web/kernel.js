// The only code that talks to the wasm module, with kernel-heap.js: the calls, each writing
// its input straight into buffers the binding owns (one TypedArray.set() per caller array; the
// core checks the values as it reads them) and taking each output array with one slice of a
// heap view. Callers get plain typed arrays they own, and no heap view outlives the call
// (memory growth would detach it). The names of fields, statistics, status codes, location
// kinds, keep, fill and phases all come from the module (bindings/names.h,
// bindings/output.cpp): no table is kept here.
import { methodOption } from './call-options.js';
import { outOfMemoryError, statusError } from './errors.js';
import { coordinateError, polygonCoordinateError } from './input.js';
import { copyNumbers, copyOffsets, KernelHeap } from './kernel-heap.js';

const now = () => globalThis.performance?.now() ?? Date.now();

// The error for the bad coordinate `point` of the points (polyline < 0) or of a polyline, as
// checkInput() gave them.
function inputCoordinateError(points, lines, polyline, point) {
  if (polyline < 0) return coordinateError(points, 'points', 0, point, '');
  return lines.arrays === undefined
    ? coordinateError(lines.coords, 'polylines.coords', 2 * lines.offsets[polyline], point,
      ` of polyline ${polyline}`)
    : coordinateError(lines.arrays[polyline], `polylines[${polyline}]`, 0, point,
      ` of polyline ${polyline}`);
}

export class Kernel extends KernelHeap {
  // checked: checkInput()'s { points, lines, polygons, values }; o: meshOptions();
  // valuesPerPoint: checkValuesPerPoint()'s; onProgress: a function or undefined; r:
  // refineOptions().
  triangulate(checked, o, valuesPerPoint, onProgress, r = this.refineOptions()) {
    const { points, lines, polygons, values } = checked;
    const progress = this.progress(onProgress);
    this.enter();
    let ok;
    let coreMilliseconds;
    try {
      this.writeInput(checked);
      const started = now();
      ok = this.wasm.triangulateInto(this.output, this.input, o.keep, o.fill, o.insideFlags,
        o.segmentSources, valuesPerPoint, this.threads, progress.callback, r.refine, r.minAngle,
        r.maxArea, r.maxSteinerPoints);
      coreMilliseconds = now() - started;
    } finally {
      this.input.clear();
      this.leave();
    }
    this.check(ok, (polyline, point) => inputCoordinateError(points, lines, polyline, point));
    progress.rethrow();
    const mesh = this.takeMesh({
      inputToVertex: true, inside: o.insideFlags, regions: polygons !== undefined,
      values: values !== undefined, steiner: r.refine, segmentSources: o.segmentSources,
    });
    mesh.stats.coreMilliseconds = coreMilliseconds;
    return mesh;
  }

  // The binding's polygon call, made once: its header (bindings/polygons.h) is where
  // addresses and sizes travel, read as uint32 at this.polygonHeader.
  polygonCall() {
    if (this.polygons === undefined) {
      this.polygons = new this.wasm.PolygonCall();
      this.polygonHeader = this.polygons.header() / 4;
    }
    return this.polygons;
  }

  // A checked batch { coords, ringOffsets, polygonOffsets } (coords: dim numbers a point, x
  // and y first) -> { triangles, extraPoints, triangleOffsets, stats }. names: what the caller
  // calls the three arrays, for errors.
  triangulatePolygons({ coords, ringOffsets, polygonOffsets }, fill, dim, names) {
    const call = this.polygonCall();
    const h = this.polygonHeader;
    this.enter();
    try {
      if (!call.prepare(coords.length, ringOffsets.length - 1, polygonOffsets.length - 1)) {
        const bytes = 8 * coords.length + 4 * (ringOffsets.length + polygonOffsets.length);
        throw outOfMemoryError(`the input alone needs ${bytes} bytes`);
      }
      const f64 = this.heap().HEAPF64;
      let u32 = this.heap().HEAPU32;
      copyNumbers(f64, u32[h] / 8, coords, names.coords);
      copyOffsets(u32, u32[h + 1] / 4, ringOffsets, names.ringOffsets);
      copyOffsets(u32, u32[h + 2] / 4, polygonOffsets, names.polygonOffsets);
      const started = now();
      const ok = call.run(dim, fill, this.threads);
      const coreMilliseconds = now() - started;
      if (!ok) throw this.polygonError(call, coords, dim, ringOffsets, polygonOffsets, names);
      ({ HEAPU32: u32 } = this.heap());
      const { buffer } = u32;
      const stats = call.stats();
      stats.coreMilliseconds = coreMilliseconds;
      return {
        triangles: new Uint32Array(buffer, u32[h + 3], u32[h + 4]).slice(),
        extraPoints: new Float64Array(buffer, u32[h + 5], u32[h + 6]).slice(),
        triangleOffsets: new Uint32Array(buffer, u32[h + 7], u32[h + 8]).slice(),
        stats,
      };
    } finally {
      call.release();
      this.leave();
    }
  }

  // The exception for a failed polygon call: bad offsets and coordinates are RangeErrors that
  // name the polygon and ring (and, for a coordinate, the caller's index of it).
  polygonError(call, coords, dim, ringOffsets, polygonOffsets, names) {
    const code = this.statusCodes[call.code().value];
    const polygon = call.index(), ring = call.segment();
    let error = null;
    if (code === 'InvalidCoordinate' && ring >= 0) {
      error = polygonCoordinateError(coords, dim, names.coords, ringOffsets, ring,
        polygon < 0 ? null : { polygon, ring: ring - polygonOffsets[polygon] });
    }
    if (error === null && (code === 'InvalidArgument' || code === 'InvalidCoordinate')) {
      error = new RangeError(`geocdt: ${call.message()}`);
    }
    if (error === null) return statusError(code, call.message(), polygon, ring);
    error.code = code;
    if (polygon >= 0) error.polygon = polygon;
    if (ring >= 0) error.ring = ring;
    return error;
  }

  // triangulateRaster(): checked is checkHeightmap()'s, r checkRasterOptions()'s.
  triangulateRaster({ heights, width, height }, { options, lines, heights: lineHeights }) {
    this.enter();
    let ok;
    let coreMilliseconds;
    try {
      const name = 'options.breaklines';
      this.writeInput({ points: [], lines, values: lineHeights }, lines.count, 'polygons',
        'options.breaklineHeights', name);
      if (!this.input.resizeRaster(width * height)) {
        throw outOfMemoryError(`the raster alone needs ${8 * width * height} bytes`);
      }
      copyNumbers(this.heap().HEAPF64, this.input.rasterAddress() / 8, heights, 'raster.heights');
      const started = now();
      ok = this.wasm.triangulateRasterInto(this.output, this.input, width, height, options);
      coreMilliseconds = now() - started;
    } finally {
      this.input.clear();
      this.leave();
    }
    this.check(ok, (line, point) => (line < 0 ? null : lines.arrays === undefined
      ? coordinateError(lines.coords, 'options.breaklines.coords', 2 * lines.offsets[line], point,
        ` of breakline ${line}`)
      : coordinateError(lines.arrays[line], `options.breaklines[${line}]`, 0, point,
        ` of breakline ${line}`)));
    try {
      const mesh = {
        ...this.readTriangles(),
        constraintEdges: this.read('constraintEdges'),
        sourceOffsets: this.read('sourceOffsets'),
        sources: this.read('sources'),
        values: this.read('values'),
      };
      mesh.stats = this.output.terrainStats();
      mesh.stats.coreMilliseconds = coreMilliseconds;
      return mesh;
    } finally {
      this.output.clear();
    }
  }

  // checked: checkInput()'s { points, lines }; o: checkVoronoiOptions()'s. Returns the cells in
  // GeoArrow's layout, with the moved sites and the steps taken when o asks for relaxation.
  voronoi(checked, o) {
    const { points, lines } = checked;
    this.enter();
    let ok;
    let coreMilliseconds;
    try {
      this.writeInput({ points, lines });
      const started = now();
      const [xmin, ymin, xmax, ymax] = o.box;
      ok = this.wasm.voronoiInto(this.output, this.input, this.voronoiClip[o.clip], xmin, ymin,
        xmax, ymax, this.fillRule[o.fillRule], this.threads, o.lloydIterations, o.lloydTolerance);
      coreMilliseconds = now() - started;
    } finally {
      this.input.clear();
      this.leave();
    }
    this.check(ok, (polyline, point) => inputCoordinateError(points, lines, polyline, point));
    try {
      const cells = {
        coords: this.read('coords'),
        ringOffsets: this.read('ringOffsets'),
        polygonOffsets: this.read('polygonOffsets'),
        siteOffsets: this.read('siteOffsets'),
      };
      const stats = this.output.voronoiStats();
      if (o.lloydIterations > 0) {
        cells.points = this.read('sites');
        cells.lloyd = { iterations: stats.lloydIterations, movement: stats.lloydMovement };
      }
      cells.stats = {
        domainArea: stats.domainArea,
        crossings: stats.crossings,
        clippedCells: stats.clippedCells,
        threads: stats.threads,
        coreMilliseconds,
      };
      return cells;
    } finally {
      this.output.clear();
    }
  }
  // (Its address goes with it, for the editing calls that bypass embind: removePoint,
  // movePoint.)
  createIncremental(valuesPerPoint) {
    const incremental = new this.wasm.Incremental(valuesPerPoint, this.threads);
    incremental.rawAddress = incremental.objectAddress();
    return incremental;
  }

  // Inserts checked coordinates, with checked values or undefined, into an Incremental;
  // returns their vertex ids.
  insert(incremental, coordinates, polyline, onProgress, values) {
    const name = polyline ? 'polyline' : 'points';
    const progress = this.progress(onProgress);
    this.enter();
    let ok;
    try {
      this.writeInput({ points: coordinates, lines: { count: 0, points: 0 }, values },
        0, 'polygons', 'values');
      ok = polyline ? incremental.insertPolyline(this.output, this.input, progress.callback)
        : incremental.insertPoints(this.output, this.input, progress.callback);
    } finally {
      this.input.clear();
      this.leave();
    }
    this.check(ok, (_, point) => coordinateError(coordinates, name, 0, point, ''));
    progress.rethrow();
    try {
      return this.read('vertexIds');
    } finally {
      this.output.clear();
    }
  }

  // polygons: checked offsets into the triangulation's polylines, or undefined.
  mesh(incremental, o, onProgress, polygons) {
    const progress = this.progress(onProgress);
    this.enter();
    let ok;
    let started;
    try {
      this.writeInput({ points: [], lines: { count: 0, points: 0 }, polygons },
        incremental.polylineCount(), 'options.polygons');
      started = now();
      ok = incremental.mesh(this.output, this.input, o.keep, o.fill, o.insideFlags,
        o.segmentSources, progress.callback);
    } finally {
      this.input.clear();
      this.leave();
    }
    const coreMilliseconds = now() - started;
    this.check(ok, () => null);
    progress.rethrow();
    const mesh = this.takeMesh({
      inside: o.insideFlags, regions: polygons !== undefined, values: incremental.hasValues(),
      segmentSources: o.segmentSources, vertexIds: true,
    });
    mesh.stats.coreMilliseconds = coreMilliseconds;
    return mesh;
  }

  // 'linear' or 'natural' -> the module's enum value.
  method(options) {
    return methodOption(options, this.interpolation);
  }

  // Values at checked query coordinates: valuesPerPoint numbers per query.
  interpolate(incremental, xy, method) {
    this.enter();
    try {
      this.writeInput({ points: xy, lines: { count: 0, points: 0 } });
      incremental.interpolate(this.output, this.input, method);
    } finally {
      this.input.clear();
      this.leave();
    }
    this.check(this.output.code().value === 0, () => null);
    try {
      return this.read('values');
    } finally {
      this.output.clear();
    }
  }

  // A checked raster ({ bbox, width, height }) -> Float32Array.
  rasterize(incremental, { bbox, width, height }, method) {
    this.idle();
    const ok = incremental.rasterize(this.output, bbox[0], bbox[1], bbox[2], bbox[3], width,
      height, method);
    this.check(ok, () => null);
    try {
      return this.read('raster');
    } finally {
      this.output.clear();
    }
  }

  // o: meshOptions() (keep and fill), r: refineOptions().
  refine(incremental, o, r) {
    this.enter();
    let ok;
    try {
      ok = incremental.refine(this.output, o.keep, o.fill, r.minAngle, r.maxArea,
        r.maxSteinerPoints);
    } finally {
      this.leave();
    }
    this.check(ok, () => null);
    this.output.clear();
    return incremental.stats();
  }

  // Editing: the core's refusal of an id or polyline (InvalidArgument) is a RangeError here,
  // as for ids JS checks itself.
  checkEdit(ok) {
    if (ok) return;
    const o = this.output;
    const code = this.statusCodes[o.code().value];
    if (code !== 'InvalidArgument') this.check(false, () => null);
    const error = new RangeError(`geocdt: ${o.message()}`);
    error.code = code;
    if (o.index() >= 0) error.index = o.index();
    o.clear();
    throw error;
  }

  removePoint(incremental, id) {
    this.idle();
    const result = this.wasm._geocdt_remove_point(incremental.rawAddress, this.outputAddress, id);
    this.checkEdit(result >= 0);
    return result === 1;
  }

  // ids: checked integers in [0, 2^32).
  removePoints(incremental, ids) {
    this.enter();
    let removed;
    try {
      if (!this.input.resizeIds(ids.length)) {
        throw outOfMemoryError(`the ids alone need ${4 * ids.length} bytes`);
      }
      if (ids.length > 0) this.heap().HEAPU32.set(ids, this.input.idsAddress() / 4);
      removed = incremental.removePoints(this.output, this.input);
    } finally {
      this.input.clear();
      this.leave();
    }
    this.checkEdit(removed >= 0);
    return removed;
  }

  removePolyline(incremental, k) {
    this.idle();
    this.checkEdit(incremental.removePolyline(this.output, k));
  }

  movePoint(incremental, id, x, y) {
    this.idle();
    this.checkEdit(this.wasm._geocdt_move_point(incremental.rawAddress, this.outputAddress, id, x,
      y) === 1);
  }

  locate(incremental, x, y) {
    incremental.locate(x, y, this.scratch);
    const at = this.scratch / 8;
    const slots = this.heap().HEAPF64.subarray(at, at + 6);
    return {
      kind: this.locationKinds[slots[0]],
      triangle: slots[1],
      vertices: Array.from(slots.subarray(3, 3 + slots[2])),
    };
  }
}
