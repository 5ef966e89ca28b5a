// Promise-style requests to the demo's worker. A crashed worker rejects every pending
// request with a message for the page, and the next request starts a fresh worker.

export class WorkerFailure extends Error {
  constructor(message) {
    super(message);
    this.name = 'WorkerFailure';
  }
}

export class InputRejected extends Error {
  constructor(message) {
    super(message);
    this.name = 'InputRejected';
  }
}

export class MeshWorker {
  constructor(createWorker) {
    this._createWorker = createWorker;
    this._worker = null;
    this._pending = new Map();
    this._nextId = 1;
  }

  // onProgress({ phase, fraction }) hears the worker's progress reports for this request.
  request(type, payload = {}, transfer = [], onProgress = null) {
    const worker = this._ensureWorker();
    const id = this._nextId++;
    return new Promise((resolve, reject) => {
      this._pending.set(id, { resolve, reject, onProgress });
      worker.postMessage({ id, type, ...payload }, transfer);
    });
  }

  _ensureWorker() {
    if (this._worker) return this._worker;
    const worker = this._createWorker();
    worker.onmessage = ({ data }) => {
      const pending = this._pending.get(data.id);
      if (!pending) return;
      if (data.progress) {
        pending.onProgress?.(data.progress);
        return;
      }
      this._pending.delete(data.id);
      if (data.ok) pending.resolve(data);
      else if (data.kind === 'input') pending.reject(new InputRejected(data.error));
      else pending.reject(new WorkerFailure(`the triangulation failed: ${data.error}`));
    };
    const fail = (message) => {
      this._worker = null;
      worker.terminate();
      for (const { reject } of this._pending.values()) reject(new WorkerFailure(message));
      this._pending.clear();
    };
    worker.onerror = (e) => {
      e.preventDefault();
      fail(`the triangulation worker crashed: ${e.message || 'it could not start'}`);
    };
    worker.onmessageerror =
      () => fail('the triangulation worker sent a message that could not be read');
    this._worker = worker;
    return worker;
  }
}
