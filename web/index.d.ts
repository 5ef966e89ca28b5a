// geocdt: constrained Delaunay triangulation for maps, in WebAssembly. The GeoJSON, polygon,
// terrain and Voronoi calls are declared in the files beside this one, exported from here too.

export * from './geojson-types.js';
export * from './polygon-types.js';
export * from './raster-types.js';
export * from './voronoi-types.js';


/**
 * x0, y0, x1, y1, …: any numeric typed array (BigInt64Array and BigUint64Array aside) or an
 * array of numbers. Typed arrays are copied into the wasm heap with one TypedArray.set().
 */
export type Coordinates =
  | Float64Array | Float32Array
  | Int32Array | Uint32Array | Int16Array | Uint16Array | Int8Array | Uint8Array
  | Uint8ClampedArray
  | readonly number[];

/** Vertex ids: integers from 0 to 2^32 - 1, in any numeric typed array or an array. */
export type Ids = Coordinates;

/** Offsets (n + 1 for n things) in any integer array. */
export type Offsets = Uint32Array | Int32Array | Uint16Array | Uint8Array | readonly number[];

/**
 * Polylines as one flat buffer, in GeoArrow's layout: polyline i has the points
 * offsets[i] .. offsets[i + 1] - 1, whose x, y are coords[2 * offsets[i]] ..
 * coords[2 * offsets[i + 1] - 1]. offsets holds n + 1 entries for n polylines, starts at 0,
 * never decreases and ends at coords.length / 2. No JS array per polyline.
 */
export interface FlatPolylines {
  coords: Coordinates;
  offsets: Offsets;
}

export interface TriangulateInput {
  /** Points to triangulate: x0, y0, x1, y1, … */
  points?: Coordinates;
  /**
   * Polylines whose segments become constrained edges, split where they cross: an array with
   * one coordinate array per polyline, or the flat form. A ring repeats its first point at its
   * end (the GeoJSON convention) and bounds the inside.
   */
  polylines?: readonly Coordinates[] | FlatPolylines;
  /**
   * Polygons, for region labels (the result's `regions`): polygon j has the polylines
   * polygons[j] .. polygons[j + 1] - 1 (either form of polylines). n + 1 offsets for n
   * polygons, never decreasing, at most the number of polylines; polylines outside every
   * polygon still constrain but bound no region.
   */
  polygons?: Offsets;
  /**
   * Values carried by the points (elevation, depth, any attribute): valuesPerPoint numbers per
   * input point (the points, then the polylines' points; NaN: none), carried to the result's
   * `values`. (Earlier versions called one value per point `z`.)
   */
  values?: Coordinates;
}

/** What a long call is doing: sorting points, inserting them, constraints, the arrays out. */
export type ProgressPhase = 'sort' | 'points' | 'constraints' | 'export';

export interface ProgressEvent {
  phase: ProgressPhase;
  /** How far the phase is, 0 to 1. Phases only move forward; a phase's fraction only grows. */
  fraction: number;
}

export interface ProgressOptions {
  /**
   * Called as each phase begins, then at most once per 100 ms within a phase, then once at
   * the end. Costs nothing when absent. An exception it throws ends the
   * reports and is thrown once the call has returned; it may not call geocdt meanwhile.
   */
  onProgress?: (event: ProgressEvent) => void;
}

export type Keep = 'all' | 'inside';
/** 'linear': barycentric in a triangle; 'natural': Sibson's natural neighbours. */
export type Interpolation = 'linear' | 'natural';
export type FillRule = 'evenodd' | 'nonzero';

export interface MeshOptions extends ProgressOptions {
  /** 'all' (default) keeps every triangle; 'inside' only those inside the rings. */
  keep?: Keep;
  /** How rings decide inside: 'evenodd' (default) or 'nonzero' (winding number). */
  fillRule?: FillRule;
  /** Return `inside`, one flag per triangle (implied by keep: 'inside'). */
  insideFlags?: boolean;
  /** Return `segmentOffsets` and `segmentSources`: the input segments of each constrained edge. */
  segmentSources?: boolean;
}

/**
 * Delaunay refinement: Steiner vertices are added until every triangle of the refined part
 * has all its angles at least minAngle and its area at most maxArea, except where two input
 * segments meet at a smaller angle than minAngle (those triangles are counted in
 * stats.refineSkipped). Steiner vertices are listed in the result's `steiner`.
 */
export interface RefineOptions {
  /** Degrees, from 0 to less than 60; default 20. Up to about 20.7 refinement provably ends. */
  minAngle?: number;
  /** Squared input units; absent: no bound. */
  maxArea?: number;
  /**
   * A hard cap on the Steiner vertices of the call; when it ends refinement,
   * stats.refineCapped says so. Default: 64 per vertex plus 4 per maxArea of the refined area
   * plus 1024.
   */
  maxSteinerPoints?: number;
}

