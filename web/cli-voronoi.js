// geocdt voronoi in.geojson -o out.geojson [--clip rings|hull|xmin,ymin,xmax,ymax] [--lloyd N]
// The cells of a GeoJSON's points clipped to its polygons (or a box, or their hull), written as
// a FeatureCollection with one feature per point.
import { createWriteStream } from 'node:fs';
import { once } from 'node:events';
import { readInput } from './cli-input.js';
import { init, voronoiGeoJSON } from './index.node.js';
import { cellsToGeoJSON } from './voronoi-geojson.js';

export const VORONOI_USAGE = `Usage: geocdt voronoi <in.geojson | -> [-o out.geojson] [options]

The Voronoi cell of every point of a GeoJSON file (Point and MultiPoint positions), clipped to
the inside of its Polygon and MultiPolygon rings, or to a box or the points' convex hull.
Writes a FeatureCollection with one feature per point, in input order: its cell as a
MultiPolygon (null when the cell misses the domain), with the id and properties of the point's
feature. Equal points: the first gets the cell.

Options:
  -o, --output <file>            where to write the cells (default: stdout)
  --clip <rings|hull|x0,y0,x1,y1>  the domain (default: rings when there are polygons, else the
                                 points' bounding box)
  --fill-rule <evenodd|nonzero>  how rings decide inside (default: evenodd)
  --lloyd <steps>                move each point to its cell's centroid this many times first
  --lloyd-tolerance <distance>   stop relaxing once no point moves farther
  --threads <n|auto>             threads for the points (default 1; auto: the cores, at most 8)
  --stats                        print statistics to stderr
  -h, --help                     show this help`;

export class VoronoiUsageError extends Error {}

function parseArgs(argv) {
  const args = { input: null, output: null, options: {}, threads: 1, stats: false };
  const value = (i, flag) => {
    if (i + 1 >= argv.length) throw new VoronoiUsageError(`${flag} needs a value`);
    return argv[i + 1];
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '-h' || a === '--help') args.help = true;
    else if (a === '-o' || a === '--output') args.output = value(i++, a);
    else if (a === '--clip') args.options.clip = clipOf(value(i++, a));
    else if (a === '--fill-rule') args.options.fillRule = value(i++, a);
    else if (a === '--lloyd') {
      args.options.lloyd = { ...args.options.lloyd, iterations: Number(value(i++, a)) };
    } else if (a === '--lloyd-tolerance') {
      args.options.lloyd = { ...args.options.lloyd, tolerance: Number(value(i++, a)) };
    } else if (a === '--threads') args.threads = value(i++, a);
    else if (a === '--stats') args.stats = true;
    else if (a.startsWith('-') && a !== '-') throw new VoronoiUsageError(`unknown option ${a}`);
    else if (args.input === null) args.input = a;
    else throw new VoronoiUsageError(`unexpected argument ${a}`);
  }
  if (!args.help && args.input === null) throw new VoronoiUsageError('no input file');
  if (args.threads !== 'auto') args.threads = Number(args.threads);
  return args;
}

function clipOf(text) {
  if (text === 'rings' || text === 'hull') return text;
  const box = text.split(',').map(Number);
  if (box.length !== 4 || box.some((v) => Number.isNaN(v))) {
    throw new VoronoiUsageError(`--clip must be rings, hull or xmin,ymin,xmax,ymax, not ${text}`);
  }
  return box;
}

// Feature by feature, so that no string of the whole collection is ever made.
async function write(collection, stream) {
  const chunk = [];
  const flush = async () => {
    if (!stream.write(chunk.join(''))) await once(stream, 'drain');
    chunk.length = 0;
  };
  chunk.push('{"type":"FeatureCollection","features":[');
  const { features } = collection;
  for (let i = 0; i < features.length; i++) {
    chunk.push(i === 0 ? '' : ',', JSON.stringify(features[i]));
    if (chunk.length >= 2048) await flush();
  }
  chunk.push(']}\n');
  await flush();
}

export async function voronoiCommand(argv) {
  const args = parseArgs(argv);
  if (args.help) {
    console.log(VORONOI_USAGE);
    return;
  }
  const loaded = init({ threads: args.threads });
  loaded.catch(() => {});
  const text = await readInput(args.input);
  let geojson;
  try {
    geojson = JSON.parse(text);
  } catch (error) {
    throw new Error(`${args.input} is not valid JSON: ${error.message}`, { cause: error });
  }
  await loaded;
  const cells = voronoiGeoJSON(geojson, { ...args.options, output: 'arrays' });
  const stream = args.output ? createWriteStream(args.output) : process.stdout;
  await write(cellsToGeoJSON(cells), stream);
  if (stream !== process.stdout) {
    stream.end();
    await once(stream, 'finish');
  }
  if (args.stats) {
    const stats = { ...cells.stats, ...(cells.lloyd && { lloydIterations: cells.lloyd.iterations,
      lloydMovement: cells.lloyd.movement }) };
    const lines = Object.entries(stats).map(([k, v]) =>
      `  ${k.padEnd(16)} ${Number.isInteger(v) ? v.toLocaleString('en-US') : v.toPrecision(6)}`);
    process.stderr.write(`geocdt voronoi statistics:\n${lines.join('\n')}\n`);
  }
}
