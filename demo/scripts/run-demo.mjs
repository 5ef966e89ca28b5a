// `npm run demo`: builds the demo, serves it on localhost and prints its URL. npm runs
// scripts/ensure-deps.sh demo first, which installs what a fresh clone lacks and builds the
// wasm when it is missing or stale.
// Options: --port N (default 8080, or the next free one), --no-build (serve demo/dist as is).
import { buildDemo, distDir } from './build-demo.mjs';
import { serveDirectory } from './static-server.mjs';

const args = process.argv.slice(2);
const portArg = args.indexOf('--port');
const firstPort = portArg >= 0 ? Number(args[portArg + 1]) : Number(process.env.PORT ?? 8080);

async function listen() {
  for (let port = firstPort; port < firstPort + 20; port++) {
    try {
      return await serveDirectory(distDir, { port });
    } catch (e) {
      if (e.code !== 'EADDRINUSE') throw e;
    }
  }
  return serveDirectory(distDir, { port: 0 });
}

try {
  if (!args.includes('--no-build')) await buildDemo();
  const { url } = await listen();
  console.log(`\ngeocdt demo: ${url}\n(Ctrl+C to stop)`);
} catch (e) {
  console.error(e.message);
  process.exit(1);
}
