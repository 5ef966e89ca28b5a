#pragma once
// Lloyd's relaxation step: each site moves to the centroid of its clipped cell, which makes the
// sites spread evenly over the domain as the steps repeat (a centroidal Voronoi tessellation).
#include <vector>

#include "geocdt/voronoi.h"

namespace geocdt {

// Moves sites (x, y pairs, one per cell of `cells`) to their cells' centroids; a site whose cell
// is empty stays. Returns the longest move.
double moveToCentroids(const VoronoiCells& cells, std::vector<double>& sites);

}  // namespace geocdt
