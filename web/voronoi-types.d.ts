// voronoi() and its GeoJSON forms: cells clipped to a domain (part of web/index.d.ts).
import type { Coordinates, FillRule, FlatPolylines, GeoJSONFeature, GeoJSONInput, GeoJSONOutput } from './index.js';

/** Input of voronoi(): the sites, and the rings that bound the domain. */
export interface VoronoiInput {
  /** The sites: x0, y0, x1, y1, … (at least one). */
  points: Coordinates;
  /** Rings (a polyline ending where it starts) bounding the domain, as triangulate() takes. */
  polylines?: Coordinates[] | FlatPolylines;
}

/** What voronoi() clips the cells to. */
export type VoronoiClip = 'rings' | 'hull' | readonly [number, number, number, number];

export interface LloydOptions {
  /** At most this many relaxation steps (default 10). */
  iterations?: number;
  /** Stop once no site moved farther than this in a step (default 0: take every step). */
  tolerance?: number;
}

export interface VoronoiOptions {
  /**
   * 'rings' (the default with polylines): the inside of the rings by fillRule; 'hull': the
   * sites' convex hull; [xmin, ymin, xmax, ymax]: a box (the default without polylines is the
   * sites' bounding box).
   */
  clip?: VoronoiClip;
  /** How the rings decide inside, as in triangulate() (default 'evenodd'). */
  fillRule?: FillRule;
  /**
   * Lloyd's relaxation: each step moves every site to the centroid of its clipped cell (a site
   * with an empty cell stays); the cells returned are those of the final sites. true: 10 steps.
   */
  lloyd?: boolean | LloydOptions;
}

export interface VoronoiStats {
  /** Sites given. */
  sites: number;
  polygons: number;
  rings: number;
  /** Area of the domain (the inside of the rings, the hull or the box), in doubles. */
  domainArea: number;
  /** Where the domain's boundary crosses the edges of cells. */
  crossings: number;
  /** Cells that the domain's boundary enters (the others are whole or empty). */
  clippedCells: number;
  /** Threads that triangulated the sites (init({ threads }), large inputs). */
  threads: number;
  milliseconds: number;
  coreMilliseconds: number;
}

/**
 * Each site's cell as a GeoArrow MultiPolygon: site i has the polygons siteOffsets[i] ..
 * siteOffsets[i + 1] - 1, polygon p the rings polygonOffsets[p] .. polygonOffsets[p + 1] - 1
 * (the first its outer ring, counter-clockwise; the others its holes, clockwise), ring r the
 * points ringOffsets[r] .. ringOffsets[r + 1] - 1 of coords (x, y pairs), closed.
 */
export interface VoronoiCells {
  coords: Float64Array;
  ringOffsets: Uint32Array;
  polygonOffsets: Uint32Array;
  siteOffsets: Uint32Array;
  /** With lloyd: where the sites ended, x, y per site. */
  points?: Float64Array;
  /** With lloyd: the steps taken and how far the farthest site moved in the last one. */
  lloyd?: { iterations: number; movement: number };
  stats: VoronoiStats;
}

/**
 * The Voronoi cell of each site clipped to the domain: the part of the domain nearer to that
 * site than to any other. Equal sites: the first one gets the cell, the others an empty one; a
 * site outside the domain gets the part of its cell inside it (empty when none).
 * @throws TypeError on wrong types; RangeError with no sites, a bad clip box, NaN, ±Infinity
 *   or |coordinate| > 1e150; GeocdtError otherwise ('OutOfMemory', 'InternalError',
 *   'NotLoaded', 'Busy').
 */
export function voronoi(input: VoronoiInput, options?: VoronoiOptions): VoronoiCells;

export interface CellFeature {
  type: 'Feature';
  /** The site's feature's id (voronoiGeoJSON()), or the site's index (cellsToGeoJSON()). */
  id?: string | number;
  /** The site's feature's properties, the same object; {} from cellsToGeoJSON() alone. */
  properties: { [key: string]: unknown } | null;
  /** The cell; null when it is empty. */
  geometry: { type: 'MultiPolygon'; coordinates: [number, number][][][] } | null;
}

export interface CellFeatureCollection {
  type: 'FeatureCollection';
  /** One per site, in site order. */
  features: CellFeature[];
}

/** voronoiGeoJSON() with output: 'arrays'. */
export interface VoronoiGeoJSONResult extends VoronoiCells {
  /** The feature of each site (null for a bare geometry). */
  siteFeatures: (GeoJSONFeature | null)[];
}

/**
 * voronoi() on GeoJSON: Point and MultiPoint positions are the sites (each keeping its
 * feature), Polygon and MultiPolygon rings bound the domain.
 */
export function voronoiGeoJSON(
  geojson: GeoJSONInput, options?: VoronoiOptions & { output?: 'geojson' },
): CellFeatureCollection;
export function voronoiGeoJSON(
  geojson: GeoJSONInput, options: VoronoiOptions & { output: 'arrays' }): VoronoiGeoJSONResult;
export function voronoiGeoJSON(
  geojson: GeoJSONInput, options?: VoronoiOptions & { output?: GeoJSONOutput },
): CellFeatureCollection | VoronoiGeoJSONResult;

/** voronoi()'s cells -> a FeatureCollection, one MultiPolygon (or null) per site. */
export function cellsToGeoJSON(
  cells: VoronoiCells & { siteFeatures?: (GeoJSONFeature | null)[] },
): CellFeatureCollection;
