// The public API, shared by the Node and browser entries; each entry passes the function that
// instantiates the wasm module in its environment.
import { checkOptionNames } from './call-options.js';
import { Kernel } from './kernel.js';
import { GeocdtError } from './errors.js';
import {
  checkCoordinates, checkEarcutInput, checkHeightmap, checkInput, checkOffsets, checkPolygons,
  checkRaster, checkRasterOptions,
  checkValues, checkValuesPerPoint, describe, threadsError,
} from './input.js';
import {
  featureFillResult, featurePolygons, geoJSONOutput, geoJSONResult, perFeatureMode, readGeoJSON,
} from './geojson.js';
import { checkVoronoiOptions } from './voronoi-options.js';
import { cellsToGeoJSON, sitesAndRings } from './voronoi-geojson.js';

const now = () => globalThis.performance?.now() ?? Date.now();

function finish(mesh, started) {
  mesh.stats.vertices = mesh.points.length / 2;
  mesh.stats.triangles = mesh.triangles.length / 3;
  mesh.stats.constraintEdges = mesh.constraintEdges.length;
  mesh.stats.milliseconds = now() - started;
  return mesh;
}

// Options of the incremental insertions: only onProgress.
function insertOptions(options, call) {
  if (options == null) return undefined;
  if (typeof options !== 'object') {
    throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
  }
  checkOptionNames(options, call);
  return options.onProgress;
}

const POLYGON_NAMES = { coords: 'coords', ringOffsets: 'ringOffsets',
  polygonOffsets: 'polygonOffsets' };
const EARCUT_NAMES = { coords: 'data', ringOffsets: 'holeIndices', polygonOffsets: 'holeIndices' };

// 'auto' threads: the cores, at most this many.
export const kAutoThreads = 8;

