// readGeoJSON()'s input -> voronoi()'s: the points are the sites, and only the Polygon and
// MultiPolygon rings (which come first among the polylines) bound the domain; lines do not.
export function sitesAndRings({ points, polylines: { coords, offsets }, polygons }) {
  const rings = polygons === undefined ? 0 : polygons[polygons.length - 1];
  return {
    points,
    polylines: {
      coords: coords.subarray(0, 2 * offsets[rings]), offsets: offsets.subarray(0, rings + 1),
    },
  };
}

// voronoi()'s cells as GeoJSON: a FeatureCollection with one feature per site, in site order,
// whose geometry is the site's cell as a MultiPolygon (null when the cell is empty).
// cells.siteFeatures (from voronoiGeoJSON()) gives each site's feature: its id and properties
// (the same properties object, not a copy) go to the cell; without, the cell's id is the site's
// index and its properties are empty.
export function cellsToGeoJSON(cells) {
  const { coords, ringOffsets, polygonOffsets, siteOffsets, siteFeatures } = cells;
  const sites = siteOffsets.length - 1;
  const features = new Array(sites);
  const ring = (r) => {
    const out = new Array(ringOffsets[r + 1] - ringOffsets[r]);
    for (let k = ringOffsets[r], i = 0; k < ringOffsets[r + 1]; k++, i++) {
      out[i] = [coords[2 * k], coords[2 * k + 1]];
    }
    return out;
  };
  for (let i = 0; i < sites; i++) {
    let geometry = null;
    if (siteOffsets[i + 1] > siteOffsets[i]) {
      const polygons = [];
      for (let p = siteOffsets[i]; p < siteOffsets[i + 1]; p++) {
        const rings = [];
        for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) rings.push(ring(r));
        polygons.push(rings);
      }
      geometry = { type: 'MultiPolygon', coordinates: polygons };
    }
    const f = siteFeatures?.[i];
    const id = siteFeatures === undefined ? i : f?.id;
    const properties = siteFeatures === undefined ? {} : f?.properties ?? null;
    features[i] = id === undefined
      ? { type: 'Feature', properties, geometry }
      : { type: 'Feature', id, properties, geometry };
  }
  return { type: 'FeatureCollection', features };
}
