// Builds the demo into demo/dist: a static folder with relative URLs only (base './'),
// holding the page, the worker, geocdt's wasm and the bundled map data.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';
import { buildAllDatasets } from './scripts/bundle-data.mjs';
import { buildTileData } from './scripts/bundle-tiles.mjs';
import { buildTerrainData } from './scripts/bundle-dem.mjs';

const here = (path) => fileURLToPath(new URL(path, import.meta.url));

// The binary datasets are made from npm packages at build time, never stored in the tree.
function bundledData() {
  let files = null;
  const all = () =>
    (files ??= { ...buildAllDatasets(), ...buildTileData(), ...buildTerrainData() });
  return {
    name: 'geocdt-demo-data',
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const file = all()[decodeURIComponent(request.url.split('?')[0]).replace(/^\//, '')];
        if (!file) return next();
        response.setHeader('Content-Type', 'application/octet-stream');
        response.end(Buffer.from(file));
      });
    },
    generateBundle() {
      for (const [fileName, source] of Object.entries(all())) {
        this.emitFile({ type: 'asset', fileName, source });
      }
    },
  };
}

export default defineConfig({
  root: here('.'),
  base: './',
  logLevel: 'warn',
  resolve: {
    // The demo lives inside the package it shows: resolve the package's own browser entry.
    alias: [{ find: /^geocdt$/, replacement: here('../web/index.browser.js') }],
  },
  worker: { format: 'es' },
  build: {
    outDir: here('dist'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1024,
    // The map demo, the vector tiles filled by triangulatePolygons(), the terrain
    // page and the Voronoi cells.
    rollupOptions: {
      input: {
        main: here('index.html'),
        tiles: here('tiles.html'),
        terrain: here('terrain.html'),
        voronoi: here('voronoi.html'),
      },
    },
  },
  plugins: [bundledData()],
});
