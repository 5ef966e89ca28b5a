#!/usr/bin/env node
// geocdt in.geojson -o out.geojson [--keep inside] [--stats]
// geocdt voronoi in.geojson -o out.geojson [--clip rings|hull|x0,y0,x1,y1] (cli-voronoi.js)
import { readFile } from 'node:fs/promises';
import { createWriteStream } from 'node:fs';
import { once } from 'node:events';
import { geoJSONToInput, init, triangulate } from './index.node.js';
import { geoJSONResult } from './geojson.js';
import { writeGeoJSON } from './geojson-writer.js';
import { ProgressDisplay } from './progress-display.js';
import { VoronoiUsageError, voronoiCommand } from './cli-voronoi.js';

const USAGE = `Usage: geocdt <in.geojson | -> [-o out.geojson] [options]
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
  --inside-flags             add inside to every triangle's properties
  --min-angle <degrees>      refine until every kept triangle has angles at least this
  --max-area <area>          refine until every kept triangle has at most this area
  --max-steiner <count>      stop refining after this many added vertices
  --threads <n|auto>         threads for the points (default 1; auto: the cores, at most 8)
  --stats                    print statistics to stderr
  --quiet                    no progress (a bar on a terminal, lines otherwise)
  -h, --help                 show this help
  -v, --version              show the version`;

// Inputs at least this big report progress on stderr: a bar on a terminal, lines otherwise.
const BIG_INPUT_POINTS = 200_000;

class UsageError extends Error {}

function parseArgs(argv) {
  const args = {
    input: null, output: null, keep: 'all', fillRule: 'evenodd', insideFlags: false,
    stats: false, quiet: false, refine: null, threads: 1,
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
    else if (a === '--min-angle') refine('minAngle', value(i++, a));
    else if (a === '--max-area') refine('maxArea', value(i++, a));
    else if (a === '--max-steiner') refine('maxSteinerPoints', value(i++, a));
    else if (a === '--threads') args.threads = value(i++, a);
    else if (a === '--stats') args.stats = true;
    else if (a === '--quiet') args.quiet = true;
    else if (a.startsWith('-') && a !== '-') throw new UsageError(`unknown option ${a}`);
    else if (args.input === null) args.input = a;
    else throw new UsageError(`unexpected argument ${a}`);
  }
  if (!args.help && !args.version && args.input === null) throw new UsageError('no input file');
  if (!['all', 'inside'].includes(args.keep)) {
    throw new UsageError(`--keep must be all or inside, not ${args.keep}`);
  }
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

async function readInput(path) {
  if (path !== '-') return readFile(path, 'utf8');
  const chunks = [];
  for await (const chunk of process.stdin) chunks.push(chunk);
  return Buffer.concat(chunks).toString('utf8');
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
  const input = geoJSONToInput(geojson, { flat: true });
  const lines = input.polylines.offsets.length - 1;
  const pointCount = input.points.length / 2 + input.polylines.offsets[lines];
  if (!args.quiet && pointCount >= BIG_INPUT_POINTS) {
    const display = new ProgressDisplay(process.stderr);
    say = (message) => display.line(message);
    show = (label, fraction) => display.update(label, fraction);
  }
  say(`read ${n(pointCount)} points (${n(lines)} polylines) in ${elapsed()}`);

  await loaded;
  const mesh = triangulate(input, {
    keep: args.keep,
    fillRule: args.fillRule,
    insideFlags: args.insideFlags,
    refine: args.refine ?? undefined,
    onProgress: show && (({ phase, fraction }) => show(`triangulating: ${phase}`, fraction)),
  });
  geoJSONResult(mesh, input, 'arrays', {});  // the features of the regions
  if (!args.insideFlags) delete mesh.inside;  // --keep inside alone adds no property
  const ms = mesh.stats.milliseconds.toFixed(0);
  say(`triangulated: ${n(mesh.triangles.length / 3)} triangles in ${ms} ms`);

  const stream = args.output ? createWriteStream(args.output) : process.stdout;
  await writeGeoJSON(mesh, stream, (done, total) => show?.('writing', done / total));
  if (stream !== process.stdout) {
    stream.end();
    await once(stream, 'finish');
  }
  say(`done in ${elapsed()}`);

  if (args.stats) {
    const lines = Object.entries(mesh.stats).map(([k, v]) =>
      `  ${k.padEnd(16)} ${Number.isInteger(v) ? n(v) : v.toFixed(1)}`);
    process.stderr.write(`geocdt statistics:\n${lines.join('\n')}\n`);
  }
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
