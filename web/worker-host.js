// Runs inside the worker: answers the client's requests (web/worker-client.js) with the same
// API the main entries export, and transfers every result buffer back instead of copying it.

function transferList(value) {
  const buffers = [];
  if (ArrayBuffer.isView(value)) buffers.push(value.buffer);
  else if (value !== null && typeof value === 'object') {
    for (const v of Object.values(value)) if (ArrayBuffer.isView(v)) buffers.push(v.buffer);
  }
  return buffers;
}

function serializeError(error) {
  return {
    name: error?.name ?? 'Error',
    message: error?.message ?? String(error),
    code: error?.code,
    index: error?.index,
    segment: error?.segment,
  };
}

// api: the module namespace of index.node.js or index.browser.js.
// post(message, transfer): sends to the client. Returns the handler for incoming messages.
export function createHost(api, post) {
  const triangulations = new Map();

  function live(id) {
    const t = triangulations.get(id);
    if (!t) throw new Error(`geocdt: no Triangulation ${id} in this worker (disposed?)`);
    return t;
  }

  const ops = {
    init: () => undefined,
    triangulate: (input, options) => api.triangulate(input, options),
    memoryUsage: () => api.memoryUsage(),
    create: (id) => { triangulations.set(id, new api.Triangulation()); },
    insertPoints: (id, xy) => live(id).insertPoints(xy),
    insertPolyline: (id, xy) => live(id).insertPolyline(xy),
    locate: (id, x, y) => live(id).locate(x, y),
    results: (id, options) => live(id).results(options),
    stats: (id) => live(id).stats,
    counts: (id) => {
      const t = live(id);
      return {
        vertexCount: t.vertexCount,
        triangleCount: t.triangleCount,
        polylineCount: t.polylineCount,
      };
    },
    dispose: (id) => {
      triangulations.get(id)?.dispose();
      triangulations.delete(id);
    },
  };

  return async function onMessage({ id, op, args }) {
    try {
      if (!Object.hasOwn(ops, op)) throw new Error(`geocdt worker: unknown request ${op}`);
      await api.init();
      const value = ops[op](...args);
      post({ id, ok: true, value }, transferList(value));
    } catch (error) {
      post({ id, ok: false, error: serializeError(error) }, []);
    }
  };
}
