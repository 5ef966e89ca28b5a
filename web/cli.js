#!/usr/bin/env node
// geocdt in.geojson -o out.geojson [--keep inside | --per-feature] [--stats]
// geocdt dem.asc -o tin.geojson --max-error 1 [--min-angle 20] [--breaklines lines.geojson]
// geocdt voronoi in.geojson -o out.geojson [--clip rings|hull|x0,y0,x1,y1] (cli-voronoi.js)
import { readFile } from 'node:fs/promises';
import { createWriteStream } from 'node:fs';
import { once } from 'node:events';
import { readInput } from './cli-input.js';
import {
  geoJSONToInput, init, triangulate, triangulatePolygons, triangulateRaster,
} from './index.node.js';
import {
  featureFillResult, featurePolygons, geoJSONResult, readGeoJSON,
} from './geojson.js';
import { writeGeoJSON } from './geojson-writer.js';
import { ProgressDisplay } from './progress-display.js';
import { isRasterFile, readRasterFile } from './raster-file.js';
import { VoronoiUsageError, voronoiCommand } from './cli-voronoi.js';

const USAGE = `Usage: geocdt <in.geojson | -> [-o out.geojson] [options]
       geocdt <dem.asc | dem.npy | dem.npz> [-o out.geojson] [terrain options]
       geocdt voronoi <in.geojson | -> [-o out.geojson] [options]   (geocdt voronoi --help)

Triangulates a GeoJSON file: Point/MultiPoint become vertices, LineString/MultiLineString
become constrained edges, Polygon/MultiPolygon rings become constrained edges that bound
the inside. Writes a FeatureCollection with one Polygon per triangle (to stdout without -o):
each triangle has the id and properties of the feature whose polygon holds it (the innermost
where polygons nest), or properties null outside every polygon; positions keep their z.
Coordinates are triangulated in the plane as given (lon/lat or projected).

Options:
  -o, --output <file>        where to write the triangles (default: stdout)
  --keep <all|inside>        keep every triangle, or only those inside the rings (default: all)
  --fill-rule <evenodd|nonzero>  how rings decide inside (default: evenodd)
  --per-feature              fill each polygon of each feature alone, as renderers do (inside
                             triangles only; points and lines left out; not with --keep all,
                             --inside-flags or refinement)
  --inside-flags             add inside to every triangle's properties
  --min-angle <degrees>      refine until every kept triangle has angles at least this
  --max-area <area>          refine until every kept triangle has at most this area
  --max-steiner <count>      stop refining after this many added vertices
  --threads <n|auto>         threads for the points (default 1; auto: the cores, at most 8)
  --stats                    print statistics to stderr
  --quiet                    no progress (a bar on a terminal, lines otherwise)
  -h, --help                 show this help
  -v, --version              show the version

Terrain: a heightmap (an ESRI ASCII grid, or a NumPy array of rows) becomes a triangulated
irregular network whose every cell centre is within --max-error of it: triangles with x, y, z
positions (an ASCII grid's coordinates, else --bbox, else column and row).
  --max-error <height>       the largest error allowed at any cell (default 0)
  --max-triangles <count>    stop before more triangles, largest errors first
  --max-vertices <count>     stop before more vertices, largest errors first
  --no-data <height>         cells of this height (and NaN) are left out (an ASCII grid's
                             NODATA_value by default)
  --breaklines <file>        GeoJSON lines kept as edges (their z, where given, as heights)
  --bbox <minX,minY,maxX,maxY>  where the first and last cell centres lie
  --min-angle <degrees>      refine to this smallest angle, heights read from the raster
  --decimate                 remove the inserted vertices the bound no longer needs`;

// Inputs at least this big report progress on stderr: a bar on a terminal, lines otherwise.
const BIG_INPUT_POINTS = 200_000;

class UsageError extends Error {}

