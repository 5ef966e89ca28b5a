// triangulateGeoJSON() and the GeoJSON helpers: features in, triangles as features or arrays
// out (part of web/index.d.ts).
import type { FillRule, Mesh, TriangulateOptions, TriangulateResult } from './index.js';
import type { PolygonStats } from './polygon-types.js';

export type GeoJSONOutput = 'geojson' | 'arrays';

export interface GeoJSONOptions extends TriangulateOptions {
  /** 'geojson' (default): a FeatureCollection of triangles; 'arrays': the typed arrays. */
  output?: GeoJSONOutput;
  /** false (default): everything triangulated together. See FeatureFillOptions for true. */
  perFeature?: false;
}

/**
 * triangulateGeoJSON() with perFeature: true: each Polygon of each feature (each part of a
 * MultiPolygon, with its holes) filled alone, as triangulatePolygons() fills a polygon, inside
 * triangles only, each triangle labelled with its feature. Points and lines are left out.
 */
export interface FeatureFillOptions {
  perFeature: true;
  fillRule?: FillRule;
  /** Only 'inside', which is what it does anyway. */
  keep?: 'inside';
  /** 'geojson' (default): a FeatureCollection of triangles; 'arrays': FeatureFillResult. */
  output?: GeoJSONOutput;
}

/** triangulateGeoJSON() with perFeature: true and output: 'arrays'. */
export interface FeatureFillResult {
  /** x, y: the rings' points, feature by feature, then the points added where rings cross. */
  points: Float64Array;
  /** 3 indices into points a triangle, counter-clockwise with y up. */
  triangles: Uint32Array;
  /** Feature k's triangles (k indexes regionFeatures) are triangleOffsets[k] .. [k + 1] - 1. */
  triangleOffsets: Uint32Array;
  /** Each triangle's feature: regionFeatures[regions[t]]. */
  regions: Int32Array;
  /** The features with rings, in input order (null for a bare geometry). */
  regionFeatures: (GeoJSONFeature | null)[];
  /** When some position has a z: the height of each point, NaN where none (added points). */
  values?: Float64Array;
  stats: PolygonStats;
}

/** A GeoJSON position: x, y and, when the input had one, z. */
export type Position = [number, number] | [number, number, number];

export interface TriangleFeature {
  type: 'Feature';
  /**
   * triangulateGeoJSON(): the id of the feature whose polygon holds the triangle, absent when
   * it has none or no polygon holds the triangle. meshToGeoJSON() of a mesh without
   * regionFeatures: the triangle's index.
   */
  id?: string | number;
  /**
   * triangulateGeoJSON(): that feature's properties (the same object for all its triangles),
   * null outside every polygon; with insideFlags: true, a copy with `inside` added.
   * meshToGeoJSON() of a mesh without regionFeatures: `inside` and `region` when the mesh has
   * them.
   */
  properties: { [key: string]: unknown } | null;
  geometry: { type: 'Polygon'; coordinates: [Position[]] };
}

export interface TriangleFeatureCollection {
  type: 'FeatureCollection';
  features: TriangleFeature[];
}

/** Any GeoJSON object: FeatureCollection, Feature or geometry. */
export type GeoJSONInput = { type: string; [key: string]: unknown };

/** A GeoJSON Feature of the input. */
export type GeoJSONFeature = {
  type: 'Feature';
  id?: string | number;
  properties?: { [key: string]: unknown } | null;
  [key: string]: unknown;
};

/** triangulateGeoJSON() with output: 'arrays'. */
export interface GeoJSONResult extends TriangulateResult {
  /**
   * The input feature of each region (regions[t] indexes it; null for a bare geometry); one
   * region per feature with Polygon or MultiPolygon rings, in the order of the features.
   */
  regionFeatures: (GeoJSONFeature | null)[];
}

/**
 * Triangulates GeoJSON: Point and MultiPoint give points, LineString and MultiLineString give
 * constraints, Polygon and MultiPolygon rings give constraints that bound the inside; each
 * feature with rings is a region, whose id and properties its triangles carry, and positions
 * keep their z. Coordinates are used as given (lon/lat or projected) and triangulated in the
 * plane.
 */
export function triangulateGeoJSON(
  geojson: GeoJSONInput, options: FeatureFillOptions & { output?: 'geojson' },
): TriangleFeatureCollection;
export function triangulateGeoJSON(
  geojson: GeoJSONInput, options: FeatureFillOptions & { output: 'arrays' }): FeatureFillResult;
export function triangulateGeoJSON(
  geojson: GeoJSONInput, options?: TriangulateOptions & { output?: 'geojson'; perFeature?: false },
): TriangleFeatureCollection;
export function triangulateGeoJSON(
  geojson: GeoJSONInput, options: TriangulateOptions & { output: 'arrays'; perFeature?: false },
): GeoJSONResult;
export function triangulateGeoJSON(
  geojson: GeoJSONInput, options?: GeoJSONOptions | FeatureFillOptions,
): TriangleFeatureCollection | GeoJSONResult | FeatureFillResult;

/** What geoJSONToInput() returns besides the polylines. */
export interface GeoJSONInputParts {
  points: Float64Array;
  /** One polygon per feature with rings; the rings come first among the polylines. */
  polygons?: Uint32Array;
  /** The feature of each polygon (null for a bare geometry). */
  regionFeatures?: (GeoJSONFeature | null)[];
  /** A height per input point, when some position has a third coordinate (NaN: none). */
  values?: Float64Array;
}

/**
 * GeoJSON -> the input of triangulate(); rings are closed if they are not. With flat: true
 * the polylines come in the flat form (no array per polyline), as triangulateGeoJSON() uses.
 */
export function geoJSONToInput(
  geojson: GeoJSONInput,
  options?: { flat?: false },
): GeoJSONInputParts & { polylines: Float64Array[] };
export function geoJSONToInput(
  geojson: GeoJSONInput,
  options: { flat: true },
): GeoJSONInputParts & { polylines: { coords: Float64Array; offsets: Uint32Array } };

/**
 * A mesh -> a FeatureCollection with one counter-clockwise Polygon per triangle (its id and
 * properties: see TriangleFeature); positions get the mesh's first value per vertex as z,
 * where it is not NaN.
 */
export function meshToGeoJSON(
  mesh: Mesh & { regionFeatures?: (GeoJSONFeature | null)[] },
): TriangleFeatureCollection;
