// Run as a child process: how long a cold `await init()` takes (the import excluded, then
// included).
const started = performance.now();
const { init } = await import('geocdt');
const imported = performance.now();
await init();
const done = performance.now();
console.log(JSON.stringify({ initMs: done - imported, importAndInitMs: done - started }));
