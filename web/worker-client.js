// The calling side of geocdt/worker: the same calls as the main entry, answered by a worker.
// Input coordinates are transferred to the worker and results transferred back, never copied
// by postMessage.
import { checkCoordinates, checkInput, checkOptions } from './input.js';
import { geoJSONToInput, meshToGeoJSON } from './geojson.js';

const ERROR_TYPES = { TypeError, RangeError };

function reviveError(e) {
  const error = new (ERROR_TYPES[e.name] ?? Error)(e.message);
  for (const key of ['code', 'index', 'segment']) if (e[key] !== undefined) error[key] = e[key];
  return error;
}

// A Float64Array the worker may take: the caller's own array when it spans a whole
// transferable buffer (the caller's array is then detached), otherwise a copy.
function transferable(xy, transfer) {
  const whole = xy instanceof Float64Array && xy.byteOffset === 0
    && xy.byteLength === xy.buffer.byteLength && xy.buffer instanceof ArrayBuffer;
  return transfer && whole ? xy : Float64Array.from(xy);
}

export class GeocdtWorker {
  #endpoint;
  #pending = new Map();
  #nextRequest = 1;
  #nextTriangulation = 1;

  // endpoint: { post(message, transfer), busy(isBusy), terminate() }; the environment's
  // entry calls receive() and fail() with what the worker sends.
  constructor(endpoint) {
    this.#endpoint = endpoint;
  }

  receive({ id, ok, value, error }) {
    const request = this.#pending.get(id);
    if (!request) return;
    this.#pending.delete(id);
    if (this.#pending.size === 0) this.#endpoint.busy(false);
    if (ok) request.resolve(value);
    else request.reject(reviveError(error));
  }

  fail(error) {
    const pending = [...this.#pending.values()];
    this.#pending.clear();
    this.#endpoint.busy(false);
    for (const request of pending) request.reject(error);
  }

  request(op, args = [], transfer = []) {
    const id = this.#nextRequest++;
    return new Promise((resolve, reject) => {
      if (this.#pending.size === 0) this.#endpoint.busy(true);
      this.#pending.set(id, { resolve, reject });
      try {
        this.#endpoint.post({ id, op, args }, transfer);
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

  // options.transfer (default true): hand the caller's Float64Arrays to the worker instead
  // of copying them; they are detached afterwards.
  async triangulate(input, options = {}) {
    const { transfer = true, ...rest } = options ?? {};
    const { points, polylines } = checkInput(input);
    checkOptions(rest);
    const sent = {
      points: transferable(points, transfer),
      polylines: polylines.map((line) => transferable(line, transfer)),
    };
    const buffers = [sent.points.buffer, ...sent.polylines.map((l) => l.buffer)];
    return this.request('triangulate', [sent, rest], [...new Set(buffers)]);
  }

  // The GeoJSON is read on this thread (it cannot be transferred); the coordinates go to the
  // worker as transferred arrays, and the triangles come back as GeoJSON or as arrays.
  async triangulateGeoJSON(geojson, options = {}) {
    const { output = 'geojson', ...rest } = options ?? {};
    if (output !== 'geojson' && output !== 'arrays') {
      throw new TypeError(
        `geocdt: options.output must be 'geojson' or 'arrays', got ${JSON.stringify(output)}`);
    }
    const mesh = await this.triangulate(geoJSONToInput(geojson), { ...rest, transfer: true });
    return output === 'arrays' ? mesh : meshToGeoJSON(mesh);
  }

  memoryUsage() {
    return this.request('memoryUsage');
  }

  createTriangulation() {
    const id = this.#nextTriangulation++;
    const created = this.request('create', [id]);
    return new RemoteTriangulation(this, id, created);
  }

  terminate() {
    this.fail(new Error('geocdt: the worker was terminated'));
    this.#endpoint.terminate();
  }
}

// A Triangulation living in the worker; every method returns a promise.
export class RemoteTriangulation {
  #worker;
  #id;
  #created;

  constructor(worker, id, created) {
    this.#worker = worker;
    this.#id = id;
    this.#created = created;
  }

  async #call(op, args = [], transfer = []) {
    await this.#created;
    return this.#worker.request(op, [this.#id, ...args], transfer);
  }

  #coordinates(op, xy, name, transfer) {
    const sent = transferable(checkCoordinates(xy, name), transfer);
    return this.#call(op, [sent], [sent.buffer]);
  }

  insertPoints(points, { transfer = true } = {}) {
    return this.#coordinates('insertPoints', points, 'points', transfer);
  }

  insertPolyline(polyline, { transfer = true } = {}) {
    return this.#coordinates('insertPolyline', polyline, 'polyline', transfer);
  }

  locate(x, y) { return this.#call('locate', [x, y]); }

  results(options) {
    checkOptions(options);
    return this.#call('results', [options]);
  }

  stats() { return this.#call('stats'); }
  counts() { return this.#call('counts'); }
  dispose() { return this.#call('dispose'); }
}
