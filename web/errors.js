// The package's own error class, and the core's status values turned into exceptions: bad
// input is a TypeError or RangeError, anything else a GeocdtError with a code.

// Thrown for everything that is not a mistake in the input: code is 'OutOfMemory' or
// 'InternalError' (from the core), 'NotLoaded', 'Disposed', 'Busy',
// 'WorkerFailed' or 'WorkerTerminated' (from the JS layer). index and segment name the input
// point or polyline and its segment where the core knows them.
export class GeocdtError extends Error {
  constructor(code, message, { index, segment, cause } = {}) {
    super(message, cause === undefined ? undefined : { cause });
    this.code = code;
    if (index !== undefined && index >= 0) this.index = index;
    if (segment !== undefined && segment >= 0) this.segment = segment;
  }
}
GeocdtError.prototype.name = 'GeocdtError';

const ADDRESS_SPACE = 'a WebAssembly module can address at most 4 GB';

export function outOfMemoryError(detail) {
  return new GeocdtError('OutOfMemory', `geocdt: out of memory: ${detail}; ${ADDRESS_SPACE}`);
}

// A failed status as the binding reports it: the code's name, the message, and index and
// segment (-1: none).
export function statusError(code, message, index, segment) {
  const limit = code === 'OutOfMemory' && !/4 GB/.test(message) ? `; ${ADDRESS_SPACE}` : '';
  const text = `geocdt: ${message}${limit}`;
  if (code === 'InvalidArgument' || code === 'InvalidCoordinate') {
    const error = new (code === 'InvalidArgument' ? TypeError : RangeError)(text);
    error.code = code;
    if (index >= 0) error.index = index;
    if (segment >= 0) error.segment = segment;
    return error;
  }
  return new GeocdtError(code ?? 'InternalError', text, { index, segment });
}

// An error as plain data for postMessage, and back: the worker's errors keep their class.
export function serializeError(error) {
  return {
    name: error?.name ?? 'Error',
    message: error?.message ?? String(error),
    code: error?.code,
    index: error?.index,
    segment: error?.segment,
    polygon: error?.polygon,
    ring: error?.ring,
  };
}

export function reviveError(e) {
  if (e.name === 'GeocdtError') return new GeocdtError(e.code, e.message, e);
  const Type = e.name === 'TypeError' ? TypeError : e.name === 'RangeError' ? RangeError : null;
  if (Type === null) {
    return new GeocdtError('InternalError', `geocdt: the worker failed: ${e.name}: ${e.message}`);
  }
  const error = new Type(e.message);
  for (const key of ['code', 'index', 'segment', 'polygon', 'ring']) {
    if (e[key] !== undefined) error[key] = e[key];
  }
  return error;
}