export interface TriangulateOptions extends MeshOptions {
  /**
   * Refine the triangulation before export (true: the defaults). With keep: 'inside' only the
   * inside is refined; the outside stays as it is.
   */
  refine?: RefineOptions | boolean;
}

/** The counters of the core (Triangulation.stats). */
export interface CoreStats {
  /** Points that became vertices. */
  inserted: number;
  /** Points equal to an existing vertex. */
  duplicates: number;
  /** Triangles visited by point location, over `locates` locations. */
  walkSteps: number;
  /** Point locations performed. */
  locates: number;
  /** Edge flips that restored the Delaunay property. */
  flips: number;
  /** Walks that hit their step bound and gave way to a scan of every triangle. */
  walkFallbacks: number;
  /** m of the m × m point-location grid. */
  gridSize: number;
  /** Vertices added where constraints cross. */
  crossings: number;
  /** Polylines inserted. */
  polylines: number;
  /** Constraint segments inserted. */
  segments: number;
  /**
   * Times the constraints were snap-rounded, because computed crossings would have moved a
   * constraint beyond the guarantee (tangles of vertices a few ulps apart).
   */
  snapRoundings: number;
  /** Duplicate points whose values differ from those their vertex kept (dropped). */
  valueDuplicates: number;
  /** Crossings whose input segments give different values (they get the mean). */
  valueDisagreements: number;
  /** Steiner vertices added by refinement, over all calls. */
  steinerPoints: number;
  /**
   * Triangles of the refined part that miss minAngle or maxArea after the last refinement:
   * those in corners where input segments meet at a smaller angle (their angle; maxArea holds
   * there too), where rounding left a convex-hull edge unsplittable (keep: 'all'), and what
   * the cap left.
   */
  refineSkipped: number;
  /** 1 when maxSteinerPoints ended the last refinement, else 0. */
  refineCapped: number;
  /**
   * Threads that triangulated the last batch of points: 1 unless init() loaded the threaded
   * build and the batch was large enough for strips (about 16,000 points a thread).
   */
  threads: number;
  /** Vertices removed by edits (removePoint, removePolyline, and what those take along). */
  removed: number;
}

/** triangulate()'s options. */
export interface TriangulateOptions extends MeshOptions {
  /** How many numbers of input.values each point has (default 1). */
  valuesPerPoint?: number;
}

/** The counters of a call: the core's, and what the call returned and took. */
export interface Stats extends CoreStats {
  /** Vertices in the result. */
  vertices: number;
  /** Triangles in the result. */
  triangles: number;
  /** Constrained edges in the result. */
  constraintEdges: number;
  /** Time of the call, checks and copies in and out included. */
  milliseconds: number;
  /** The part of it spent in the wasm core (for results(): building the mesh copy). */
  coreMilliseconds: number;
}

/**
 * A triangulation as plain typed arrays that the caller owns, in delaunator's layout:
 * triangle t has vertices triangles[3t..3t+2], counter-clockwise with y up; half-edge e runs
 * from triangles[e] to triangles[e % 3 === 2 ? e - 2 : e + 1] and belongs to triangle ⌊e/3⌋.
 */
export interface Mesh {
  /** x, y of every vertex: the input points deduplicated, then the crossing points. */
  points: Float64Array;
  /** 3 vertex ids per triangle, counter-clockwise with y up. */
  triangles: Uint32Array;
  /** The twin of each half-edge, or -1 on the boundary. */
  halfedges: Int32Array;
  /** 1 for each half-edge on an input constraint. */
  constrained: Uint8Array;
  /** One half-edge per constrained edge (provenance). */
  constraintEdges: Uint32Array;
  /**
   * Constrained edge i came from the polylines sources[sourceOffsets[i] .. sourceOffsets[i + 1]);
   * sourceOffsets has constraintEdges.length + 1 entries.
   */
  sourceOffsets: Uint32Array;
  /** Polyline indices (the order of `input.polylines`, or of insertPolyline calls). */
  sources: Uint32Array;
  /**
   * With segmentSources: constrained edge i lies on the input segments
   * segmentSources[segmentOffsets[i] .. segmentOffsets[i + 1]); constraintEdges.length + 1
   * entries.
   */
  segmentOffsets?: Uint32Array;
  /**
   * Input segments, numbered across the polylines in order, counting each pair of
   * consecutive points whose vertices differ (inputToVertex): a repeated point, or two points
   * that became one vertex, make no segment.
   */
  segmentSources?: Uint32Array;
  /** 1 for each triangle inside the rings; present with insideFlags or keep: 'inside'. */
  inside?: Uint8Array;
  /**
   * For each triangle, the polygon whose inside holds it, or -1; present when polygons are
   * given. Where several hold it (nested or overlapping), the smallest by area (then by
   * triangle count, then the lower index): where polygons nest, the innermost.
   */
  regions?: Int32Array;
  /**
   * valuesPerPoint values per vertex, when values were given: those of the first input point
   * it came from whose values are not all NaN; where constraints cross, interpolated along
   * each input segment through the vertex (their mean where they differ); NaN for points
   * given without values.
   */
  values?: Float64Array;
  /**
   * Refinement's Steiner vertices, in the order they were added (present after refinement).
   * steiner[i] is a vertex id, placed between the vertices steinerParents[3i..3i+2] (the
   * corners of the triangle it fell in, or the two ends of the edge it split and 0xFFFFFFFF)
   * with the barycentric weights steinerWeights[3i..3i+2] (summing to 1): values given at the
   * parents interpolate linearly to it.
   */
  steiner?: Uint32Array;
  steinerParents?: Uint32Array;
  steinerWeights?: Float64Array;
  /**
   * Triangulation.results() only: the id of each vertex (what the insertions returned and
   * locate() names). Vertex i is id i until vertices are removed; after that the vertices are
   * numbered without gaps here and this maps them back to their ids.
   */
  vertexIds?: Uint32Array;
  stats: Stats;
}

