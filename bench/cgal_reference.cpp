#include "cgal_reference.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/version_macros.h>

#include <numeric>

#include "heap_counter.h"

namespace bench {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

template <class K>
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>,
                                         CGAL::Constrained_triangulation_face_base_2<K>>,
    CGAL::Exact_predicates_tag>;

double roundToDouble(double v) { return v; }
double roundToDouble(const Epeck::FT& v) { return CGAL::to_double(v.exact()); }

template <class K>
bool runConstrained(const std::vector<double>& freePoints,
                    const geocdt::testing::PolylineSet& polylines, Sample& sample) {
  using Point = typename K::Point_2;
  using Triangulation = Cdt<K>;
  std::vector<Point> points;
  points.reserve(freePoints.size() / 2 + polylines.pointCount());
  for (std::size_t i = 0; i + 1 < freePoints.size(); i += 2)
    points.emplace_back(freePoints[i], freePoints[i + 1]);
  for (std::size_t i = 0; i + 1 < polylines.xy.size(); i += 2) {
    points.emplace_back(polylines.xy[i], polylines.xy[i + 1]);
  }
  const std::size_t firstPolylinePoint = freePoints.size() / 2;

  const std::size_t heapBefore = heapInUse();
  resetHeapPeak();
  std::uint64_t start = nowNanos();
  Triangulation cdt;
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using PointMap = typename CGAL::Pointer_property_map<Point>::type;
  CGAL::spatial_sort(
      order.begin(), order.end(),
      CGAL::Spatial_sort_traits_adapter_2<K, PointMap>(CGAL::make_property_map(points)));
  std::vector<typename Triangulation::Vertex_handle> vertexOf(points.size());
  typename Triangulation::Face_handle hint;
  for (std::size_t i : order) {
    vertexOf[i] = cdt.insert(points[i], hint);
    hint = vertexOf[i]->face();
  }
  sample.pointSeconds = secondsSince(start);
  const std::size_t verticesAfterPoints = cdt.number_of_vertices();

  start = nowNanos();
  for (std::size_t p = 0; p < polylines.polylineCount(); ++p) {
    const std::size_t first = firstPolylinePoint + polylines.offsets[p];
    for (std::size_t k = first; k + 1 < firstPolylinePoint + polylines.offsets[p + 1]; ++k) {
      if (vertexOf[k] != vertexOf[k + 1]) cdt.insert_constraint(vertexOf[k], vertexOf[k + 1]);
    }
  }
  sample.edgeSeconds = secondsSince(start);
  sample.peakBytes = heapPeak() - heapBefore;
  sample.vertices = cdt.number_of_vertices();
  sample.crossings = sample.vertices - verticesAfterPoints;
  sample.triangles = cdt.number_of_faces();

  // Each triangle with its own three corners, rounded to double as a user would store them.
  std::vector<double> corners;
  corners.reserve(6 * sample.triangles);
  for (auto f : cdt.finite_face_handles()) {
    for (int i = 0; i < 3; ++i) {
      corners.push_back(roundToDouble(f->vertex(i)->point().x()));
      corners.push_back(roundToDouble(f->vertex(i)->point().y()));
    }
  }
  std::vector<std::uint32_t> triangles(corners.size() / 2);
  std::iota(triangles.begin(), triangles.end(), 0u);
  countBadTriangles(corners, triangles, sample);
  return true;
}

}  // namespace

bool cgalAvailable() { return true; }
std::string cgalDescription() {
#ifdef NDEBUG
  return "CGAL " CGAL_VERSION_STR " (release: its assertions off)";
#else
  return "CGAL " CGAL_VERSION_STR " (its assertions on: they make CGAL slower)";
#endif
}

bool cgalDelaunay(const std::vector<double>& xy, Sample& sample, std::string&) {
  std::vector<Epick::Point_2> points;
  points.reserve(xy.size() / 2);
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) points.emplace_back(xy[i], xy[i + 1]);
  const std::size_t heapBefore = heapInUse();
  resetHeapPeak();
  const std::uint64_t start = nowNanos();
  CGAL::Delaunay_triangulation_2<Epick> dt;
  dt.insert(points.begin(), points.end());
  sample.pointSeconds = secondsSince(start);
  sample.peakBytes = heapPeak() - heapBefore;
  sample.vertices = dt.number_of_vertices();
  sample.triangles = dt.number_of_faces();
  return true;
}

bool cgalConstrained(const std::vector<double>& freePoints,
                     const geocdt::testing::PolylineSet& polylines, CgalKernel kernel,
                     Sample& sample, std::string&) {
  return kernel == CgalKernel::Inexact ? runConstrained<Epick>(freePoints, polylines, sample)
                                       : runConstrained<Epeck>(freePoints, polylines, sample);
}

void countBadTriangles(const std::vector<double>& xy, const std::vector<std::uint32_t>& triangles,
                       Sample& sample) {
  sample.flipped = sample.zeroArea = 0;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const double* a = &xy[2 * triangles[t]];
    const double* b = &xy[2 * triangles[t + 1]];
    const double* c = &xy[2 * triangles[t + 2]];
    const CGAL::Orientation o = CGAL::orientation(
        Epick::Point_2(a[0], a[1]), Epick::Point_2(b[0], b[1]), Epick::Point_2(c[0], c[1]));
    if (o == CGAL::CLOCKWISE) ++sample.flipped;
    if (o == CGAL::COLLINEAR) ++sample.zeroArea;
  }
}

}  // namespace bench
