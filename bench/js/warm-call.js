// The median warm triangulate() time of one package tree in a process of its own, for A/B
// comparisons of two trees (a worktree of an older commit, built) without two wasm heaps in
// one process: run it for each tree in turn, several times.
//   node --expose-gc bench/js/warm-call.js TREE uniform4m|rings10m [--threads N]
import { countryRings, uniformLehmer } from './datasets.js';

const [tree, which] = process.argv.slice(2);
const at = process.argv.indexOf('--threads');
const threads = at > 0 ? Number(process.argv[at + 1]) : 1;
const api = await import(`${tree}/web/index.node.js`);
await api.init({ threads });
const input = which === 'uniform4m'
  ? { points: uniformLehmer(4_000_000, 7) }
  : { polylines: countryRings('10m').polylines };
const times = [];
for (let i = 0; i < 4; i++) {
  globalThis.gc?.();
  const started = performance.now();
  const r = api.triangulate(input);
  times.push(performance.now() - started);
  if (r.stats.threads !== threads) throw new Error(`ran on ${r.stats.threads} threads`);
}
times.shift();  // the first call: cold
times.sort((a, b) => a - b);
console.log(times[1].toFixed(1));
process.exit(0);
