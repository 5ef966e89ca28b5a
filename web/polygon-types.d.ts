// triangulatePolygons() and earcut(): polygons for rendering (part of web/index.d.ts).
import type { Coordinates, FillRule, Offsets } from './index.js';

/**
 * Polygons in GeoArrow's polygon layout: ring r is the points ringOffsets[r] ..
 * ringOffsets[r + 1] - 1 (x, y at coords[2i], coords[2i + 1]), and polygon p is the rings
 * polygonOffsets[p] .. polygonOffsets[p + 1] - 1, its shell first. coords may be any numeric
 * typed array, as tile decoders give them (Int16Array, Int32Array, Float32Array, ...). A ring
 * may be closed (its last point repeats its first) or open.
 */
export interface PolygonBatch {
  coords: Coordinates;
  ringOffsets: Offsets;
  polygonOffsets: Offsets;
}

export interface TriangulatePolygonsOptions {
  /** How rings decide inside: 'evenodd' (default) or 'nonzero'. */
  fillRule?: FillRule;
}

export interface PolygonStats {
  /** Polygons in the batch. */
  polygons: number;
  /** Polygons triangulated by the path with no per-polygon setup. */
  smallPath: number;
  /** Polygons sent to the general engine (rings that cross). */
  general: number;
  /** Extra points: where rings cross. */
  crossings: number;
  /** Threads that ran the batch. */
  threads: number;
  /** Time in the core, and in the whole call. */
  coreMilliseconds: number;
  milliseconds: number;
}

export interface PolygonTriangles {
  /**
   * 3 indices per triangle, counter-clockwise with y up (clockwise on a screen whose y runs
   * down, as in tiles). An index below coords.length / 2 is that input point (equal points of
   * one polygon may share one index); coords.length / 2 + i is extra point i.
   */
  triangles: Uint32Array;
  /** x, y of the points added where rings cross; empty for valid polygons. */
  extraPoints: Float64Array;
  /** Polygon p's triangles are triangleOffsets[p] .. triangleOffsets[p + 1] - 1. */
  triangleOffsets: Uint32Array;
  stats: PolygonStats;
}

/**
 * Triangulates every polygon of the batch alone, as the constrained Delaunay triangulation
 * of its rings, keeping the triangles inside them, in one call.
 * @throws TypeError on wrong types; RangeError (naming the polygon and ring, with `polygon`
 *   and `ring` set) on offsets that decrease or run past their arrays, on an odd coords
 *   length, on NaN, ±Infinity or |coordinate| > 1e150; GeocdtError otherwise.
 */
export function triangulatePolygons(
  polygons: PolygonBatch, options?: TriangulatePolygonsOptions): PolygonTriangles;

/** earcut()'s result: vertex indices, with the points added where rings cross. */
export type EarcutTriangles = Uint32Array & {
  /** x, y of the extra points, indexed from data.length / dim on. */
  extraPoints: Float64Array;
};

/**
 * earcut's signature: one polygon, data holding dim numbers a vertex (x and y first), its
 * holes starting at the vertex indices holeIndices. Triangulated as triangulatePolygons()
 * does (even-odd): exact, constrained Delaunay.
 */
export function earcut(
  data: Coordinates, holeIndices?: Offsets | null, dim?: number): EarcutTriangles;
