// The public API, shared by the Node and browser entries; each entry passes the function that
// instantiates the wasm module in its environment.
import { Kernel } from './kernel.js';
import { checkCoordinates, checkInput, checkOptions } from './input.js';
import { geoJSONToInput, meshToGeoJSON } from './geojson.js';

const now = () => globalThis.performance?.now() ?? Date.now();

function finish(mesh, started) {
  mesh.stats.vertices = mesh.points.length / 2;
  mesh.stats.triangles = mesh.triangles.length / 3;
  mesh.stats.constraintEdges = mesh.constraintEdges.length;
  mesh.stats.milliseconds = now() - started;
  return mesh;
}

export function createApi(instantiate) {
  let kernel = null;
  let loading = null;

  function ready() {
    if (kernel === null) {
      throw new Error('geocdt: the WebAssembly module is not loaded yet: `await init()` first');
    }
    return kernel;
  }

  // Loads the wasm once; later calls resolve at once. A failed load can be retried.
  function init(options) {
    if (kernel !== null) return Promise.resolve();
    loading ??= instantiate(options ?? {}).then(
      (wasm) => { kernel = new Kernel(wasm); },
      (error) => { loading = null; throw error; });
    return loading;
  }

  function triangulate(input, options) {
    const started = now();
    const { points, polylines } = checkInput(input);
    const o = checkOptions(options);
    const k = ready();
    return finish(k.triangulate(points, polylines, o), started);
  }

  function triangulateGeoJSON(geojson, options = {}) {
    const { output = 'geojson', ...rest } = options ?? {};
    if (output !== 'geojson' && output !== 'arrays') {
      throw new TypeError(
        `geocdt: options.output must be 'geojson' or 'arrays', got ${JSON.stringify(output)}`);
    }
    const input = geoJSONToInput(geojson);
    const mesh = triangulate(input, rest);
    return output === 'arrays' ? mesh : meshToGeoJSON(mesh);
  }

  // What the wasm heap holds: its size, the bytes allocated now, and the allocator's peak.
  function memoryUsage() {
    return ready().memory();
  }

  // Frees the C++ side of Triangulation objects that were garbage-collected undisposed.
  const finalizer = typeof FinalizationRegistry === 'function'
    ? new FinalizationRegistry((incremental) => incremental.delete())
    : null;

  class Triangulation {
    #kernel;
    #incremental;

    constructor() {
      this.#kernel = ready();
      this.#incremental = this.#kernel.createIncremental();
      finalizer?.register(this, this.#incremental, this);
    }

    #live() {
      if (this.#incremental === null) throw new Error('geocdt: this Triangulation was disposed');
      return this.#incremental;
    }

    // Returns the vertex id of each point.
    insertPoints(points) {
      const xy = checkCoordinates(points, 'points');
      return this.#kernel.insert(this.#live(), xy, false);
    }

    // Inserts one polyline as constraints; returns the vertex id of each of its points.
    insertPolyline(polyline) {
      const xy = checkCoordinates(polyline, 'polyline');
      return this.#kernel.insert(this.#live(), xy, true);
    }

    locate(x, y) {
      if (typeof x !== 'number' || typeof y !== 'number') {
        throw new TypeError('geocdt: locate(x, y) takes two numbers');
      }
      return this.#kernel.locate(this.#live(), x, y);
    }

    // A copy of the current mesh; the triangulation stays as it is for more insertions.
    results(options) {
      const o = checkOptions(options);
      const started = now();
      return finish(this.#kernel.mesh(this.#live(), o), started);
    }

    get vertexCount() { return this.#live().vertexCount(); }
    get triangleCount() { return this.#live().triangleCount(); }
    get polylineCount() { return this.#live().polylineCount(); }
    get stats() { return this.#kernel.incrementalStats(this.#live()); }
    get disposed() { return this.#incremental === null; }

    dispose() {
      if (this.#incremental === null) return;
      finalizer?.unregister(this);
      this.#incremental.delete();
      this.#incremental = null;
    }
  }

  if (typeof Symbol.dispose === 'symbol') {
    Triangulation.prototype[Symbol.dispose] = Triangulation.prototype.dispose;
  }

  return { init, triangulate, triangulateGeoJSON, memoryUsage, Triangulation };
}
