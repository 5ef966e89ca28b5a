import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { createApi } from '../../web/api.js';
import { uniform } from './datasets.js';
import { median } from './timing.js';
const names = process.argv.slice(3);
const n = Number(process.argv[2]);
const apis = [];
for (const name of names) {
  const dir = `/tmp/variants/${name}/bindings/`;
  const factory = (await import(pathToFileURL(dir + 'geocdt.mjs'))).default;
  const api = createApi(async () => factory({ wasmBinary: readFileSync(dir + 'geocdt.wasm') }));
  await api.init();
  apis.push(api);
}
const xy = uniform(n);
const times = names.map(() => []);
for (let round = 0; round < 7; round++) {
  for (let k = 0; k < apis.length; k++) {
    const i = (k + round) % apis.length;
    globalThis.gc?.();
    const r = apis[i].triangulate({ points: xy });
    times[i].push(r.stats.coreMilliseconds);
  }
}
names.forEach((name, i) => console.log(name, median(times[i]).toFixed(0)));