export interface TriangulateResult extends Mesh {
  /** For each input point (points first, then each polyline's points in order), its vertex id. */
  inputToVertex: Uint32Array;
}

export interface ResultsOptions extends MeshOptions {
  /** Polygons as offsets into the polylines inserted so far, for `regions`. */
  polygons?: Offsets;
}

export interface InitOptions {
  /** The wasm bytes, if you load them yourself. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Where to fetch (browser) or read (Node: a path or a file: URL) geocdt.wasm from. */
  wasmUrl?: string | { readonly href: string };
  /**
   * Warm the code up in a worker (default true): once the code that awaited init() waits for
   * something else (its data, say), a worker runs a few small triangulations on the module
   * init() compiled, on another core, and ends. The engine shares the compiled and optimised
   * code, so a first call made 0.3–1 s after init() runs closer to the speed of later ones;
   * a call made at once is not slowed. false starts no worker. There is none with one core,
   * or where workers are unavailable or refused.
   */
  warmUp?: boolean;
  /**
   * Threads for large batches of points (default 1): a number from 1 to 64, or 'auto' (the
   * cores, at most 8). More than 1 loads the threaded build (geocdt-threads.*) in Node, and in
   * browsers on a cross-origin isolated page (COOP same-origin, COEP require-corp); elsewhere
   * the single-threaded build, and stats.threads says 1. No warm-up worker runs with the
   * threaded build.
   */
  threads?: number | 'auto';
}

/** Loads the WebAssembly module once; later calls resolve at once. */
export function init(options?: InitOptions): Promise<void>;

/**
 * The package's error for everything that is not a mistake in the input (those are
 * TypeError and RangeError): `code` says which.
 */
export type GeocdtErrorCode =
  /** The wasm heap cannot hold the input or the result (4 GB at most). */
  | 'OutOfMemory'
  /** A broken invariant in the core: a bug, reported rather than hung on. */
  | 'InternalError'
  /** A call before `await init()`, or a worker that could not load the module. */
  | 'NotLoaded'
  /** A call on a disposed Triangulation. */
  | 'Disposed'
  /** A call to geocdt from inside an onProgress callback. */
  | 'Busy'
  /** The worker crashed or exited. */
  | 'WorkerFailed'
  /** The worker was terminated with terminate(). */
  | 'WorkerTerminated';

export class GeocdtError extends Error {
  readonly name: 'GeocdtError';
  readonly code: GeocdtErrorCode;
  /** The input polyline (or point) concerned, when known. */
  readonly index?: number;
  /** The segment of that polyline, when known. */
  readonly segment?: number;
}

/**
 * Triangulates points and polylines in one call.
 * @throws TypeError on wrong types; RangeError on odd lengths, NaN, ±Infinity,
 *   |coordinate| > 1e150 or a bad flat layout (with `code` 'InvalidCoordinate' when the core
 *   found the value); GeocdtError otherwise (code 'OutOfMemory', 'InternalError',
 *   'NotLoaded' before init() has resolved, 'Busy').
 */
export function triangulate(
  input: TriangulateInput, options?: TriangulateOptions): TriangulateResult;

export interface MemoryUsage {
  /** Size of the wasm memory (it grows, never shrinks). */
  heapBytes: number;
  /** Bytes allocated now. */
  allocatedBytes: number;
  /** The allocator's high-water mark. */
  peakBytes: number;
}

export function memoryUsage(): MemoryUsage;

/**
 * 'empty': no triangle yet; 'outside': outside the convex hull (vertices: the hull edge that
 * sees the point); 'face': inside a triangle; 'edge': on an edge; 'vertex': on a vertex.
 */
