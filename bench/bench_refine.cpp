// Delaunay refinement against CGAL's Delaunay_mesher_2 (Mesh_2), on the rings of a dataset,
// inside only: the same input and minimum angle, time, Steiner points and the worst angle
// inside. Runs alternate (geocdt, CGAL, geocdt, ...); the medians are printed as a markdown
// row. Usage: bench_refine [--exact] file.gpl minAngle [runs]
//
// CGAL's default kernel is Epick with Exact_predicates_tag: fast, but its constructed crossing
// points are rounded, and on rings that cross and overlap (the country rings) the mesher then
// crashes. --exact runs it with Epeck and Exact_intersections_tag instead, exact constructions
// throughout, to see whether CGAL gets through those inputs at all and at what cost.
//
// CGAL's domain: its constrained edges, each counted as often as input segments lie on it
// (shared borders twice), decide inside by parity in a flood from the infinite face; edges
// that CGAL split at crossings count once. geocdt decides by its own exact windings. The
// inside triangle counts before refinement say how far the two domains agree.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "geocdt/triangulation.h"
#include "polyline_file.h"

namespace {

template <class K, class Itag>
using MeshCdt = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>,
                                         CGAL::Delaunay_mesh_face_base_2<K>>,
    Itag>;
// The default: what CGAL's Mesh_2 examples use.
using InexactCdt =
    MeshCdt<CGAL::Exact_predicates_inexact_constructions_kernel, CGAL::Exact_predicates_tag>;
// --exact: crossing points constructed exactly, so crossing and overlapping rings stay
// consistent. Constrained_triangulation_plus_2 computes each crossing from the input segments;
// the bare CDT would compute it from pieces whose ends are earlier crossings, numbers that grow
// with every crossing along a segment (CGAL warns so in debug builds).
using ExactCdt = CGAL::Constrained_triangulation_plus_2<
    MeshCdt<CGAL::Exact_predicates_exact_constructions_kernel, CGAL::Exact_intersections_tag>>;

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
  double seconds = 0, buildSeconds = 0;
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
  r.buildSeconds = seconds(start, built);
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
template <class Cdt, class Vertex = typename Cdt::Vertex_handle>
void markDomain(Cdt& cdt, const std::map<std::pair<Vertex, Vertex>, int>& multiplicity) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  std::map<typename Cdt::Face_handle, int> level;
  std::queue<typename Cdt::Face_handle> queue;
  level[cdt.infinite_face()] = 0;
  queue.push(cdt.infinite_face());
  while (!queue.empty()) {
    const typename Cdt::Face_handle f = queue.front();
    queue.pop();
    const int l = level[f];
    if (!cdt.is_infinite(f)) f->set_in_domain(l % 2 == 1);
    for (int i = 0; i < 3; ++i) {
      const typename Cdt::Face_handle n = f->neighbor(i);
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

template <class Cdt>
Run runCgal(const geocdt::testing::PolylineSet& set, double minAngle) {
  using Vertex = typename Cdt::Vertex_handle;
  Run r;
  Cdt cdt;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<Vertex, Vertex>> segments;
  for (std::size_t i = 0; i < set.polylineCount(); ++i) {
    Vertex previous;
    for (std::uint32_t k = set.offsets[i]; k < set.offsets[i + 1]; ++k) {
      const Vertex v = cdt.insert(typename Cdt::Point(set.xy[2 * k], set.xy[2 * k + 1]));
      if (k > set.offsets[i] && v != previous) segments.push_back({previous, v});
      previous = v;
    }
  }
  std::map<std::pair<Vertex, Vertex>, int> multiplicity;
  for (auto [a, b] : segments) {
    cdt.insert_constraint(a, b);
    if (b < a) std::swap(a, b);
    ++multiplicity[{a, b}];
  }
  r.buildSeconds = seconds(start, std::chrono::steady_clock::now());
  // Said at once: where a run that never ends spends its time.
  std::fprintf(stderr, "CGAL: inserted in %.3f s, %zu vertices; refining\n", r.buildSeconds,
               cdt.number_of_vertices());
  markDomain(cdt, multiplicity);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    r.insideBefore += f->is_in_domain();
  const std::size_t before = cdt.number_of_vertices();
  const double s = std::sin(minAngle * kPi / 180);
  using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
  CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt, Criteria(s * s, 0));
  const auto refining = std::chrono::steady_clock::now();
  mesher.init(true);
  // Point by point, which is what refine_mesh() does (encroached edges first, then bad faces),
  // so that a run that takes minutes says how far it got, once a minute.
  double said = 0;
  for (std::size_t points = 1; mesher.step_by_step_refine_mesh(); ++points) {
    if (points % 64) continue;
    const double now = seconds(refining, std::chrono::steady_clock::now());
    if (now < said + 60) continue;
    said = now;
    std::fprintf(stderr, "CGAL: %zu Steiner points after %.0f s\n", points, now);
  }
  r.seconds = seconds(refining, std::chrono::steady_clock::now());
  r.steiner = cdt.number_of_vertices() - before;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    ++r.inside;
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = CGAL::to_double(f->vertex(k)->point().x());
      y[k] = CGAL::to_double(f->vertex(k)->point().y());
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

// One line a run on stderr as soon as it ends, so that a CGAL run that crashes or is stopped
// still leaves the figures of those before it.
void report(const char* engine, int run, const Run& r) {
  std::fprintf(stderr,
               "run %d, %s: insertion %.3f s, refinement %.3f s, %zu Steiner points, %zu inside "
               "triangles, worst %.2f, %zu below\n",
               run + 1, engine, r.buildSeconds, r.seconds, r.steiner, r.inside, r.worst, r.bad);
}

}  // namespace

int main(int argc, char** argv) {
  const bool exact = argc > 1 && std::string(argv[1]) == "--exact";
  if (exact) {
    --argc;
    ++argv;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_refine [--exact] file.gpl minAngle [runs]\n");
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
  const char* cgal =
      exact ? "CGAL Delaunay_mesher_2 (Epeck, Exact_intersections_tag)" : "CGAL Delaunay_mesher_2";
  std::vector<double> ours, theirs;
  Run g, c;
  for (int i = 0; i < runs; ++i) {
    g = runGeocdt(set, angle);
    report("geocdt", i, g);
    ours.push_back(g.seconds);
    c = exact ? runCgal<ExactCdt>(set, angle) : runCgal<InexactCdt>(set, angle);
    report(cgal, i, c);
    theirs.push_back(c.seconds);
  }
  std::printf(
      "| engine | min angle | refine s (median of %d) | Steiner points | inside triangles | "
      "worst angle | below min angle |\n| --- | --- | --- | --- | --- | --- | --- |\n",
      runs);
  std::printf("| geocdt | %g | %.3f | %zu | %zu | %.2f | %zu |\n", angle, median(ours), g.steiner,
              g.inside, g.worst, g.bad);
  std::printf("| %s | %g | %.3f | %zu | %zu | %.2f | %zu |\n", cgal, angle, median(theirs),
              c.steiner, c.inside, c.worst, c.bad);
  std::printf("CGAL inside triangles before refinement: %zu\n", c.insideBefore);
  return 0;
}
