// The wasm memory grows once a call, before the input is written (bindings/heap_reserve.h).
// V8 collects the caller's whole JS heap when memory outside it has grown past a limit:
// grown step by step, a first call with a large GeoJSON alive paid for several of those
// collections. Its own file: node --test runs it in a process of its own, whose wasm memory
// starts at its initial size.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { countries, uniform } from './support/inputs.js';

const grows = [];
const grow = WebAssembly.Memory.prototype.grow;
WebAssembly.Memory.prototype.grow = function growAndCount(pages) {
  grows.push(pages);
  return grow.call(this, pages);
};
const { init, geoJSONToInput, memoryUsage, triangulate } = await import('geocdt');
await init({ warmUp: false });

test('a call grows the wasm memory once, to about what it needs', () => {
  const mb = (bytes) => `${(bytes / 1048576).toFixed(1)} MB`;
  const initial = memoryUsage().heapBytes;
  // Each needs more than the one before, so that each must grow the memory.
  for (const [name, input] of [
    ['Natural Earth 50m countries', geoJSONToInput(countries('50m'), { flat: true })],
    ['400,000 points', { points: uniform(400_000) }],
    ['1,000,000 points', { points: uniform(1_000_000) }]]) {
    grows.length = 0;
    const before = memoryUsage().heapBytes;
    triangulate(input);
    const { heapBytes, peakBytes } = memoryUsage();
    assert.ok(heapBytes > before, `${name}: the memory grew (${mb(before)} -> ${mb(heapBytes)})`);
    assert.equal(grows.length, 1, `${name}: grown ${grows.length} times`);
    // Growing by 20% steps, as the memory did before, ended 10-20% above the peak.
    assert.ok(heapBytes < 1.25 * peakBytes + initial,
      `${name}: ${mb(heapBytes)} of memory for an allocator peak of ${mb(peakBytes)}`);
  }
});
