// The warm-up: triangulations run in a worker on the module the caller's init() compiled.
// Engines share a compiled WebAssembly.Module's code between the threads that instantiate it,
// so the worker's calls compile the functions a first call reaches and get them optimised on
// another core while the caller's own first call runs (bench/EXPERIMENTS.md, F19b).

// The glue's instantiateWasm hook, instantiating an already compiled module. Resolves to the
// ready module, or rejects with the error of instantiating it (the glue would only log it).
// settings: more properties of the module object (the threaded build's pool).
export function instantiateCompiled(createModule, module, settings = {}) {
  return new Promise((resolve, reject) => {
    const instantiateWasm = (imports, receive) => {
      WebAssembly.instantiate(module, imports).then((instance) => receive(instance, module))
        .catch(reject);
      return {};
    };
    createModule({ ...settings, instantiateWasm }).then(resolve, reject);
  });
}

// The single-threaded module, instantiated from its compiled module, with the warm-up
// (startWarmUp(module), each entry's own worker) started unless options.warmUp is false.
// It starts once the code that awaits init() has run to its first wait: a call made at once
// finds both cores free (the warm-up would only compete with it, bench/EXPERIMENTS.md), and a
// caller that loads its data first gets the warm-up meanwhile.
export async function instantiateWithWarmUp(createModule, module, options, startWarmUp) {
  const wasm = await instantiateCompiled(createModule, module);
  if (options.warmUp !== false) setTimeout(() => startWarmUp(module), 0);
  return { wasm, threads: 1 };
}

// The threaded build's module settings: a pool of threads - 1 workers, which load the glue
// from glueUrl. The glue's warning on a blocked main thread is dropped: a call blocks the
// thread that makes it while the pool works, as any call does (API.md says so).
export function threadedSettings(threads, glueUrl) {
  return {
    geocdtThreadPool: threads - 1,
    mainScriptUrlOrBlob: glueUrl,
    printErr: (text) => {
      if (!text.startsWith('Blocking on the main thread')) console.warn(text);
    },
  };
}

// Pseudo-random numbers in [0, 1): the same warm-up in every run.
function random(seed) {
  let s = seed;
  return () => {
    s = (s * 16807) % 2147483647;
    return s / 2147483647;
  };
}

// Points; rings that overlap and cross one another (as coasts do); rings that share borders.
function warmUpInputs() {
  const next = random(12345);
  const points = new Float64Array(2 * 20000);
  for (let i = 0; i < points.length; i++) points[i] = next();
  const rings = 256;
  const sides = 48;
  const coords = new Float64Array(2 * rings * (sides + 1));
  const offsets = new Uint32Array(rings + 1);
  let at = 0;
  for (let r = 0; r < rings; r++) {
    const cx = next(), cy = next(), radius = 0.02 + 0.05 * next();
    for (let k = 0; k <= sides; k++) {
      const angle = (2 * Math.PI * (k % sides)) / sides;
      const wobble = radius * (0.7 + 0.3 * Math.sin(5 * angle + r));
      coords[at++] = cx + wobble * Math.cos(angle);
      coords[at++] = cy + wobble * Math.sin(angle);
    }
    offsets[r + 1] = (r + 1) * (sides + 1);
  }
  const grid = { polylines: countryGrid(16, 6) };
  return [
    [{ points }, undefined],
    [{ polylines: { coords, offsets } }, undefined],
    [{ polylines: { coords, offsets } }, { keep: 'inside' }],
    [grid, undefined],
  ];
}

