#pragma once
// Delaunay refinement after Ruppert and Chew, made robust as Shewchuk describes: encroached
// subsegments are split first (on concentric shells around input vertices, so that small
// input angles do not make it loop), then bad triangles (in BadQueue's order) at their
// off-centre or circumcentre; a candidate that would encroach a subsegment splits the
// subsegment instead. Steiner points are computed in floating point and inserted through the
// exact core, by the cavity the encroachment check found where it is a star.
#include "delaunay/delaunay.h"

namespace geocdt {

// Refines d as options say (already validated); adds to d.stats and d.steiner. windings, if
// not null, gets every slot's winding number after it (what slotWindings would give).
Status refineTriangulation(Delaunay& d, const RefineOptions& options,
                           std::vector<std::int32_t>* windings = nullptr);

// The message for an invalid RefineOptions, or "" when they are valid.
std::string refineOptionsError(const RefineOptions& options);

}  // namespace geocdt
