// assert.throws for an error of one class whose message matches a pattern.
import assert from 'node:assert/strict';

export function throwsWith(fn, Type, pattern) {
  assert.throws(fn, (error) => {
    assert.ok(error instanceof Type,
      `expected ${Type.name}, got ${error?.name}: ${error?.message}`);
    assert.match(error.message, pattern);
    return true;
  });
}