// A k x k grid of cells whose rings share their borders, as neighbouring countries' do: the
// points of a shared side are duplicates and its segments overlap; on the sides between
// columns the cell on the left has twice the points of the one on the right, so that points
// lie on the other ring's segments (T-junctions). Real borders take these paths, which the
// random rings do not reach; left cold, they were compiled and run in baseline code during a
// caller's first call on country rings (bench/EXPERIMENTS.md, F22).
function countryGrid(k, m) {
  const rings = [];
  const side = (x0, y0, x1, y1, n) => {
    const out = [];
    for (let t = 0; t < n; t++) out.push(x0 + ((x1 - x0) * t) / n, y0 + ((y1 - y0) * t) / n);
    return out;
  };
  for (let i = 0; i < k; i++) {
    for (let j = 0; j < k; j++) {
      const x0 = i / k, x1 = (i + 1) / k, y0 = j / k, y1 = (j + 1) / k;
      rings.push([
        ...side(x0, y0, x1, y0, m), ...side(x1, y0, x1, y1, 2 * m),
        ...side(x1, y1, x0, y1, m), ...side(x0, y1, x0, y0, m), x0, y0,
      ]);
    }
  }
  // Lines a hair off the grid's diagonals, which cross its sides right next to its corners.
  const diagonals = [[0, 1e-13, 1, 1 + 1e-13], [1e-13, 1, 1 + 1e-13, 0]];
  return [...rings, ...diagonals];
}

// A batch for triangulatePolygons() that reaches its paths as map tiles and layers do:
// buildings of four corners (no triangulation), triangles, wobbly rings with and without a
// hole, rings of 64 points and more (the spatial order), a bow tie (the general engine); in
// tile integers (the exact integer predicates) or in degrees (the filtered ones).
function polygonWarmUpBatch(next, inTileUnits) {
  const coords = [], ringOffsets = [0], polygonOffsets = [0];
  const unit = inTileUnits ? 4096 : 1;
  const put = (x, y) => coords.push(inTileUnits ? Math.round(x * unit) : x * unit,
    inTileUnits ? Math.round(y * unit) : y * unit);
  const ring = (cx, cy, radius, sides, clockwise) => {
    for (let k = 0; k <= sides; k++) {
      const angle = ((clockwise ? -2 : 2) * Math.PI * (k % sides)) / sides;
      const wobble = radius * (0.75 + 0.25 * Math.sin(3 * angle + cx));
      put(cx + wobble * Math.cos(angle), cy + wobble * Math.sin(angle));
    }
    ringOffsets.push(coords.length / 2);
  };
  const polygon = () => polygonOffsets.push(ringOffsets.length - 1);
  for (let p = 0; p < 400; p++) {
    const cx = next(), cy = next(), r = 0.002 + 0.01 * next();
    const kind = p % 12;
    if (kind < 6) {
      ring(cx, cy, r, 4, false);  // a building
    } else if (kind < 8) {
      ring(cx, cy, r, 3, false);
    } else if (kind < 10) {
      ring(cx, cy, r, 8 + (p % 40), false);
    } else if (kind === 10) {
      ring(cx, cy, 3 * r, 24, false);
      ring(cx, cy, r, 12, true);  // a hole
    } else {
      ring(cx, cy, 5 * r, 64 + (p % 200), false);
    }
    polygon();
  }
  for (const [x, y] of [[0, 0], [0.02, 0.02], [0.02, 0], [0, 0.02], [0, 0]]) put(0.5 + x, 0.5 + y);
  ringOffsets.push(coords.length / 2);
  polygon();
  const Coords = inTileUnits ? Int16Array : Float64Array;
  return {
    coords: Coords.from(coords), ringOffsets: Uint32Array.from(ringOffsets),
    polygonOffsets: Uint32Array.from(polygonOffsets),
  };
}

// A raster of waves and a hill, width x height, with two breaklines across it (one along a
// row, one diagonal, crossing each other) and a no-data hole: the terrain mesher's paths.
function rasterWarmUp(width, height) {
  const heights = new Float64Array(width * height);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      heights[y * width + x] = Math.round(40 * Math.sin(x / 9) * Math.cos(y / 13) + 0.3 * x * y
        / width + 25 * Math.exp(-(((x - width / 2) ** 2) + (y - height / 3) ** 2) / 300));
    }
  }
  for (let y = 20; y < 26; y++) heights.fill(-9999, y * width + 30, y * width + 38);
  const breaklines = [[2, height / 2, width - 3, height / 2], [5, 5, width - 6, height - 7]];
  return { raster: { heights, width, height }, breaklines };
}

