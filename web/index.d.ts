// geocdt: constrained Delaunay triangulation for maps, in WebAssembly.

/** x0, y0, x1, y1, …: a Float64Array (or Float32Array) or an array of numbers. */
export type Coordinates = Float64Array | Float32Array | readonly number[];

export interface TriangulateInput {
  /** Points to triangulate: x0, y0, x1, y1, … */
  points?: Coordinates;
  /**
   * Polylines whose segments become constrained edges, split where they cross. A ring repeats
   * its first point at its end (the GeoJSON convention) and bounds the inside.
   */
  polylines?: readonly Coordinates[];
}

export interface MeshOptions {
  /** 'all' (default) keeps every triangle; 'inside' only those inside the rings. */
  keep?: 'all' | 'inside';
  /** How rings decide inside: 'evenodd' (default) or 'nonzero' (winding number). */
  fillRule?: 'evenodd' | 'nonzero';
  /** Return `inside`, one flag per triangle (implied by keep: 'inside'). */
  insideFlags?: boolean;
}

export interface Stats {
  /** Points that became vertices. */
  inserted: number;
  /** Points equal to an existing vertex. */
  duplicates: number;
  /** Triangles visited by point location, over `locates` locations. */
  walkSteps: number;
  locates: number;
  flips: number;
  walkFallbacks: number;
  /** m of the m × m point-location grid. */
  gridSize: number;
  /** Vertices added where constraints cross. */
  crossings: number;
  polylines: number;
  /** Constraint segments inserted. */
  segments: number;
  vertices: number;
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
  /** 1 for each triangle inside the rings; present with insideFlags or keep: 'inside'. */
  inside?: Uint8Array;
  stats: Stats;
}

export interface TriangulateResult extends Mesh {
  /** For each input point (points first, then each polyline's points in order), its vertex id. */
  inputToVertex: Uint32Array;
}

export interface InitOptions {
  /** The wasm bytes, if you load them yourself. */
  wasmBinary?: ArrayBuffer | Uint8Array;
  /** Where to fetch (browser) or read (Node: a path or a file: URL) geocdt.wasm from. */
  wasmUrl?: string | { readonly href: string };
}

/** Loads the WebAssembly module once; later calls resolve at once. */
export function init(options?: InitOptions): Promise<void>;

/**
 * Triangulates points and polylines in one call.
 * @throws TypeError on wrong types; RangeError on odd lengths, NaN, ±Infinity,
 *   |coordinate| > 1e150 or memory exhaustion; Error before init() has resolved.
 */
export function triangulate(input: TriangulateInput, options?: MeshOptions): TriangulateResult;

export type GeoJSONOutput = 'geojson' | 'arrays';

export interface GeoJSONOptions extends MeshOptions {
  /** 'geojson' (default): a FeatureCollection of triangles; 'arrays': the typed arrays. */
  output?: GeoJSONOutput;
}

export interface TriangleFeature {
  type: 'Feature';
  /** The triangle's index in the mesh. */
  id: number;
  /** `inside` is present when the mesh has inside flags. */
  properties: { inside?: boolean };
  geometry: { type: 'Polygon'; coordinates: [[number, number][]] };
}

export interface TriangleFeatureCollection {
  type: 'FeatureCollection';
  features: TriangleFeature[];
}

/** Any GeoJSON object: FeatureCollection, Feature or geometry. */
export type GeoJSONInput = { type: string; [key: string]: unknown };

/**
 * Triangulates GeoJSON: Point and MultiPoint give points, LineString and MultiLineString give
 * constraints, Polygon and MultiPolygon rings give constraints that bound the inside.
 * Coordinates are used as given (lon/lat or projected) and triangulated in the plane.
 */
export function triangulateGeoJSON(geojson: GeoJSONInput, options?: MeshOptions & { output?: 'geojson' }): TriangleFeatureCollection;
export function triangulateGeoJSON(geojson: GeoJSONInput, options: MeshOptions & { output: 'arrays' }): TriangulateResult;
export function triangulateGeoJSON(geojson: GeoJSONInput, options?: GeoJSONOptions): TriangleFeatureCollection | TriangulateResult;

/** GeoJSON -> the input of triangulate(); rings are closed if they are not. */
export function geoJSONToInput(geojson: GeoJSONInput): { points: Float64Array; polylines: Float64Array[] };

/** A mesh -> a FeatureCollection with one counter-clockwise Polygon per triangle. */
export function meshToGeoJSON(mesh: Mesh): TriangleFeatureCollection;

export interface MemoryUsage {
  /** Size of the wasm memory (it grows, never shrinks). */
  heapBytes: number;
  /** Bytes allocated now. */
  allocatedBytes: number;
  /** The allocator's high-water mark. */
  peakBytes: number;
}

export function memoryUsage(): MemoryUsage;

export interface Location {
  /**
   * 'empty': no triangle yet; 'outside': outside the convex hull (vertices: the hull edge
   * that sees the point); 'face': inside a triangle; 'edge': on an edge; 'vertex': on a vertex.
   */
  kind: 'empty' | 'outside' | 'face' | 'edge' | 'vertex';
  /** Index into results().triangles / 3 (with keep: 'all'), or -1. */
  triangle: number;
  /** 3 for a face, 2 for an edge or outside, 1 for a vertex, 0 when empty. */
  vertices: number[];
}

/** A triangulation that grows by insertions. Free it with dispose(). */
export class Triangulation {
  constructor();
  /** Inserts points; returns the vertex id of each (an existing one for a duplicate). */
  insertPoints(points: Coordinates): Uint32Array;
  /** Inserts one polyline as constraints; returns the vertex id of each of its points. */
  insertPolyline(polyline: Coordinates): Uint32Array;
  locate(x: number, y: number): Location;
  /** A copy of the current mesh; insertions can go on. */
  results(options?: MeshOptions): Mesh;
  readonly vertexCount: number;
  readonly triangleCount: number;
  readonly polylineCount: number;
  readonly stats: Omit<Stats, 'vertices' | 'triangles' | 'constraintEdges' | 'milliseconds' | 'coreMilliseconds'>;
  readonly disposed: boolean;
  /**
   * Frees the wasm memory it holds; further calls throw. Calling it twice is harmless.
   * (At run time `Symbol.dispose` does the same, for `using` declarations; it is left out of
   * these types so that they compile without the esnext.disposable lib.)
   */
  dispose(): void;
}
