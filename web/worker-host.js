// Runs inside the worker: answers the client's requests (web/worker-client.js) with the same
// API the main entries export, and transfers every result buffer back instead of copying it.
// A request that asks for progress gets { id, progress: { phase, fraction } } messages
// before its answer.
import { GeocdtError, serializeError } from './errors.js';

function transferList(value) {
  const buffers = [];
  if (ArrayBuffer.isView(value)) buffers.push(value.buffer);
  else if (value !== null && typeof value === 'object') {
    for (const v of Object.values(value)) if (ArrayBuffer.isView(v)) buffers.push(v.buffer);
  }
  return buffers;
}

// api: the module namespace of index.node.js or index.browser.js.
// post(message, transfer): sends to the client. Returns the handler for incoming messages.
export function createHost(api, post) {
  const triangulations = new Map();

  function live(id) {
    const t = triangulations.get(id);
    if (!t) {
      throw new GeocdtError('Disposed',
        `geocdt: no Triangulation ${id} in this worker (disposed?)`);
    }
    return t;
  }

  // Each takes the request's onProgress (or undefined), then its arguments.
  const ops = {
    init: () => undefined,
    triangulate: (onProgress, input, options) =>
      api.triangulate(input, { ...options, onProgress }),
    triangulatePolygons: (_, polygons, options) => api.triangulatePolygons(polygons, options),
    // The index array's extraPoints would not survive the message: sent beside it.
    earcut: (_, data, holeIndices, dim) => {
      const triangles = api.earcut(data, holeIndices, dim);
      return { triangles, extraPoints: triangles.extraPoints };
    },
    triangulateRaster: (_, raster, options) => api.triangulateRaster(raster, options),
    voronoi: (_, input, options) => api.voronoi(input, options),
    memoryUsage: () => api.memoryUsage(),
    create: (_, id, options) => { triangulations.set(id, new api.Triangulation(options)); },
    insertPoints: (onProgress, id, xy, values) =>
      live(id).insertPoints(xy, values, { onProgress }),
    insertPolyline: (onProgress, id, xy, values) =>
      live(id).insertPolyline(xy, values, { onProgress }),
    interpolate: (_, id, xy, options) => live(id).interpolate(xy, options),
    rasterize: (_, id, options) => live(id).rasterize(options),
    locate: (_, id, x, y) => live(id).locate(x, y),
    removePoint: (_, id, vertex) => live(id).removePoint(vertex),
    removePoints: (_, id, ids) => live(id).removePoints(ids),
    removePolyline: (_, id, k) => live(id).removePolyline(k),
    movePoint: (_, id, vertex, x, y) => live(id).movePoint(vertex, x, y),
    hasVertex: (_, id, vertex) => live(id).hasVertex(vertex),
    results: (onProgress, id, options) => live(id).results({ ...options, onProgress }),
    refine: (_, id, options) => live(id).refine(options),
    stats: (_, id) => live(id).stats,
    counts: (_, id) => {
      const t = live(id);
      return {
        vertexCount: t.vertexCount,
        triangleCount: t.triangleCount,
        polylineCount: t.polylineCount,
      };
    },
    dispose: (_, id) => {
      triangulations.get(id)?.dispose();
      triangulations.delete(id);
    },
  };

  let initOptions;  // from the client's configure message, sent before any request

  async function load() {
    try {
      await api.init(initOptions);
    } catch (error) {
      throw new GeocdtError('NotLoaded',
        `geocdt: could not load the WebAssembly module in the worker: ${error?.message}`,
        { cause: error });
    }
  }

  return async function onMessage({ id, op, args, progress }) {
    if (op === 'configure') {
      initOptions = args[0];
      return;
    }
    try {
      if (!Object.hasOwn(ops, op)) {
        throw new GeocdtError('InternalError', `geocdt worker: unknown request ${op}`);
      }
      await load();
      const onProgress = progress ? (event) => post({ id, progress: event }, []) : undefined;
      const value = ops[op](onProgress, ...args);
      post({ id, ok: true, value }, transferList(value));
    } catch (error) {
      post({ id, ok: false, error: serializeError(error) }, []);
    }
  };
}
