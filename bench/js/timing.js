// Same-process timing: contenders run in alternation, round after round, so that machine noise
// and JIT warm-up fall on all of them alike; each reports its median.
import { existsSync, readFileSync } from 'node:fs';

export function median(values) {
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

// The main thread's CPU time in ms, from Linux's scheduler statistics (ns on a CPU), or
// undefined elsewhere: unlike the wall clock, blind to the time spent waiting for a core on a
// loaded machine (and to other threads' work).
export function threadCpuClock() {
  const file = `/proc/self/task/${process.pid}/schedstat`;
  if (!existsSync(file)) return undefined;
  return () => Number(readFileSync(file, 'utf8').split(' ')[0]) / 1e6;
}

function collect() {
  globalThis.gc?.();
}

// contenders: [{ name, run(), describe(output) }]: only run() is timed; describe() turns its
// output into the summary, checks included, afterwards. run() may instead return a promise of
// { output, ms } when it times itself elsewhere (in a worker). Returns { name: { ms, summary }
// or { error } }. A contender that throws is reported as failed and not run again.
export async function alternate(contenders, rounds) {
  const results = Object.fromEntries(contenders.map((c) => [c.name, { times: [] }]));
  for (let round = 0; round < rounds; round++) {
    for (let k = 0; k < contenders.length; k++) {
      const c = contenders[(k + round) % contenders.length];
      const r = results[c.name];
      if (r.error) continue;
      collect();
      const started = performance.now();
      try {
        let output = c.run();
        let elapsed = performance.now() - started;
        if (output instanceof Promise) ({ output, ms: elapsed } = await output);
        r.times.push(elapsed);
        r.summary = c.describe(output);
      } catch (error) {
        const firstLine = String(error?.message ?? error).split('\n')[0];
        r.error = `${error?.name ?? 'Error'}: ${firstLine.slice(0, 120)}`;
      }
    }
  }
  for (const r of Object.values(results)) if (r.times.length) r.ms = median(r.times);
  return results;
}
