#include "polygons/batch_check.h"

#include <algorithm>
#include <string>

#include "invalid_coordinate.h"

namespace geocdt {

namespace {

// The largest batch: every index, extra points included, must fit 32 bits.
constexpr std::size_t kMostPoints = std::size_t{1} << 31;

std::string str(std::size_t v) { return std::to_string(v); }

// The polygon that holds ring r (polygonOffsets checked), or kNoIndex.
std::size_t polygonOf(const PolygonBatch& b, std::size_t r) {
  const std::uint32_t* begin = b.polygonOffsets;
  const std::uint32_t* end = b.polygonOffsets + b.polygonCount + 1;
  const std::uint32_t* after = std::upper_bound(begin, end, static_cast<std::uint32_t>(r));
  if (after == begin || after == end) return kNoIndex;
  return static_cast<std::size_t>(after - begin - 1);
}

Status failure(StatusCode code, std::string message, std::size_t polygon, std::size_t ring) {
  Status s{code, std::move(message), polygon};
  s.segment = ring;
  return s;
}

std::string ringName(const PolygonBatch& b, std::size_t r) {
  const std::size_t p = polygonOf(b, r);
  if (p == kNoIndex) return "ring " + str(r) + " (in no polygon)";
  return "polygon " + str(p) + " ring " + str(r - b.polygonOffsets[p]) + " (ringOffsets[" + str(r) +
         "])";
}

Status checkPolygonOffsets(const PolygonBatch& b) {
  const std::uint32_t* o = b.polygonOffsets;
  for (std::size_t i = 0; i <= b.polygonCount; ++i) {
    const std::size_t p = i < b.polygonCount ? i : i - 1;
    if (i > 0 && o[i] < o[i - 1])
      return failure(StatusCode::InvalidArgument,
                     "polygon " + str(i - 1) + " ends before it starts: polygonOffsets[" + str(i) +
                         "] = " + str(o[i]) + " is below polygonOffsets[" + str(i - 1) +
                         "] = " + str(o[i - 1]),
                     i - 1, kNoIndex);
    if (o[i] > b.ringCount)
      return failure(StatusCode::InvalidArgument,
                     "polygon " + str(p) + ": polygonOffsets[" + str(i) + "] = " + str(o[i]) +
                         " is past the " + str(b.ringCount) + " rings",
                     p, kNoIndex);
  }
  return Status::success();
}

Status checkRingOffsets(const PolygonBatch& b) {
  const std::uint32_t* o = b.ringOffsets;
  for (std::size_t i = 0; i <= b.ringCount; ++i) {
    const std::size_t r = i < b.ringCount ? i : i - 1;
    if (i > 0 && o[i] < o[i - 1])
      return failure(StatusCode::InvalidArgument,
                     ringName(b, i - 1) + " ends before it starts: ringOffsets[" + str(i) + "] = " +
                         str(o[i]) + " is below ringOffsets[" + str(i - 1) + "] = " + str(o[i - 1]),
                     polygonOf(b, i - 1), i - 1);
    if (o[i] > b.pointCount)
      return failure(StatusCode::InvalidArgument,
                     ringName(b, r) + ": ringOffsets[" + str(i) + "] = " + str(o[i]) +
                         " is past the " + str(b.pointCount) + " points",
                     polygonOf(b, r), r);
  }
  return Status::success();
}

}  // namespace

Status checkPolygonBatch(const PolygonBatch& b) {
  if (b.pointCount > 0 && b.xy == nullptr)
    return {StatusCode::InvalidArgument, "null coordinates with a count"};
  if (b.ringOffsets == nullptr || b.polygonOffsets == nullptr)
    return {StatusCode::InvalidArgument, "null offsets: n rings or polygons take n + 1 offsets"};
  if (b.pointCount >= kMostPoints)
    return {StatusCode::InvalidArgument, "too many points: a batch takes fewer than 2^31"};
  Status s = checkPolygonOffsets(b);
  if (s.ok()) s = checkRingOffsets(b);
  if (!s.ok() || b.polygonCount == 0) return s;
  // The points the polygons' rings use: one range, since polygons and rings are consecutive.
  const std::size_t first = 2 * static_cast<std::size_t>(b.ringOffsets[b.polygonOffsets[0]]);
  const std::size_t last =
      2 * static_cast<std::size_t>(b.ringOffsets[b.polygonOffsets[b.polygonCount]]);
  const std::size_t i = firstInvalidCoordinate(b.xy, first, last);
  if (i == last) return Status::success();
  const std::size_t point = i / 2;
  // The last ring that starts at or before the point and is not empty holds it.
  const std::uint32_t* ringsEnd = b.ringOffsets + b.ringCount + 1;
  const std::size_t r = static_cast<std::size_t>(
      std::upper_bound(b.ringOffsets, ringsEnd, static_cast<std::uint32_t>(point)) - b.ringOffsets -
      1);
  return failure(StatusCode::InvalidCoordinate,
                 ringName(b, r) + " point " + str(point - b.ringOffsets[r]) + " (point " +
                     str(point) + " of the batch) has " +
                     describeInvalidCoordinate(b.xy[i], i % 2 == 1),
                 polygonOf(b, r), r);
}

}  // namespace geocdt