export type LocationKind = 'empty' | 'outside' | 'face' | 'edge' | 'vertex';

export interface Location {
  kind: LocationKind;
  /** Index into results().triangles / 3 (with keep: 'all'), or -1. */
  triangle: number;
  /** 3 for a face, 2 for an edge or outside, 1 for a vertex, 0 when empty. */
  vertices: number[];
}

export interface TriangulationOptions {
  /** How many values each point carries (default 1). */
  valuesPerPoint?: number;
}

export interface InterpolateOptions {
  /** 'linear' (default) or 'natural'. */
  method?: Interpolation;
}

export interface RasterOptions extends InterpolateOptions {
  /** [minX, minY, maxX, maxY]: the area the raster covers. */
  bbox: readonly [number, number, number, number] | Float64Array;
  /** Pixels per row and rows: whole numbers from 1 up. */
  width: number;
  height: number;
}

/** A triangulation that grows by insertions. Free it with dispose(). */
export class Triangulation {
  constructor(options?: TriangulationOptions);
  /**
   * Inserts points, with valuesPerPoint values each (NaN without); returns the vertex id of
   * each (an existing one for a duplicate).
   */
  insertPoints(points: Coordinates, values?: Coordinates, options?: ProgressOptions): Uint32Array;
  insertPoints(points: Coordinates, options?: ProgressOptions): Uint32Array;
  /** Inserts one polyline as constraints; returns the vertex id of each of its points. */
  insertPolyline(
    polyline: Coordinates, values?: Coordinates, options?: ProgressOptions): Uint32Array;
  insertPolyline(polyline: Coordinates, options?: ProgressOptions): Uint32Array;
  /**
   * The values at each query point (x, y pairs): valuesPerPoint numbers per query, NaN outside
   * the convex hull.
   */
  interpolate(points: Coordinates, options?: InterpolateOptions): Float64Array;
  /**
   * The values sampled at pixel centres, width * height * valuesPerPoint numbers, row by row
   * from the top (maxY); NaN outside the convex hull. 'linear' scan-converts triangle by
   * triangle; 'natural' interpolates each pixel.
   */
  rasterize(options: RasterOptions): Float32Array;
  readonly valuesPerPoint: number;
  /** @throws RangeError when x or y is NaN or infinite. */
  locate(x: number, y: number): Location;
  /**
   * Removes a point inserted with insertPoints. Returns true when its vertex went, false when
   * it stays as a vertex of a polyline (until that polyline is removed too).
   * @throws RangeError when id names no point now (removed, out of range, not an integer);
   *   nothing changes then.
   */
  removePoint(id: number): boolean;
  /**
   * Removes many points inserted with insertPoints in one call, as removePoint would one by
   * one, nearby points one after the other (which costs less than a call each in random
   * order). Returns how many vertices went; the others stay as polylines' vertices
   * (hasVertex tells which).
   * @throws RangeError when an id names no point now, or comes twice (error.index: its index
   *   in ids; the first such); nothing changes then. TypeError when ids is not an array or
   *   typed array.
   */
  removePoints(ids: Ids): number;
  /**
   * Removes polyline k (insertion order; the others keep their numbers): its edges become
   * free, and its vertices, crossings and Steiner points that nothing else needs go.
   * @throws RangeError when k names no polyline now.
   */
  removePolyline(polyline: number): void;
  /**
   * Moves the vertex of a point or of a polyline to (x, y); the polylines through it follow.
   * A move within the vertex's star (a drag) takes flips only, for a free point or a polyline
   * vertex with nothing along its segments.
   * @throws RangeError on a bad id, a coordinate that is not finite (or beyond 1e150), or a
   *   place that another point or polyline vertex holds; nothing changes then.
   */
  movePoint(id: number, x: number, y: number): void;
  /** Whether id names a vertex now. */
  hasVertex(id: number): boolean;
  /** A copy of the current mesh, with vertexIds; insertions and edits can go on. */
  results(options?: ResultsOptions): Mesh & { vertexIds: Uint32Array };
  /**
   * Delaunay refinement of what is there now (keep: 'inside' refines only the inside); later
   * insertions leave quality to a later call. Returns the stats.
   * @throws TypeError, RangeError on bad options; GeocdtError ('OutOfMemory', 'Disposed',
   *   'Busy').
   */
  refine(options?: RefineOptions & { keep?: Keep; fillRule?: FillRule }): CoreStats;
  readonly vertexCount: number;
  readonly triangleCount: number;
  readonly polylineCount: number;
  readonly stats: CoreStats;
  readonly disposed: boolean;
  /**
   * Frees the wasm memory it holds; further calls throw. Calling it twice is harmless.
   * (At run time `Symbol.dispose` does the same, for `using` declarations; it is left out of
   * these types so that they compile without the esnext.disposable lib.)
   */
  dispose(): void;
}