function parseArgs(argv) {
  const args = {
    input: null, output: null, keep: null, fillRule: 'evenodd', insideFlags: false,
    perFeature: false,
    stats: false, quiet: false, refine: null, threads: 1, terrain: {}, breaklines: null,
  };
  const terrainNumber = (what, text, flag) => {
    const v = Number(text);
    if (text.trim() === '' || Number.isNaN(v) && text.toLowerCase() !== 'nan') {
      throw new UsageError(`${flag} must be a number, not ${text}`);
    }
    args.terrain[what] = v;
  };
  const refine = (what, text) => {
    args.refine ??= {};
    args.refine[what] = Number(text);
  };
  const value = (i, flag) => {
    if (i + 1 >= argv.length) throw new UsageError(`${flag} needs a value`);
    return argv[i + 1];
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '-h' || a === '--help') args.help = true;
    else if (a === '-v' || a === '--version') args.version = true;
    else if (a === '-o' || a === '--output') args.output = value(i++, a);
    else if (a === '--keep') args.keep = value(i++, a);
    else if (a === '--fill-rule') args.fillRule = value(i++, a);
    else if (a === '--inside-flags') args.insideFlags = true;
    else if (a === '--per-feature') args.perFeature = true;
    else if (a === '--min-angle') refine('minAngle', value(i++, a));
    else if (a === '--max-area') refine('maxArea', value(i++, a));
    else if (a === '--max-steiner') refine('maxSteinerPoints', value(i++, a));
    else if (a === '--threads') args.threads = value(i++, a);
    else if (a === '--max-error') terrainNumber('maxError', value(i++, a), a);
    else if (a === '--max-triangles') terrainNumber('maxTriangles', value(i++, a), a);
    else if (a === '--max-vertices') terrainNumber('maxVertices', value(i++, a), a);
    else if (a === '--no-data') terrainNumber('noData', value(i++, a), a);
    else if (a === '--breaklines') args.breaklines = value(i++, a);
    else if (a === '--decimate') args.terrain.decimate = true;
    else if (a === '--bbox') {
      const bbox = value(i++, a).split(',').map(Number);
      if (bbox.length !== 4) throw new UsageError('--bbox takes minX,minY,maxX,maxY');
      args.terrain.bbox = bbox;
    }
    else if (a === '--stats') args.stats = true;
    else if (a === '--quiet') args.quiet = true;
    else if (a.startsWith('-') && a !== '-') throw new UsageError(`unknown option ${a}`);
    else if (args.input === null) args.input = a;
    else throw new UsageError(`unexpected argument ${a}`);
  }
  if (!args.help && !args.version && args.input === null) throw new UsageError('no input file');
  if (args.keep !== null && !['all', 'inside'].includes(args.keep)) {
    throw new UsageError(`--keep must be all or inside, not ${args.keep}`);
  }
  if (args.perFeature && (args.keep === 'all' || args.insideFlags || args.refine !== null)) {
    throw new UsageError('--per-feature keeps the inside of each polygon alone: it takes no '
      + '--keep all, --inside-flags, --min-angle, --max-area or --max-steiner');
  }
  args.keep ??= 'all';
  if (args.threads !== 'auto') {
    const threads = Number(args.threads);
    if (!Number.isInteger(threads) || threads < 1 || threads > 64) {
      throw new UsageError(`--threads must be auto or a number from 1 to 64, not ${args.threads}`);
    }
    args.threads = threads;
  }
  if (!['evenodd', 'nonzero'].includes(args.fillRule)) {
    throw new UsageError(`--fill-rule must be evenodd or nonzero, not ${args.fillRule}`);
  }
  return args;
}

const n = (x) => x.toLocaleString('en-US');