// instantiate(options) resolves to { wasm, threads }: the module and the threads it may use.
export function createApi(instantiate) {
  let kernel = null;
  let loading = null;

  function ready() {
    if (kernel === null) {
      throw new GeocdtError('NotLoaded',
        'geocdt: the WebAssembly module is not loaded yet: `await init()` first');
    }
    return kernel;
  }

  // Loads the wasm once; later calls resolve at once. A failed load can be retried.
  // options.warmUp: false starts no warm-up worker (web/warm-up.js). options.threads: a
  // number of threads or 'auto'; more than 1 loads the threaded build where it can run.
  function init(options) {
    try {
      checkOptionNames(options, 'init()');
    } catch (error) {
      return Promise.reject(error);
    }
    if (kernel !== null) return Promise.resolve();
    const warmUp = options?.warmUp;
    if (warmUp !== undefined && typeof warmUp !== 'boolean') {
      return Promise.reject(new TypeError(
        `geocdt: options.warmUp must be a boolean, got ${describe(warmUp)}`));
    }
    const wrongThreads = threadsError(options?.threads);
    if (wrongThreads) return Promise.reject(wrongThreads);
    loading ??= instantiate(options ?? {}).then(
      (loaded) => { kernel = new Kernel(loaded.wasm, loaded.threads); },
      (error) => { loading = null; throw error; });
    return loading;
  }

  function triangulate(input, options) {
    const started = now();
    const k = ready();
    const o = k.meshOptions(options);
    checkOptionNames(options, 'triangulate()');
    checkOptionNames(options?.refine, 'options.refine');
    const valuesPerPoint = checkValuesPerPoint(options);
    const checked = checkInput(input, valuesPerPoint);
    const r = k.refineOptions(options?.refine);
    return finish(k.triangulate(checked, o, valuesPerPoint, options?.onProgress, r), started);
  }

  // A TIN from a heightmap: vertices on pixel positions (or the bbox's frame), heights in
  // values, every pixel within options.maxError of the surface.
  function triangulateRaster(raster, options) {
    const started = now();
    const k = ready();
    checkOptionNames(options, 'triangulateRaster()');
    const checked = checkHeightmap(raster);
    const mesh = k.triangulateRaster(checked, checkRasterOptions(options, checked));
    return finish(mesh, started);
  }

  function triangulateGeoJSON(geojson, options) {
    checkOptionNames(options, 'triangulateGeoJSON()');
    const { output, rest: chosen } = geoJSONOutput(options);
    const { perFeature, rest } = perFeatureMode(chosen);
    const input = readGeoJSON(geojson);
    if (perFeature) {
      const batch = featurePolygons(input);
      const filled = triangulatePolygons(batch, { fillRule: rest.fillRule });
      return featureFillResult(filled, batch, input, output);
    }
    return geoJSONResult(triangulate(input, rest), input, output, rest);
  }

  // Every polygon of a batch in GeoArrow's layout triangulated alone, inside triangles only,
  // in one call: { triangles, extraPoints, triangleOffsets, stats }.
  function triangulatePolygons(polygons, options) {
    const started = now();
    const k = ready();
    const checked = checkPolygons(polygons);
    const fill = k.fillRuleOption(options);
    checkOptionNames(options, 'triangulatePolygons()');
    const result = k.triangulatePolygons(checked, fill, 2, POLYGON_NAMES);
    result.stats.polygons = checked.polygonOffsets.length - 1;
    result.stats.milliseconds = now() - started;
    return result;
  }

  // earcut's signature: one polygon (data with dim numbers a vertex, holes starting at the
  // vertex indices holeIndices) -> its triangles' vertex indices, with the points added where
  // rings cross as the array's extraPoints (indices from data.length / dim on).
  function earcut(data, holeIndices, dim = 2) {
    const k = ready();
    const batch = checkEarcutInput(data, holeIndices, dim);
    const { triangles, extraPoints } = k.triangulatePolygons(batch, k.fillRule.evenodd, dim,
      EARCUT_NAMES);
    triangles.extraPoints = extraPoints;
    return triangles;
  }

  // Each site's Voronoi cell clipped to the domain (the rings, the sites' hull or a box), as a
  // GeoArrow MultiPolygon per site; options.lloyd relaxes the sites first.
  function voronoi(input, options) {
    const started = now();
    const k = ready();
    checkOptionNames(options, 'voronoi()');
    if (options?.lloyd !== null && typeof options?.lloyd === 'object') {
      checkOptionNames(options.lloyd, 'options.lloyd');
    }
    const { points, lines } = checkInput(input, 1, 'voronoi');
    if (points.length === 0) {
      throw new RangeError('geocdt: voronoi() needs at least one site in input.points');
    }
    const o = checkVoronoiOptions(options, points, lines.count);
    const cells = k.voronoi({ points, lines }, o);
    cells.stats.sites = points.length / 2;
    cells.stats.polygons = cells.polygonOffsets.length - 1;
    cells.stats.rings = cells.ringOffsets.length - 1;
    cells.stats.milliseconds = now() - started;
    return cells;
  }

  // The same from GeoJSON: Point and MultiPoint positions are the sites, Polygon and
  // MultiPolygon rings bound the domain; a FeatureCollection of each site's cell with its
  // feature's id and properties, or with { output: 'arrays' } voronoi()'s arrays and the
  // sites' features.
  function voronoiGeoJSON(geojson, options) {
    checkOptionNames(options, 'voronoiGeoJSON()');
    const { output, rest } = geoJSONOutput(options);
    const input = readGeoJSON(geojson, { pointFeatures: true });
    const cells = voronoi(sitesAndRings(input), rest);
    cells.siteFeatures = input.pointFeatures;
    return output === 'arrays' ? cells : cellsToGeoJSON(cells);
  }

  // What the wasm heap holds: its size, the bytes allocated now, and the allocator's peak.
  function memoryUsage() {
    return ready().memory();
  }

  // Frees the C++ side of Triangulation objects that were garbage-collected undisposed.
  const finalizer = typeof FinalizationRegistry === 'function'
    ? new FinalizationRegistry((incremental) => incremental.delete())
    : null;

  // An id or polyline number: an integer in [0, 2^32).
  function checkId(id, call) {
    if (typeof id !== 'number') {
      throw new TypeError(`geocdt: ${call}: the id must be a number, got ${describe(id)}`);
    }
    if (!Number.isInteger(id) || id < 0 || id > 0xffffffff) {
      throw new RangeError(`geocdt: ${call}: the id must be an integer from 0 to 2^32 - 1, `
        + `got ${id}`);
    }
    return id;
  }

  // An array or typed array of ids, each checked as checkId checks one; a bad one's error
  // has its index in ids, as the core's refusals have.
  function checkIds(ids, call) {
    if (!Array.isArray(ids) && !(ArrayBuffer.isView(ids) && !(ids instanceof DataView))) {
      throw new TypeError(`geocdt: ${call}: ids must be an array or typed array, `
        + `got ${describe(ids)}`);
    }
    if (ids instanceof Uint32Array || ids instanceof Uint16Array || ids instanceof Uint8Array) {
      return ids;
    }
    for (let i = 0; i < ids.length; i++) {
      try {
        checkId(ids[i], `${call}: ids[${i}]`);
      } catch (error) {
        error.index = i;
        throw error;
      }
    }
    return ids;
  }

  // insertPoints(xy, values?, options?): values is an array or typed array, options an object.
  const splitValues = (values, options) => (values != null && typeof values === 'object'
    && !Array.isArray(values) && !ArrayBuffer.isView(values)
    ? { values: undefined, options: values } : { values, options });

  class Triangulation {
    #kernel;
    #incremental;
    #valuesPerPoint;

    // options.valuesPerPoint: how many values each point carries (default 1).
    constructor(options) {
      if (options != null && typeof options !== 'object') {
        throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
      }
      checkOptionNames(options, 'new Triangulation()');
      this.#kernel = ready();
      this.#valuesPerPoint = checkValuesPerPoint(options);
      this.#incremental = this.#kernel.createIncremental(this.#valuesPerPoint);
      finalizer?.register(this, this.#incremental, this);
    }

    #insert(given, name, polyline, maybeValues, maybeOptions) {
      const live = this.#live();
      const xy = checkCoordinates(given, name);
      const { values, options } = splitValues(maybeValues, maybeOptions);
      const checked = values == null ? undefined
        : checkValues(values, xy.length / 2, this.#valuesPerPoint, `${name} values`);
      return this.#kernel.insert(live, xy, polyline,
        insertOptions(options, polyline ? 'insertPolyline()' : 'insertPoints()'), checked);
    }

    #live() {
      if (this.#incremental === null) {
        throw new GeocdtError('Disposed', 'geocdt: this Triangulation was disposed');
      }
      this.#kernel.idle();
      return this.#incremental;
    }

    // Returns the vertex id of each point. values: valuesPerPoint numbers per point.
    insertPoints(points, values, options) {
      return this.#insert(points, 'points', false, values, options);
    }

    // Inserts one polyline as constraints; returns the vertex id of each of its points.
    insertPolyline(polyline, values, options) {
      return this.#insert(polyline, 'polyline', true, values, options);
    }

    // Values at each query point (valuesPerPoint numbers per query; NaN outside the hull).
    interpolate(points, options) {
      const live = this.#live();
      const method = this.#kernel.method(options);
      checkOptionNames(options, 'interpolate()');
      return this.#kernel.interpolate(live, checkCoordinates(points, 'points'), method);
    }

    // The surface sampled on width x height pixels over bbox [minX, minY, maxX, maxY].
    rasterize(options) {
      const live = this.#live();
      const raster = checkRaster(options, this.#valuesPerPoint);
      checkOptionNames(options, 'rasterize()');
      return this.#kernel.rasterize(live, raster, this.#kernel.method(options));
    }

    get valuesPerPoint() { return this.#valuesPerPoint; }

    // Editing in place. Ids are those the insertions returned; a bad one (removed, out of
    // range, not an integer) throws a RangeError and changes nothing.
    // Removes a point of insertPoints: true when its vertex went, false when it stays as a
    // vertex of a polyline.
    removePoint(id) {
      const live = this.#live();
      return this.#kernel.removePoint(live, checkId(id, 'removePoint(id)'));
    }

    // Removes many points of insertPoints in one call, nearby ones one after the other (which
    // costs less than a call each in random order); returns how many vertices went (the
    // others stay as polylines' vertices: hasVertex tells). A bad id changes nothing.
    removePoints(ids) {
      const live = this.#live();
      return this.#kernel.removePoints(live, checkIds(ids, 'removePoints'));
    }

    // Removes polyline k (numbered in insertion order from 0; the others keep their numbers).
    removePolyline(k) {
      const live = this.#live();
      this.#kernel.removePolyline(live, checkId(k, 'removePolyline(k)'));
    }

    // Moves the vertex of a point or of a polyline to (x, y); its polylines follow.
    movePoint(id, x, y) {
      const live = this.#live();
      const checked = checkId(id, 'movePoint(id, x, y)');
      if (typeof x !== 'number' || typeof y !== 'number') {
        throw new TypeError('geocdt: movePoint(id, x, y): x and y must be numbers, '
          + `got ${describe(x)} and ${describe(y)}`);
      }
      this.#kernel.movePoint(live, checked, x, y);
    }

    // Whether id names a vertex now.
    hasVertex(id) {
      return Number.isInteger(id) && id >= 0 && id <= 0xffffffff && this.#live().hasVertex(id);
    }

    locate(x, y) {
      if (typeof x !== 'number' || typeof y !== 'number') {
        throw new TypeError('geocdt: locate(x, y) takes two numbers');
      }
      if (!Number.isFinite(x) || !Number.isFinite(y)) {
        throw new RangeError(`geocdt: locate(${x}, ${y}): x and y must be finite numbers`);
      }
      return this.#kernel.locate(this.#live(), x, y);
    }

    // Delaunay refinement of what is there now: options.minAngle, maxArea, maxSteinerPoints,
    // and keep / fillRule (keep: 'inside' refines only the inside). Returns the stats.
    refine(options) {
      const live = this.#live();
      if (options != null && typeof options !== 'object') {
        throw new TypeError(`geocdt: options must be an object, got ${describe(options)}`);
      }
      checkOptionNames(options, 'refine()');
      const o = this.#kernel.meshOptions(
        options == null ? undefined : { keep: options.keep, fillRule: options.fillRule });
      const r = this.#kernel.refineOptions(options ?? {}, 'options');
      return this.#kernel.refine(live, o, r);
    }

    // A copy of the current mesh; the triangulation stays as it is for more insertions.
    // options.polygons: offsets into the polylines inserted so far, for region labels.
    results(options) {
      const started = now();
      const live = this.#live();
      const o = this.#kernel.meshOptions(options);
      checkOptionNames(options, 'results()');
      const polygons = options?.polygons == null ? undefined
        : checkOffsets(options.polygons, 'options.polygons', 'polygons', 'polyline');
      return finish(this.#kernel.mesh(live, o, options?.onProgress, polygons), started);
    }

    get vertexCount() { return this.#live().vertexCount(); }
    get triangleCount() { return this.#live().triangleCount(); }
    get polylineCount() { return this.#live().polylineCount(); }
    get stats() { return this.#live().stats(); }
    get disposed() { return this.#incremental === null; }

    dispose() {
      if (this.#incremental === null) return;
      this.#kernel.idle();
      finalizer?.unregister(this);
      this.#incremental.delete();
      this.#incremental = null;
    }
  }

  if (typeof Symbol.dispose === 'symbol') {
    Triangulation.prototype[Symbol.dispose] = Triangulation.prototype.dispose;
  }

  return {
    init, triangulate, triangulatePolygons, earcut, triangulateRaster, triangulateGeoJSON,
    voronoi, voronoiGeoJSON, memoryUsage, Triangulation,
  };
}
