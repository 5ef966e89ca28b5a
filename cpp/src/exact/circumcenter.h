#pragma once
// The circumcentre of a triangle, the vertex of the Voronoi diagram its corners share, to a
// stated accuracy: each coordinate within kCircumcenterTolerance * (M + R) of the exact
// centre, M the largest |coordinate| of the corners and R the circumradius. Computed in
// doubles with an error bound, and, for the few triangles whose bound misses (nearly collinear
// corners), from exact fixed-point numerator and denominator.
#include "exact/bisector_predicates.h"

namespace geocdt {

inline constexpr double kCircumcenterTolerance = 0x1p-48;

// a, b, c not collinear (either orientation).
XY circumcenter(XY a, XY b, XY c);

}  // namespace geocdt
