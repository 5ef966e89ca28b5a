// Compiled with tsc --noEmit by types.test.js: the declarations must accept real use and
// reject wrong use (the @ts-expect-error lines fail the build if they stop being errors).
import {
  init, triangulate, triangulatePolygons, earcut, triangulateRaster, triangulateGeoJSON,
  geoJSONToInput, Triangulation, memoryUsage, GeocdtError, voronoi, voronoiGeoJSON,
  cellsToGeoJSON, type TriangulateResult, type ProgressEvent, type GeocdtErrorCode,
  type Position, type PolygonTriangles, type RasterMesh, type VoronoiCells,
  type FeatureFillResult, type TriangleFeatureCollection,
} from 'geocdt';
import { createWorker } from 'geocdt/worker';

async function main(): Promise<void> {
  await init();
  await init({ wasmUrl: 'geocdt.wasm' });
  const r: TriangulateResult = triangulate(
    { points: new Float64Array(6), polylines: [[0, 0, 1, 1]] }, { keep: 'inside' });
  const t: Uint32Array = r.triangles;
  const h: Int32Array = r.halfedges;
  const inside: Uint8Array | undefined = r.inside;
  const ms: number = r.stats.milliseconds;

  // Any numeric array, and the flat polylines form.
  triangulate({ points: new Int32Array(6), polylines: [new Uint16Array(4), [0, 0, 1, 1]] });
  const flat = triangulate({
    points: new Float32Array(6),
    polylines: { coords: new Int16Array(8), offsets: new Uint32Array([0, 2, 4]) },
  }, { onProgress: (e: ProgressEvent) => void [e.phase, e.fraction] });
  const phases: ProgressEvent['phase'][] = ['sort', 'points', 'constraints', 'export'];

  const fc = triangulateGeoJSON({ type: 'FeatureCollection', features: [] });
  const firstRing: Position[] = fc.features[0].geometry.coordinates[0];
  const id: string | number | undefined = fc.features[0].id;
  const name: unknown = fc.features[0].properties?.name;
  const arrays = triangulateGeoJSON({ type: 'Point', coordinates: [0, 0] }, { output: 'arrays' });
  const ids: Uint32Array = arrays.inputToVertex;
  const regionOf: Int32Array | undefined = arrays.regions;
  const featureOf = arrays.regionFeatures[0]?.properties;
  const heights: Float64Array | undefined = arrays.values;
  // Each feature filled alone.
  const fills: FeatureFillResult = triangulateGeoJSON({ type: 'FeatureCollection', features: [] },
    { perFeature: true, output: 'arrays', fillRule: 'nonzero' });
  const fillOffsets: Uint32Array = fills.triangleOffsets;
  const fillFeature = fills.regionFeatures[fills.regions[0]]?.id;
  const fillCollection: TriangleFeatureCollection =
    triangulateGeoJSON({ type: 'Point', coordinates: [0, 0] }, { perFeature: true });
  // @ts-expect-error perFeature takes no refinement
  triangulateGeoJSON({ type: 'Point', coordinates: [0, 0] }, { perFeature: true, refine: true });

  // Polygons and heights in the array API, polygons in results().
  const labelled = triangulate({
    polylines: { coords: new Float64Array(8), offsets: [0, 4] }, polygons: [0, 1],
    values: new Float32Array(4),
  }, { valuesPerPoint: 1 });
  const regions: Int32Array | undefined = labelled.regions;
  const perRing: Float64Array[] = geoJSONToInput({ type: 'Point', coordinates: [0, 0] }).polylines;
  const offsets: Uint32Array =
    geoJSONToInput({ type: 'Point', coordinates: [0, 0] }, { flat: true }).polylines.offsets;

  // Polygons in GeoArrow's layout, tile decoders' typed arrays included; earcut's signature.
  const filled: PolygonTriangles = triangulatePolygons({
    coords: new Int16Array(8), ringOffsets: new Uint32Array([0, 4]), polygonOffsets: [0, 1],
  }, { fillRule: 'nonzero' });
  const fillIndices: Uint32Array = filled.triangles;
  const extra: Float64Array = filled.extraPoints;
  const perPolygon: Uint32Array = filled.triangleOffsets;
  const general: number = filled.stats.general;
  const ear = earcut([0, 0, 1, 0, 0, 1], null);
  const earIndices: Uint32Array = ear;
  const earExtra: Float64Array = earcut(new Float32Array(9), [3], 3).extraPoints;

  const tri = new Triangulation();
  const v: Uint32Array = tri.insertPoints([0, 0, 1, 0, 0, 1], { onProgress: () => {} });
  const surface = new Triangulation({ valuesPerPoint: 2 });
  surface.insertPoints([0, 0, 1, 0, 0, 1], new Float64Array(6), { onProgress: () => {} });
  surface.insertPolyline([0, 0, 1, 1], [1, 2, 3, 4]);
  const at: Float64Array = surface.interpolate([0.2, 0.2], { method: 'natural' });
  const grid: Float32Array = surface.rasterize({ bbox: [0, 0, 1, 1], width: 4, height: 4 });
  const perPoint: number = surface.valuesPerPoint;
  const meshRegions: Int32Array | undefined = tri.results({ polygons: new Uint32Array([0, 0]) })
    .regions;
  const where = tri.locate(0.2, 0.2);
  const kind: 'empty' | 'outside' | 'face' | 'edge' | 'vertex' = where.kind;
  const flips: number = tri.stats.flips;
  const wentAway: boolean = tri.removePoint(v[0]);
  tri.movePoint(v[1], 0.5, 0.5);
  surface.removePolyline(0);
  const outputIds: Uint32Array = tri.results().vertexIds;
  const stillThere: boolean = tri.hasVertex(v[2]);
  const removedCount: number = tri.stats.removed;
  const wentInBatch: number = tri.removePoints(new Uint32Array([v[3]])) + tri.removePoints([]);
  void [wentAway, outputIds, stillThere, removedCount, wentInBatch];
  tri.dispose();
  const heap: number = memoryUsage().heapBytes;

  // Voronoi cells: GeoArrow offsets, clip choices, Lloyd, GeoJSON.
  const cells: VoronoiCells = voronoi({ points: new Float64Array(6) }, { clip: [0, 0, 1, 1] });
  const cellCoords: Float64Array = cells.coords;
  const sitePolygons: Uint32Array = cells.siteOffsets;
  const relaxed = voronoi({ points: [0, 0, 1, 1], polylines: [[0, 0, 2, 0, 2, 2, 0, 0]] },
    { clip: 'rings', fillRule: 'nonzero', lloyd: { iterations: 5, tolerance: 1e-9 } });
  const moved: Float64Array | undefined = relaxed.points;
  const steps: number | undefined = relaxed.lloyd?.iterations;
  voronoi({ points: [0, 0] }, { clip: 'hull', lloyd: true });
  const cellFeatures = voronoiGeoJSON({ type: 'FeatureCollection', features: [] });
  const cellGeometry = cellFeatures.features[0].geometry?.coordinates[0][0][0];
  const cellArrays = voronoiGeoJSON({ type: 'Point', coordinates: [0, 0] }, { output: 'arrays' });
  const siteFeature = cellArrays.siteFeatures[0]?.properties;
  const asGeoJSON = cellsToGeoJSON(cells).features.length;

  try {
    triangulate({});
  } catch (e) {
    if (e instanceof GeocdtError) {
      const code: GeocdtErrorCode = e.code;
      const index: number | undefined = e.index;
      void [code, index];
    }
  }

  // Terrain: any numeric heights, breaklines in either form, heights in values.
  const tin: RasterMesh = triangulateRaster(
    { heights: new Int16Array(12), width: 4, height: 3 },
    { maxError: 1, noData: -9999, minAngle: 20, bbox: [0, 0, 3, 2], breaklines: [[0, 0, 3, 2]],
      breaklineHeights: [NaN, 5] });
  const tinHeights: Float64Array = tin.values;
  const tinError: number = tin.stats.maxError;
  triangulateRaster({ heights: [1, 2, 3, 4], width: 2, height: 2 },
    { breaklines: { coords: new Float32Array(4), offsets: [0, 2] }, maxTriangles: 10 });

  const worker = createWorker();
  const remoteTin: RasterMesh = await worker.triangulateRaster(
    { heights: new Float32Array(4), width: 2, height: 2 }, { transfer: false });
  const remoteFills: FeatureFillResult = await worker.triangulateGeoJSON(
    { type: 'Point', coordinates: [0, 0] }, { perFeature: true, output: 'arrays' });
  const remote = await worker.triangulate({ points: [0, 0, 1, 0, 0, 1] },
    { transfer: false, onProgress: ({ fraction }) => void fraction });
  const rt = worker.createTriangulation();
  await rt.insertPoints(new Int32Array(6), { onProgress: () => {} });
  const located = await rt.locate(0, 0);
  const remoteWent: boolean = await rt.removePoint(0);
  const remoteBatch: number = await rt.removePoints([2, 3]);
  await rt.movePoint(1, 0.5, 0.5);
  await rt.removePolyline(0);
  void [remoteWent, remoteBatch];
  const rv = worker.createTriangulation({ valuesPerPoint: 1 });
  await rv.insertPoints([0, 0, 1, 0, 0, 1], [1, 2, 3], { transfer: false });
  const remoteAt: Float64Array = await rv.interpolate([0.1, 0.1], { method: 'linear' });
  const remoteGrid: Float32Array = await rv.rasterize({ bbox: [0, 0, 1, 1], width: 2, height: 2 });
  const remoteFill: Uint32Array = (await worker.triangulatePolygons(
    { coords: [0, 0, 1, 0, 0, 1], ringOffsets: [0, 3], polygonOffsets: [0, 1] },
    { transfer: false })).triangles;
  const remoteEar: Float64Array = (await worker.earcut([0, 0, 1, 0, 0, 1])).extraPoints;
  const remoteCells: VoronoiCells = await worker.voronoi({ points: [0, 0, 1, 1] },
    { clip: 'hull', transfer: false });
  const remoteCellFeatures = await worker.voronoiGeoJSON({ type: 'Point', coordinates: [0, 0] });
  worker.terminate();

  // @ts-expect-error clip takes 'rings', 'hull' or a box
  voronoi({ points: [0, 0] }, { clip: 'bbox' });
  // @ts-expect-error a box has four numbers
  voronoi({ points: [0, 0] }, { clip: [0, 0, 1] });
  // @ts-expect-error voronoi() needs points
  voronoi({ polylines: [] });
  // @ts-expect-error keep takes 'all' or 'inside'
  triangulate({ points: [] }, { keep: 'outside' });
  // @ts-expect-error points are numbers
  triangulate({ points: ['0', '1'] });
  // @ts-expect-error BigInt arrays are not coordinates
  triangulate({ points: new BigInt64Array(2) });
  // @ts-expect-error offsets are integers
  triangulate({ polylines: { coords: [0, 0], offsets: new Float64Array(2) } });
  // @ts-expect-error results() of a mesh has no inputToVertex
  new Triangulation().results().inputToVertex;
  // @ts-expect-error polygons are integer offsets
  triangulate({ polygons: new Float64Array(2) });
  // @ts-expect-error no such phase
  const phase: ProgressEvent['phase'] = 'walk';
  // @ts-expect-error no such method
  surface.interpolate([0, 0], { method: 'cubic' });
  // @ts-expect-error the layout needs ringOffsets
  triangulatePolygons({ coords: [0, 0], polygonOffsets: [0, 0] });
  // @ts-expect-error no such fill rule
  triangulatePolygons({ coords: [], ringOffsets: [0], polygonOffsets: [0] }, { fillRule: 'all' });
  // @ts-expect-error a heightmap needs its width and height
  triangulateRaster({ heights: new Float32Array(4) });
  // @ts-expect-error maxError is a number
  triangulateRaster({ heights: [0], width: 1, height: 1 }, { maxError: '1' });

  void [t, h, inside, ms, flat, phases, firstRing, ids, perRing, offsets, v, kind, flips, heap,
    remote, located, phase, id, name, regionOf, featureOf, heights, regions, meshRegions, at,
    grid, perPoint, remoteAt, remoteGrid, fillIndices, extra, perPolygon, general, earIndices,
    earExtra, remoteFill, remoteEar, tinHeights, tinError, remoteTin, cellCoords, sitePolygons,
    moved, steps, cellGeometry, siteFeature, asGeoJSON, remoteCells, remoteCellFeatures];
}

main();