// Edits on a Triangulation (Triangulation: the api's class): points removed, moved far and
// moved a little; roads inserted across them, one nudged, one removed.
function editWarmUp(Triangulation, next, size) {
  const t = new Triangulation();
  try {
    const points = new Float64Array(2 * size);
    for (let i = 0; i < points.length; i++) points[i] = next();
    const ids = t.insertPoints(points);
    const roads = [];
    for (let r = 0; r < 12; r++) {
      const road = [];
      for (let k = 0; k < 8; k++) road.push(next(), next());
      roads.push(t.insertPolyline(road));
    }
    const edits = size / 10;
    for (let k = 0; k < edits; k++) t.removePoint(ids[k]);
    for (let k = edits; k < 2 * edits; k++) t.movePoint(ids[k], next(), next());
    const step = 0.2 / Math.sqrt(size);
    for (let k = 2 * edits; k < 3 * edits; k++) {
      const [dx, dy] = [step * (next() - 0.5), step * (next() - 0.5)];
      t.movePoint(ids[k], points[2 * k] + dx, points[2 * k + 1] + dy);
    }
    t.movePoint(roads[0][1], 0.5, 0.5);
    t.removePolyline(1);
    return t.results().triangles.length / 3;
  } finally {
    t.dispose();
  }
}

// Runs the warm-up with the worker's own calls (api: its functions and Triangulation class):
// first a call so small that its time is compiling the functions every call reaches (the
// caller's call then finds them compiled), then calls long enough for the engine to optimise
// them, round after round over every part: triangulate(), triangulatePolygons(), voronoi(),
// triangulateRaster() and edits. Every part is reached in the first round, so a first call
// of any of them made while later rounds run finds its code warmed (part after part, the
// terrain's came 0.7 s after the start, bench/EXPERIMENTS.md, F30). Returns the triangles
// made (with the Voronoi cells' ring points), which the worker reports when it is done (read
// by the tests only).
export function runWarmUp(api, rounds = 3) {
  const { triangulate, triangulatePolygons, voronoi, triangulateRaster, Triangulation } = api;
  let triangles = triangulate({ polylines: [[0, 0, 1, 1, 0, 1, 0, 0], [0.5, -1, 0.5, 2]] },
    { keep: 'inside' }).stats.triangles;
  const inputs = warmUpInputs();
  const next = random(777);
  const batches = [polygonWarmUpBatch(next, true), polygonWarmUpBatch(next, false)];
  // The cells, the terrain and the edits have code of their own that triangulate() does not
  // reach.
  const points = inputs[0][0].points.subarray(0, 2 * 5000);
  const { coords, offsets } = inputs[1][0].polylines;
  const rings = { coords: coords.subarray(0, 2 * offsets[32]), offsets: offsets.subarray(0, 33) };
  const { raster, breaklines } = rasterWarmUp(160, 120);
  for (let round = 0; round < rounds; round++) {
    for (const [input, options] of inputs) triangles += triangulate(input, options).stats.triangles;
    for (const batch of batches) triangles += triangulatePolygons(batch).triangles.length / 3;
    triangles += voronoi({ points }).coords.length / 2;
    triangles += voronoi({ points, polylines: rings }).coords.length / 2;
    triangles += triangulateRaster(raster, { maxError: 2, noData: -9999 }).triangles.length / 3;
    triangles += triangulateRaster(raster, { maxError: 4, breaklines, minAngle: 20,
      decimate: true, noData: -9999 }).triangles.length / 3;
    triangles += editWarmUp(Triangulation, next, 6000);
  }
  return triangles;
}
