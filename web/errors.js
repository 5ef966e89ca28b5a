// Turns the core's status values into the exceptions JS callers expect.

const CODES = ['Ok', 'InvalidArgument', 'InvalidCoordinate', 'OutOfMemory', 'ConstraintUnresolved',
  'InternalError'];

export function outOfMemoryError(detail) {
  const error = new RangeError(
    `geocdt: out of memory: ${detail}; a WebAssembly module can address at most 4 GB`);
  error.code = 'OutOfMemory';
  return error;
}

// code, message, index and segment as the binding reports them (index -1: none).
export function statusError(code, message, index, segment) {
  const name = CODES[code] ?? 'InternalError';
  const Type = name === 'InvalidArgument' ? TypeError
    : name === 'InvalidCoordinate' || name === 'OutOfMemory' ? RangeError
      : Error;
  const limit = name === 'OutOfMemory' && !/4 GB/.test(message)
    ? '; a WebAssembly module can address at most 4 GB' : '';
  const error = new Type(`geocdt: ${message}${limit}`);
  error.code = name;
  if (index >= 0) error.index = index;
  if (segment >= 0) error.segment = segment;
  return error;
}
