// The calling side of geocdt/worker: the same calls as the main entry, answered by a worker.
// Input arrays are transferred to the worker and results transferred back, never copied by
// postMessage; the values are checked in the worker, by the core, as they are copied into
// the heap.
import { checkOptionNames } from './call-options.js';
import { GeocdtError, reviveError } from './errors.js';
import {
  checkCoordinates, checkEarcutInput, checkHeightmap, checkInput, checkOffsets, checkPolygons,
  checkRaster, checkRasterOptions,
  checkValues, checkValuesPerPoint, describe,
} from './input.js';
import {
  featureFillResult, featurePolygons, geoJSONOutput, geoJSONResult, perFeatureMode, readGeoJSON,
} from './geojson.js';
import { cellsToGeoJSON, sitesAndRings } from './voronoi-geojson.js';

// An array the worker may take: a typed array that spans its whole buffer is handed over
// (the caller's array is then detached), another typed array is copied with slice(), and a
// plain array goes as it is (postMessage clones it).
function transferable(values, transfer, buffers) {
  if (!ArrayBuffer.isView(values)) return values;
  if (!(values.buffer instanceof ArrayBuffer)) return values;  // shared memory: posted as is
  const whole = values.byteOffset === 0 && values.byteLength === values.buffer.byteLength;
  const sent = transfer && whole ? values : values.slice();
  buffers.add(sent.buffer);
  return sent;
}

// options: those of call `what` (call-options.js), and transfer.
function takeProgress(options, what) {
  checkOptionNames(options, what, ['transfer']);
  const { transfer = true, onProgress, ...rest } = options ?? {};
  if (onProgress != null && typeof onProgress !== 'function') {
    throw new TypeError(
      `geocdt: options.onProgress must be a function, got ${describe(onProgress)}`);
  }
  return { transfer, onProgress, rest };
}

export class GeocdtWorker {
  #endpoint;
  #pending = new Map();
  #nextRequest = 1;
  #nextTriangulation = 1;
  #terminated = false;

  // endpoint: { post(message, transfer), busy(isBusy), terminate() }; the environment's
  // entry calls receive() and fail() with what the worker sends.
  constructor(endpoint) {
    this.#endpoint = endpoint;
  }

