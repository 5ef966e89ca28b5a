#pragma once
// Exact decisions about input segments, for snap rounding and for checking the chains that
// stand for the segments: where a crossing rounds to, which vertices' boxes a segment meets,
// how far a vertex lies from a segment, which of two points comes first along one. Each is
// decided by a floating-point filter where that is safe, else with fixed-point big integers
// on the inputs' lowest common unit, so nothing rounds.
#include <cmath>

#include "exact/input_segment.h"

namespace geocdt {

// The spacing of doubles at |v|: from |v| to the next double up; 2^-1074 among subnormals.
inline double spacingAt(double v) {
  const double m = std::fabs(v);
  return std::nextafter(m, INFINITY) - m;
}

// The exponent e of the power of two 2^e = spacingAt(v).
int spacingExponent(double v);

// The exponent e of the documented bound 2^e that every chain keeps from its input segment:
// two spacings of doubles at the segment's largest |coordinate|.
inline int chainBoundExponent(const InputSegment& s) {
  return spacingExponent(std::fmax(std::fmax(std::fabs(s.ax), std::fabs(s.ay)),
                                   std::fmax(std::fabs(s.bx), std::fabs(s.by)))) +
         1;
}

// Where the lines of s and t cross (s and t not parallel), each coordinate rounded to the
// nearest double, halfway cases upward: the point whose rounding box [x - below/2,
// x + above/2) x [y - below/2, y + above/2) holds the crossing (below and above being the
// spacings to the neighbouring doubles).
void roundedCrossing(const InputSegment& s, const InputSegment& t, double& x, double& y);

// Where the lines of s and t cross, rounded as roundedCrossing rounds; false where they are
// parallel or cross outside s's bounding box. The same point on every platform.
bool roundedLineCrossing(const InputSegment& s, const InputSegment& t, double& x, double& y);

// Whether the closed segment s meets the rounding cell of (x, y): the half-open box of the
// points that round to it, from halfway to the double below to halfway to the double above
// on each axis (halfway cases upward, as roundedCrossing does).
bool segmentMeetsCell(const InputSegment& s, double x, double y);

// Whether (x, y) lies within 2^e of the closed segment s (Euclidean distance).
bool withinDistance(const InputSegment& s, double x, double y, int e);

// Whether s and t cross in one point inside both (exactly).
bool crossProperly(const InputSegment& s, const InputSegment& t);

// The sign of (q - p) . (b - a) for s from a to b: whether q lies further along s than p.
int signAlong(const InputSegment& s, double px, double py, double qx, double qy);

}  // namespace geocdt
