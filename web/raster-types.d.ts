// triangulateRaster(): terrain meshes from heightmaps (part of web/index.d.ts).
import type { Coordinates, FlatPolylines } from './index.js';

/** A heightmap: width * height heights, row by row from row 0 (the top of a north-up image). */
export interface Heightmap {
  /** Any numeric typed array (Int16Array, Float32Array, ...) or an array of numbers. */
  heights: Coordinates;
  width: number;
  height: number;
}

/** triangulateRaster()'s options. */
export interface RasterMeshOptions {
  /**
   * Every pixel's height is within this of the mesh's surface at the pixel (default 0: only
   * pixels on the surface to within rounding are left out).
   */
  maxError?: number;
  /**
   * After the greedy insertion, remove the pixels it inserted that later ones made needless:
   * each interior vertex whose removal keeps every pixel within maxError goes (one pass).
   * About 7-17% fewer triangles for the same bound, at 1.3-1.6 times the time (default
   * false). Hull, tile border, breakline and no-data boundary vertices always stay.
   */
  decimate?: boolean;
  /** Stop before the mesh has more triangles than this, largest errors first. */
  maxTriangles?: number;
  /** Stop before the mesh has more vertices than this, largest errors first. */
  maxVertices?: number;
  /**
   * Pixels with this height (and NaN pixels) have no data: the mesh covers the grid cells
   * whose four corners have data, its boundary there made of constrained edges.
   */
  noData?: number;
  /**
   * Polylines kept as chains of constrained edges (the forms triangulate() takes), in the
   * result's coordinates; cut to the raster. Their sources in the result are their indices.
   */
  breaklines?: readonly Coordinates[] | FlatPolylines;
  /** One height per breakline point (all breaklines in order); NaN: read from the raster. */
  breaklineHeights?: Coordinates;
  /**
   * Delaunay refinement to this smallest angle in degrees, [0, 60); its Steiner points take
   * their heights from the raster, and the error bound still holds. Breakline pieces shorter
   * than 1/16 pixel are not split (stats.refineSkipped counts the triangles left below it).
   */
  minAngle?: number;
  /**
   * [minX, minY, maxX, maxY]: pixel (0, 0) lands at (minX, maxY) and pixel (width - 1,
   * height - 1) at (maxX, minY). Without it, points are pixel positions (x the column, y the
   * row).
   */
  bbox?: readonly [number, number, number, number] | Float64Array;
}

/** triangulateRaster()'s counters. */
export interface RasterStats {
  /** The largest error left over every pixel the mesh covers. */
  maxError: number;
  /** Pixels the greedy insertion added. */
  insertions: number;
  /** Of them, the vertices decimate removed again. */
  decimated: number;
  /** Pixel errors computed, rescans included. */
  scannedPixels: number;
  /** Vertices refinement added (minAngle). */
  steinerPoints: number;
  /** Refinements, each followed by insertions where the refined mesh missed the bound. */
  refineRounds: number;
  /**
   * Triangles of the result below minAngle: where breaklines meet each other or the raster's
   * edges at a smaller angle, or run closer than 1/16 pixel (their pieces are not split that
   * fine).
   */
  refineSkipped: number;
  vertices: number;
  triangles: number;
  constraintEdges: number;
  milliseconds: number;
  coreMilliseconds: number;
}

/** A terrain mesh: triangulate()'s layout, with the heights in values. */
export interface RasterMesh {
  /** x, y per vertex: pixel positions, or mapped by bbox. */
  points: Float64Array;
  /** 3 vertex ids per triangle, counter-clockwise with y up (in pixels: with y down). */
  triangles: Uint32Array;
  halfedges: Int32Array;
  /** 1 for each half-edge on a breakline or on the boundary of the area with data. */
  constrained: Uint8Array;
  constraintEdges: Uint32Array;
  sourceOffsets: Uint32Array;
  /** Breakline indices; breaklines.length for the boundary of the area with data. */
  sources: Uint32Array;
  /** The height of each vertex. */
  values: Float64Array;
  stats: RasterStats;
}

/**
 * A triangulated irregular network (TIN) from a heightmap, by greedy insertion of the pixel
 * farthest from the surface (tile by tile once the mesh has 8,000 triangles): vertices on
 * pixel positions, heights in values.
 * @throws TypeError on wrong types; RangeError on a width or height that does not match
 *   heights.length, NaN heights without noData, a negative maxError, a bad bbox or minAngle;
 *   GeocdtError otherwise.
 */
export function triangulateRaster(raster: Heightmap, options?: RasterMeshOptions): RasterMesh;
