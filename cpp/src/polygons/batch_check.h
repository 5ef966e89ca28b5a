#pragma once
// The layout and coordinates of a polygon batch, checked before any work: offsets that never
// decrease and stay in range, and finite coordinates within kMaxCoordinate for every point a
// ring uses. A failure names the polygon (Status::index), the ring (Status::segment, its
// index in ringOffsets) and, in the message, the point.
#include "geocdt/polygons.h"
#include "geocdt/status.h"

namespace geocdt {

Status checkPolygonBatch(const PolygonBatch& batch);

}  // namespace geocdt
