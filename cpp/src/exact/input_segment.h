#pragma once
// An input segment's geometry, a to b: what crossings are computed from and chains are checked
// against. The constraint store builds it when needed from a segment's end vertices
// (ConstraintStore::geometry).

namespace geocdt {

struct InputSegment {
  double ax, ay, bx, by;
};

}  // namespace geocdt