  receive({ id, ok, value, error, progress }) {
    const request = this.#pending.get(id);
    if (!request) return;
    if (progress !== undefined) {
      if (request.failure !== undefined || !request.onProgress) return;
      try {
        request.onProgress(progress);
      } catch (failure) {
        request.failure = failure;  // thrown once the answer arrives, as the main API does
      }
      return;
    }
    this.#pending.delete(id);
    if (this.#pending.size === 0) this.#endpoint.busy(false);
    if (!ok) request.reject(reviveError(error));
    else if (request.failure !== undefined) request.reject(request.failure);
    else request.resolve(value);
  }

  fail(error) {
    const pending = [...this.#pending.values()];
    this.#pending.clear();
    this.#endpoint.busy(false);
    for (const request of pending) request.reject(error);
  }

  request(op, args = [], transfer = [], onProgress = undefined) {
    if (this.#terminated) {
      return Promise.reject(
        new GeocdtError('WorkerTerminated', 'geocdt: the worker was terminated'));
    }
    const id = this.#nextRequest++;
    return new Promise((resolve, reject) => {
      if (this.#pending.size === 0) this.#endpoint.busy(true);
      this.#pending.set(id, { resolve, reject, onProgress });
      try {
        this.#endpoint.post({ id, op, args, progress: !!onProgress }, transfer);
      } catch (error) {
        this.#pending.delete(id);
        if (this.#pending.size === 0) this.#endpoint.busy(false);
        reject(error);
      }
    });
  }

  init() {
    return this.request('init').then(() => undefined);
  }

  // options.transfer (default true): hand the caller's typed arrays to the worker instead of
  // copying them; they are detached afterwards. options.onProgress({ phase, fraction }).
  async triangulate(input, options) {
    const { transfer, onProgress, rest } = takeProgress(options, 'triangulate()');
    const { points, lines, polygons, values } = checkInput(input, checkValuesPerPoint(rest));
    const buffers = new Set();
    const sent = { points: transferable(points, transfer, buffers) };
    if (polygons !== undefined) sent.polygons = transferable(polygons, transfer, buffers);
    if (values !== undefined) sent.values = transferable(values, transfer, buffers);
    if (lines.arrays !== undefined) {
      sent.polylines = lines.arrays.map((line) => transferable(line, transfer, buffers));
    } else {
      sent.polylines = {
        coords: transferable(lines.coords, transfer, buffers),
        offsets: transferable(lines.offsets, transfer, buffers),
      };
    }
    return this.request('triangulate', [sent, rest], [...buffers], onProgress);
  }

  // triangulatePolygons() in the worker: the batch's arrays are transferred (options.transfer
  // as for triangulate()), the three result arrays transferred back.
  async triangulatePolygons(polygons, options) {
    const { transfer, rest } = takeProgress(options, 'triangulatePolygons()');
    const { coords, ringOffsets, polygonOffsets } = checkPolygons(polygons);
    const buffers = new Set();
    const sent = {
      coords: transferable(coords, transfer, buffers),
      ringOffsets: transferable(ringOffsets, transfer, buffers),
      polygonOffsets: transferable(polygonOffsets, transfer, buffers),
    };
    return this.request('triangulatePolygons', [sent, rest], [...buffers]);
  }

  // earcut()'s signature in the worker; data is copied (it is usually a small array).
  async earcut(data, holeIndices, dim = 2) {
    checkEarcutInput(data, holeIndices, dim);
    const holes = holeIndices == null ? holeIndices : Array.from(holeIndices);
    const { triangles, extraPoints } = await this.request('earcut', [data, holes, dim]);
    triangles.extraPoints = extraPoints;
    return triangles;
  }

  // The heights (and the breaklines' arrays) go to the worker as triangulate()'s points do:
  // transferred unless options.transfer is false.
  async triangulateRaster(raster, options) {
    checkOptionNames(options, 'triangulateRaster()', ['transfer']);
    const { transfer = true, ...rest } = options ?? {};
    const { heights, width, height } = checkHeightmap(raster);
    const { lines } = checkRasterOptions(rest, { width, height });
    const buffers = new Set();
    const sent = { ...rest };
    if (rest.breaklines != null) {
      sent.breaklines = lines.arrays !== undefined
        ? lines.arrays.map((line) => transferable(line, transfer, buffers))
        : {
          coords: transferable(lines.coords, transfer, buffers),
          offsets: transferable(lines.offsets, transfer, buffers),
        };
    }
    if (rest.breaklineHeights != null) {
      sent.breaklineHeights = transferable(rest.breaklineHeights, transfer, buffers);
    }
    const input = { heights: transferable(heights, transfer, buffers), width, height };
    return this.request('triangulateRaster', [input, sent], [...buffers]);
  }

  // The GeoJSON is read on this thread (it cannot be transferred); the coordinates go to the
  // worker as transferred arrays, and the triangles come back as GeoJSON or as arrays. The
  // features of the regions stay here.
  async triangulateGeoJSON(geojson, options) {
    checkOptionNames(options, 'triangulateGeoJSON()', ['transfer']);
    const { output, rest: chosen } = geoJSONOutput(options);
    const { perFeature, rest } = perFeatureMode(chosen);
    const input = readGeoJSON(geojson);
    if (perFeature) {
      // Copied, not transferred: the rings' coordinates become the result's points here.
      const batch = featurePolygons(input);
      const filled = await this.triangulatePolygons(batch,
        { fillRule: rest.fillRule, transfer: false });
      return featureFillResult(filled, batch, input, output);
    }
    const mesh = await this.triangulate(input, { ...rest, transfer: true });
    return geoJSONResult(mesh, input, output, rest);
  }

  // The sites and rings are transferred as triangulate()'s are; the options are checked in the
  // worker, by the same code as the main API's.
  async voronoi(input, options) {
    const { transfer, rest } = takeProgress(options, 'voronoi()');
    const { points, lines } = checkInput(input, 1, 'voronoi');
    const buffers = new Set();
    const sent = { points: transferable(points, transfer, buffers) };
    sent.polylines = lines.arrays !== undefined
      ? lines.arrays.map((line) => transferable(line, transfer, buffers))
      : {
        coords: transferable(lines.coords, transfer, buffers),
        offsets: transferable(lines.offsets, transfer, buffers),
      };
    return this.request('voronoi', [sent, rest], [...buffers]);
  }

  // As triangulateGeoJSON(): read here, the cells made in the worker, the features kept here.
  async voronoiGeoJSON(geojson, options) {
    checkOptionNames(options, 'voronoiGeoJSON()', ['transfer']);
    const { output, rest } = geoJSONOutput(options);
    const input = readGeoJSON(geojson, { pointFeatures: true });
    const cells = await this.voronoi(sitesAndRings(input), { ...rest, transfer: true });
    cells.siteFeatures = input.pointFeatures;
    return output === 'arrays' ? cells : cellsToGeoJSON(cells);
  }

  memoryUsage() {
    return this.request('memoryUsage');
  }

  // options.valuesPerPoint: as new Triangulation()'s.
  createTriangulation(options) {
    checkOptionNames(options, 'new Triangulation()');
    const valuesPerPoint = checkValuesPerPoint(options);
    const id = this.#nextTriangulation++;
    const created = this.request('create', [id, { valuesPerPoint }]);
    return new RemoteTriangulation(this, id, created, valuesPerPoint);
  }

  terminate() {
    this.#terminated = true;
    this.fail(new GeocdtError('WorkerTerminated', 'geocdt: the worker was terminated'));
    this.#endpoint.terminate();
  }
}

// A Triangulation living in the worker; every method returns a promise.
export class RemoteTriangulation {
  #worker;
  #id;
  #created;
  #valuesPerPoint;

  constructor(worker, id, created, valuesPerPoint) {
    this.#worker = worker;
    this.#id = id;
    this.#created = created;
    this.#valuesPerPoint = valuesPerPoint;
  }

  async #call(op, args = [], transfer = [], onProgress = undefined) {
    await this.#created;
    return this.#worker.request(op, [this.#id, ...args], transfer, onProgress);
  }

  // values: an array or typed array, or absent (then options may come second).
  async #coordinates(op, xy, name, values, options) {
    if (values != null && typeof values === 'object' && !Array.isArray(values)
      && !ArrayBuffer.isView(values)) {
      [values, options] = [undefined, values];
    }
    const { transfer, onProgress } = takeProgress(options, `${op}()`);
    const buffers = new Set();
    const sent = transferable(checkCoordinates(xy, name), transfer, buffers);
    const sentValues = values == null ? undefined : transferable(
      checkValues(values, sent.length / 2, this.#valuesPerPoint, `${name} values`), transfer,
      buffers);
    return this.#call(op, [sent, sentValues], [...buffers], onProgress);
  }

  insertPoints(points, values, options) {
    return this.#coordinates('insertPoints', points, 'points', values, options);
  }

  insertPolyline(polyline, values, options) {
    return this.#coordinates('insertPolyline', polyline, 'polyline', values, options);
  }

  // options.transfer as for insertPoints(); options.method 'linear' or 'natural'.
  async interpolate(points, options) {
    const { transfer, rest } = takeProgress(options, 'interpolate()');
    const buffers = new Set();
    const sent = transferable(checkCoordinates(points, 'points'), transfer, buffers);
    return this.#call('interpolate', [sent, rest], [...buffers]);
  }

  async rasterize(options) {
    checkRaster(options, this.#valuesPerPoint);
    checkOptionNames(options, 'rasterize()');
    const { bbox, width, height, method } = options;
    return this.#call('rasterize', [{ bbox: Array.from(bbox), width, height, method }]);
  }

  get valuesPerPoint() { return this.#valuesPerPoint; }

  locate(x, y) { return this.#call('locate', [x, y]); }

  // Editing: the worker's Triangulation answers (a bad id rejects with its RangeError).
  removePoint(id) { return this.#call('removePoint', [id]); }
  // (Copied now: the message goes after the worker is ready, and the caller may change ids.)
  removePoints(ids) {
    return this.#call('removePoints', [ArrayBuffer.isView(ids) || Array.isArray(ids)
      ? ids.slice() : ids]);
  }
  removePolyline(k) { return this.#call('removePolyline', [k]); }
  movePoint(id, x, y) { return this.#call('movePoint', [id, x, y]); }
  hasVertex(id) { return this.#call('hasVertex', [id]); }

  async results(options) {
    const { onProgress, rest } = takeProgress(options, 'results()');
    if (rest.polygons != null) {
      checkOffsets(rest.polygons, 'options.polygons', 'polygons', 'polyline');
    }
    return this.#call('results', [rest], [], onProgress);
  }

  refine(options) { return this.#call('refine', [options]); }
  stats() { return this.#call('stats'); }
  counts() { return this.#call('counts'); }
  dispose() { return this.#call('dispose'); }
}
