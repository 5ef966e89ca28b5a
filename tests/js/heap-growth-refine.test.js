// Refinement's Steiner points are not known before the call, so nothing reserves memory for
// them: the wasm memory grows as the mesh does, doubling each time (bindings/heap_grow.js).
// Grown by 20% steps, as the glue's default does, refining the Natural Earth 50m countries
// grew it 9 times, and each growth can have Node's V8 collect the caller's whole JS heap.
// Its own file: node --test runs it in a process of its own, whose wasm memory starts at its
// initial size.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { countries } from './support/inputs.js';

const sizes = [];
const grow = WebAssembly.Memory.prototype.grow;
WebAssembly.Memory.prototype.grow = function growAndCount(pages) {
  const result = grow.call(this, pages);
  sizes.push(this.buffer.byteLength);
  return result;
};
const { init, geoJSONToInput, memoryUsage, triangulate } = await import('geocdt');
await init({ warmUp: false });

test('refinement grows the wasm memory a few times, each time doubling it', () => {
  const input = geoJSONToInput(countries('50m'), { flat: true });
  const initial = memoryUsage().heapBytes;
  const { steiner } = triangulate(input, { keep: 'inside', refine: { minAngle: 25 } });
  assert.ok(steiner.length > 100_000, `${steiner.length} Steiner points`);
  const { heapBytes, peakBytes } = memoryUsage();
  // The input's reservation, then the growths the Steiner points took: from 18 MB to the
  // 80 MB or so they need, doubling takes 3.
  assert.ok(sizes.length >= 2 && sizes.length <= 5, `grown ${sizes.length} times: ${sizes
    .map((b) => (b / 1048576).toFixed(0)).join(', ')} MB`);
  for (let i = 2; i < sizes.length; i++) {
    assert.ok(sizes[i] >= 1.9 * sizes[i - 1], `growth ${i}: ${sizes[i - 1]} -> ${sizes[i]}`);
  }
  // Doubling leaves at most twice the allocator's peak.
  assert.ok(heapBytes <= 2 * peakBytes + initial, `${heapBytes} bytes for a peak of ${peakBytes}`);
});
