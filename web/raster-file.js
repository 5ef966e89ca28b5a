// Heightmap files for the CLI: ESRI ASCII grids (.asc: a header, then rows of numbers from the
// north) and NumPy arrays (.npy, or the first two-dimensional array of an .npz), as
// triangulateRaster() takes them: { heights, width, height, bbox?, noData? }. An ASCII grid's
// bbox is the extent of its cell centres (the pixel positions of the mesh).
import { readNpy, readNpz } from './npy.js';

// A two-dimensional array: rows, then columns.
function fromArray({ data, shape }, name) {
  if (shape.length !== 2) {
    throw new Error(`${name} has ${shape.length} dimensions; a raster has 2 (rows, columns)`);
  }
  return { heights: data, width: shape[1], height: shape[0] };
}

function readAsciiGrid(text, name) {
  const header = {};
  let at = 0;
  // Header lines are a key and a number; the first line that starts with a number is data.
  for (;;) {
    const end = text.indexOf('\n', at);
    const line = text.slice(at, end < 0 ? text.length : end).trim();
    const match = /^([A-Za-z_]+)\s+(\S+)$/.exec(line);
    if (!match) break;
    header[match[1].toLowerCase()] = Number(match[2]);
    at = end < 0 ? text.length : end + 1;
  }
  const width = header.ncols, height = header.nrows;
  if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
    throw new Error(`${name}: an ASCII grid needs ncols and nrows in its header`);
  }
  const heights = new Float64Array(width * height);
  const numbers = text.slice(at).split(/\s+/).filter((t) => t !== '');
  if (numbers.length !== heights.length) {
    throw new Error(`${name}: ${numbers.length} numbers for ${width} x ${height} cells`);
  }
  for (let i = 0; i < numbers.length; i++) heights[i] = Number(numbers[i]);
  const raster = { heights, width, height };
  const dx = header.cellsize ?? header.dx, dy = header.cellsize ?? header.dy;
  const corner = header.xllcorner !== undefined;
  const x0 = corner ? header.xllcorner + dx / 2 : header.xllcenter;
  const y0 = corner ? header.yllcorner + dy / 2 : header.yllcenter;
  if ([x0, y0, dx, dy].every(Number.isFinite) && dx > 0 && dy > 0) {
    raster.bbox = [x0, y0, x0 + (width - 1) * dx, y0 + (height - 1) * dy];
    if (width === 1) raster.bbox[2] = x0 + dx;  // a bbox needs some width, whatever it is
    if (height === 1) raster.bbox[3] = y0 + dy;
  }
  if (header.nodata_value !== undefined) raster.noData = header.nodata_value;
  return raster;
}

// bytes: the file's contents; name: its path (the extension decides the format).
export function readRasterFile(bytes, name) {
  const lower = name.toLowerCase();
  if (lower.endsWith('.npy')) return fromArray(readNpy(bytes, name), name);
  if (lower.endsWith('.npz')) {
    const arrays = readNpz(bytes);
    const entry = Object.entries(arrays).find(([, a]) => a.shape.length === 2);
    if (!entry) throw new Error(`${name} holds no two-dimensional array`);
    return fromArray(entry[1], `${name}:${entry[0]}`);
  }
  if (lower.endsWith('.asc')) return readAsciiGrid(new TextDecoder().decode(bytes), name);
  throw new Error(`${name}: a raster must be an ESRI ASCII grid (.asc) or NumPy (.npy, .npz)`);
}

export function isRasterFile(name) {
  return /\.(asc|npy|npz)$/i.test(name);
}