async function main(argv) {
  const args = parseArgs(argv);
  if (args.help) {
    console.log(USAGE);
    return;
  }
  if (args.version) {
    const pkg = JSON.parse(await readFile(new URL('../package.json', import.meta.url), 'utf8'));
    console.log(pkg.version);
    return;
  }
  if (isRasterFile(args.input)) {
    await terrain(args);
    return;
  }
  const started = performance.now();
  const elapsed = () => `${((performance.now() - started) / 1000).toFixed(2)} s`;
  let say = () => {};
  let show = null;

  // Loading first lets the warm-up (init()'s worker) run while the input is read and parsed.
  const loaded = init({ threads: args.threads });
  loaded.catch(() => {});  // awaited below, after the input is read
  const text = await readInput(args.input);
  let geojson;
  try {
    geojson = JSON.parse(text);
  } catch (error) {
    throw new Error(`${args.input} is not valid JSON: ${error.message}`, { cause: error });
  }
  const input = readGeoJSON(geojson);
  const lines = input.polylines.offsets.length - 1;
  const pointCount = input.points.length / 2 + input.polylines.offsets[lines];
  if (!args.quiet && pointCount >= BIG_INPUT_POINTS) {
    const display = new ProgressDisplay(process.stderr);
    say = (message) => display.line(message);
    show = (label, fraction) => display.update(label, fraction);
  }
  say(`read ${n(pointCount)} points (${n(lines)} polylines) in ${elapsed()}`);

  await loaded;
  let mesh;
  if (args.perFeature) {
    const batch = featurePolygons(input);
    const filled = triangulatePolygons(batch, { fillRule: args.fillRule });
    mesh = featureFillResult(filled, batch, input, 'arrays');
  } else {
    mesh = triangulate(input, {
      keep: args.keep,
      fillRule: args.fillRule,
      insideFlags: args.insideFlags,
      refine: args.refine ?? undefined,
      onProgress: show && (({ phase, fraction }) => show(`triangulating: ${phase}`, fraction)),
    });
    geoJSONResult(mesh, input, 'arrays', {});  // the features of the regions
    if (!args.insideFlags) delete mesh.inside;  // --keep inside alone adds no property
  }
  const ms = mesh.stats.milliseconds.toFixed(0);
  say(`triangulated: ${n(mesh.triangles.length / 3)} triangles in ${ms} ms`);

  const stream = args.output ? createWriteStream(args.output) : process.stdout;
  await writeGeoJSON(mesh, stream, (done, total) => show?.('writing', done / total));
  if (stream !== process.stdout) {
    stream.end();
    await once(stream, 'finish');
  }
  say(`done in ${elapsed()}`);

  if (args.stats) printStats(mesh.stats);
}

function printStats(stats) {
  const lines = Object.entries(stats).map(([k, v]) =>
    `  ${k.padEnd(16)} ${Number.isInteger(v) ? n(v) : v.toFixed(1)}`);
  process.stderr.write(`geocdt statistics:\n${lines.join('\n')}\n`);
}

// A heightmap in, a TIN out: triangles with x, y, z positions.
async function terrain(args) {
  const loaded = init({ threads: args.threads });
  loaded.catch(() => {});
  const raster = readRasterFile(await readFile(args.input), args.input);
  const options = { ...args.terrain };
  if (options.noData === undefined && raster.noData !== undefined) options.noData = raster.noData;
  if (options.bbox === undefined && raster.bbox !== undefined) options.bbox = raster.bbox;
  if (args.refine?.minAngle !== undefined) options.minAngle = args.refine.minAngle;
  if (args.breaklines !== null) {
    const lines = geoJSONToInput(JSON.parse(await readFile(args.breaklines, 'utf8')));
    options.breaklines = lines.polylines;
    if (lines.values !== undefined) {
      options.breaklineHeights = lines.values.subarray(lines.points.length / 2);
    }
  }
  await loaded;
  const mesh = triangulateRaster(raster, options);
  const stream = args.output ? createWriteStream(args.output) : process.stdout;
  await writeGeoJSON(mesh, stream, () => {});
  if (stream !== process.stdout) {
    stream.end();
    await once(stream, 'finish');
  }
  if (args.stats) printStats(mesh.stats);
}

const argv = process.argv.slice(2);
const command = argv[0] === 'voronoi' ? voronoiCommand(argv.slice(1)) : main(argv);
command.catch((error) => {
  const usage = error instanceof UsageError || error instanceof VoronoiUsageError;
  const help = argv[0] === 'voronoi' ? 'geocdt voronoi --help' : 'geocdt --help';
  const hint = usage ? `Try ${help}\n` : '';
  process.stderr.write(`geocdt: ${error.message.replace(/^geocdt: /, '')}\n${hint}`);
  process.exitCode = usage ? 2 : 1;
});
