// Run as a child process: a fresh module, one triangulation of n uniform points, and the
// wasm heap it took (the allocator's peak, and the memory size) per point.
import { init, memoryUsage, triangulate } from 'geocdt';
import { uniform } from './datasets.js';

const n = Number(process.argv[2] ?? 1_000_000);
await init();
const before = memoryUsage();
const xy = uniform(n);
triangulate({ points: xy });
const after = memoryUsage();
console.log(JSON.stringify({
  n,
  peakBytesPerPoint: (after.peakBytes - before.peakBytes) / n,
  heapGrowthPerPoint: (after.heapBytes - before.heapBytes) / n,
}));
