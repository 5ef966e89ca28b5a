// Delaunay refinement against CGAL's Delaunay_mesher_2 (Mesh_2), on the rings of a dataset,
// inside only: the same input and minimum angle, time, Steiner points and the worst angle
// inside. Runs alternate (geocdt, CGAL, geocdt, ...); the medians are printed as a markdown
// row. Usage: bench_refine file.gpl minAngle [runs]
//
// CGAL's domain: its constrained edges, each counted as often as input segments lie on it
// (shared borders twice), decide inside by parity in a flood from the infinite face; edges
// that CGAL split at crossings count once. geocdt decides by its own exact windings. The
// inside triangle counts before refinement say how far the two domains agree.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <queue>
#include <utility>
#include <vector>

#include "geocdt/triangulation.h"
#include "polyline_file.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

constexpr double kPi = 3.14159265358979323846;

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

double smallestAngle(const double (&x)[3], const double (&y)[3]) {
  double smallest = 180;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double ux = x[i] - x[k], uy = y[i] - y[k], vx = x[j] - x[k], vy = y[j] - y[k];
    smallest =
        std::min(smallest, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / kPi);
  }
  return smallest;
}

struct Run {
  double seconds = 0;
  std::size_t steiner = 0, inside = 0, insideBefore = 0, bad = 0;
  double worst = 180;
};

Run runGeocdt(const geocdt::testing::PolylineSet& set, double minAngle) {
  Run r;
  const std::vector<geocdt::PolylineView> views = set.views();
  geocdt::Triangulation t;
  const auto start = std::chrono::steady_clock::now();
  t.insertPolylines(views.data(), views.size());
  const auto built = std::chrono::steady_clock::now();
  geocdt::RefineOptions ro;
  ro.minAngle = minAngle;
  ro.keep = geocdt::Keep::Inside;
  t.refine(ro);
  const auto refined = std::chrono::steady_clock::now();
  r.seconds = seconds(built, refined);
  (void)start;
  r.steiner = t.stats().steinerPoints;
  geocdt::MeshOptions mo;
  mo.keep = geocdt::Keep::Inside;
  const geocdt::Mesh m = t.mesh(mo);
  r.inside = m.triangles.size() / 3;
  for (std::size_t i = 0; i < r.inside; ++i) {
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = m.points[2 * m.triangles[3 * i + k]];
      y[k] = m.points[2 * m.triangles[3 * i + k] + 1];
    }
    const double a = smallestAngle(x, y);
    r.worst = std::min(r.worst, a);
    r.bad += a < minAngle * (1 - 1e-9);
  }
  return r;
}

// Parity of input segments on each constrained edge, flooded from the infinite face.
void markDomain(
    Cdt& cdt,
    const std::map<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>, int>& multiplicity) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  std::map<Cdt::Face_handle, int> level;
  std::queue<Cdt::Face_handle> queue;
  level[cdt.infinite_face()] = 0;
  queue.push(cdt.infinite_face());
  while (!queue.empty()) {
    const Cdt::Face_handle f = queue.front();
    queue.pop();
    const int l = level[f];
    if (!cdt.is_infinite(f)) f->set_in_domain(l % 2 == 1);
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle n = f->neighbor(i);
      if (level.count(n)) continue;
      int crossing = 0;
      if (cdt.is_constrained({f, i})) {
        auto a = f->vertex(cdt.cw(i)), b = f->vertex(cdt.ccw(i));
        if (b < a) std::swap(a, b);
        const auto found = multiplicity.find({a, b});
        crossing = found == multiplicity.end() ? 1 : found->second;
      }
      level[n] = l + crossing;
      queue.push(n);
    }
  }
}

Run runCgal(const geocdt::testing::PolylineSet& set, double minAngle) {
  Run r;
  Cdt cdt;
  std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> segments;
  for (std::size_t i = 0; i < set.polylineCount(); ++i) {
    Cdt::Vertex_handle previous;
    for (std::uint32_t k = set.offsets[i]; k < set.offsets[i + 1]; ++k) {
      const Cdt::Vertex_handle v = cdt.insert(K::Point_2(set.xy[2 * k], set.xy[2 * k + 1]));
      if (k > set.offsets[i] && v != previous) segments.push_back({previous, v});
      previous = v;
    }
  }
  std::map<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>, int> multiplicity;
  for (auto [a, b] : segments) {
    cdt.insert_constraint(a, b);
    if (b < a) std::swap(a, b);
    ++multiplicity[{a, b}];
  }
  markDomain(cdt, multiplicity);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    r.insideBefore += f->is_in_domain();
  const std::size_t before = cdt.number_of_vertices();
  const double s = std::sin(minAngle * kPi / 180);
  Mesher mesher(cdt, Criteria(s * s, 0));
  const auto start = std::chrono::steady_clock::now();
  mesher.init(true);
  mesher.refine_mesh();
  r.seconds = seconds(start, std::chrono::steady_clock::now());
  r.steiner = cdt.number_of_vertices() - before;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    ++r.inside;
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = f->vertex(k)->point().x();
      y[k] = f->vertex(k)->point().y();
    }
    const double a = smallestAngle(x, y);
    r.worst = std::min(r.worst, a);
    r.bad += a < minAngle * (1 - 1e-9);
  }
  return r;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_refine file.gpl minAngle [runs]\n");
    return 2;
  }
  geocdt::testing::PolylineSet set;
  const std::string error = geocdt::testing::readPolylineFile(argv[1], set);
  if (!error.empty()) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const double angle = std::atof(argv[2]);
  const int runs = argc > 3 ? std::atoi(argv[3]) : 3;
  std::vector<double> ours, theirs;
  Run g, c;
  for (int i = 0; i < runs; ++i) {
    g = runGeocdt(set, angle);
    ours.push_back(g.seconds);
    c = runCgal(set, angle);
    theirs.push_back(c.seconds);
  }
  std::printf(
      "| engine | min angle | refine s (median of %d) | Steiner points | inside triangles | "
      "worst angle | below min angle |\n| --- | --- | --- | --- | --- | --- | --- |\n",
      runs);
  std::printf("| geocdt | %g | %.3f | %zu | %zu | %.2f | %zu |\n", angle, median(ours), g.steiner,
              g.inside, g.worst, g.bad);
  std::printf("| CGAL Delaunay_mesher_2 | %g | %.3f | %zu | %zu | %.2f | %zu |\n", angle,
              median(theirs), c.steiner, c.inside, c.worst, c.bad);
  std::printf("CGAL inside triangles before refinement: %zu\n", c.insideBefore);
  return 0;
}
