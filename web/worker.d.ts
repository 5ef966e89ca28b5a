// geocdt/worker: the geocdt calls, answered by a module Web Worker (browsers) or a
// worker_threads Worker (Node). Coordinates go to the worker and results come back as
// transferred buffers, not copies.
import type {
  Coordinates, CoreStats, Ids, EarcutTriangles, GeoJSONInput, GeoJSONOptions, GeoJSONResult,
  InterpolateOptions, Location, MemoryUsage, Mesh, MeshOptions, Offsets, PolygonBatch,
  PolygonTriangles, ProgressOptions, RasterOptions, RefineOptions, ResultsOptions,
  TriangleFeatureCollection, TriangulateInput, TriangulateOptions, TriangulatePolygonsOptions,
  TriangulateResult, TriangulationOptions, Keep, FillRule, Heightmap, RasterMesh,
  RasterMeshOptions, VoronoiInput, VoronoiOptions, VoronoiCells, CellFeatureCollection,
  VoronoiGeoJSONResult, GeoJSONOutput, FeatureFillOptions, FeatureFillResult,
} from './index.js';

export { GeocdtError, GeocdtErrorCode, ProgressEvent, ProgressPhase } from './index.js';

export interface TransferOptions {
  /**
   * true (default): typed arrays that span their whole buffer are transferred to the worker
   * and become detached (length 0) for the caller; false: they are copied.
   */
  transfer?: boolean;
}

export class GeocdtWorker {
  /** Loads the wasm in the worker (every call does it if needed). */
  init(): Promise<void>;
  triangulate(
    input: TriangulateInput,
    options?: TriangulateOptions & TransferOptions): Promise<TriangulateResult>;
  /** The GeoJSON is read on the calling thread; the triangulation runs in the worker. */
  triangulateGeoJSON(
    geojson: GeoJSONInput,
    options: FeatureFillOptions & { output?: 'geojson' }): Promise<TriangleFeatureCollection>;
  triangulateGeoJSON(
    geojson: GeoJSONInput,
    options: FeatureFillOptions & { output: 'arrays' }): Promise<FeatureFillResult>;
  triangulateGeoJSON(
    geojson: GeoJSONInput,
    options?: TriangulateOptions & { output?: 'geojson'; perFeature?: false },
  ): Promise<TriangleFeatureCollection>;
  triangulateGeoJSON(
    geojson: GeoJSONInput,
    options: TriangulateOptions & { output: 'arrays'; perFeature?: false },
  ): Promise<GeoJSONResult>;
  triangulateGeoJSON(
    geojson: GeoJSONInput, options?: GeoJSONOptions | FeatureFillOptions,
  ): Promise<TriangleFeatureCollection | GeoJSONResult | FeatureFillResult>;
  /** The batch's typed arrays are transferred to the worker (transfer: false copies them). */
  triangulatePolygons(
    polygons: PolygonBatch,
    options?: TriangulatePolygonsOptions & TransferOptions): Promise<PolygonTriangles>;
  earcut(
    data: Coordinates, holeIndices?: Offsets | null, dim?: number): Promise<EarcutTriangles>;
  /** The heights and breaklines are transferred as triangulate()'s points are. */
  triangulateRaster(
    raster: Heightmap, options?: RasterMeshOptions & TransferOptions): Promise<RasterMesh>;
  voronoi(
    input: VoronoiInput, options?: VoronoiOptions & TransferOptions): Promise<VoronoiCells>;
  /** The GeoJSON is read on the calling thread; the cells are made in the worker. */
  voronoiGeoJSON(
    geojson: GeoJSONInput,
    options?: VoronoiOptions & { output?: 'geojson' }): Promise<CellFeatureCollection>;
  voronoiGeoJSON(
    geojson: GeoJSONInput,
    options: VoronoiOptions & { output: 'arrays' }): Promise<VoronoiGeoJSONResult>;
  voronoiGeoJSON(
    geojson: GeoJSONInput, options?: VoronoiOptions & { output?: GeoJSONOutput },
  ): Promise<CellFeatureCollection | VoronoiGeoJSONResult>;
  memoryUsage(): Promise<MemoryUsage>;
  /** A Triangulation that lives in the worker. */
  createTriangulation(options?: TriangulationOptions): RemoteTriangulation;
  /** Stops the worker; pending calls reject with a GeocdtError ('WorkerTerminated'). */
  terminate(): void;
}

export class RemoteTriangulation {
  insertPoints(
    points: Coordinates, values?: Coordinates,
    options?: TransferOptions & ProgressOptions): Promise<Uint32Array>;
  insertPoints(
    points: Coordinates, options?: TransferOptions & ProgressOptions): Promise<Uint32Array>;
  insertPolyline(
    polyline: Coordinates, values?: Coordinates,
    options?: TransferOptions & ProgressOptions): Promise<Uint32Array>;
  insertPolyline(
    polyline: Coordinates, options?: TransferOptions & ProgressOptions): Promise<Uint32Array>;
  interpolate(
    points: Coordinates, options?: InterpolateOptions & TransferOptions): Promise<Float64Array>;
  rasterize(options: RasterOptions): Promise<Float32Array>;
  readonly valuesPerPoint: number;
  locate(x: number, y: number): Promise<Location>;
  /** As Triangulation's: resolves to whether the vertex went; a bad id rejects (RangeError). */
  removePoint(id: number): Promise<boolean>;
  /** As Triangulation's: resolves to how many vertices went; a bad id rejects (RangeError). */
  removePoints(ids: Ids): Promise<number>;
  removePolyline(polyline: number): Promise<void>;
  movePoint(id: number, x: number, y: number): Promise<void>;
  hasVertex(id: number): Promise<boolean>;
  results(options?: ResultsOptions): Promise<Mesh>;
  refine(options?: RefineOptions & { keep?: Keep; fillRule?: FillRule }): Promise<CoreStats>;
  stats(): Promise<CoreStats>;
  counts(): Promise<{ vertexCount: number; triangleCount: number; polylineCount: number }>;
  dispose(): Promise<void>;
}

/**
 * Starts a worker. In Node, an idle worker does not keep the process alive. options.threads:
 * as init()'s, for the worker's module (a TypeError or RangeError at once when wrong).
 */
export function createWorker(options?: { threads?: number | 'auto' }): GeocdtWorker;
