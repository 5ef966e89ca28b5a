// Hashes of every output array on real data and on each path of the core, for checking that
// a change leaves the results as they were: run it before and after, and compare the lines.
// The cases cover the Natural Earth rings at three scales and the arcs, US counties, snap
// rounding, many random crossings, refinement, values (derivation, interpolation, rasters),
// locate(), polylines one call at a time, a buffer taken over, 2 and 4 threads, and edits
// (removals and moves of points, removals of polylines, snap-rounded ones included).
// Usage: mesh_hashes [--data DIR] [case name prefix...]
// The datasets are written by `node scripts/datasets/natural_earth.mjs DIR` (ctest does it
// into build/data).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"
#include "point_generators.h"
#include "point_sets.h"
#include "polyline_file.h"

#ifndef GEOCDT_BENCH_DATA_DIR
#define GEOCDT_BENCH_DATA_DIR "build/data"
#endif

namespace {

// FNV-1a over the bytes of an array, with its length.
class Hash {
 public:
  void bytes(const void* data, std::size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

// Prints one line per array and folds each into the case's hash and the run's.
class Report {
 public:
  explicit Report(std::string name) : name_(std::move(name)) {}

  template <typename T>
  void add(const char* array, const T* data, std::size_t size) {
    Hash h;
    const std::uint64_t n = size;
    h.bytes(&n, sizeof n);
    h.bytes(data, size * sizeof(T));
    std::printf("%-24s %-16s %10zu  %016llx\n", name_.c_str(), array, size,
                static_cast<unsigned long long>(h.value()));
    const std::uint64_t v = h.value();
    whole_.bytes(&v, sizeof v);
  }
  template <typename T>
  void add(const char* array, const std::vector<T>& v) {
    add(array, v.data(), v.size());
  }

  void add(const geocdt::Mesh& m) {
    add("points", m.points);
    add("triangles", m.triangles);
    add("halfedges", m.halfedges);
    add("constrained", m.constrained);
    add("constraintEdges", m.constraintEdges);
    add("sourceOffsets", m.sourceOffsets);
    add("sources", m.sources);
    add("segmentOffsets", m.segmentOffsets);
    add("segmentSources", m.segmentSources);
    add("inside", m.inside);
    add("regions", m.regions);
    add("values", m.values);
    add("derivedVertices", m.derivedVertices);
    add("derivedOffsets", m.derivedOffsets);
    add("derivedParents", m.derivedParents);
    add("derivedWeights", m.derivedWeights);
    add("steiner", m.steiner);
    add("steinerParents", m.steinerParents);
    add("steinerWeights", m.steinerWeights);
    if (!m.vertexIds.empty()) add("vertexIds", m.vertexIds);
  }

  // The counters too: walks, flips and fallbacks move when the algorithm does.
  void add(const geocdt::Stats& s) {
    const std::uint64_t counters[] = {
        s.inserted,      s.duplicates,      s.walkSteps,          s.locates,       s.flips,
        s.walkFallbacks, s.gridSize,        s.crossings,          s.polylines,     s.segments,
        s.snapRoundings, s.valueDuplicates, s.valueDisagreements, s.steinerPoints, s.refineSkipped,
        s.refineCapped,  s.threads};
    add("stats", counters, sizeof counters / sizeof counters[0]);
  }

  std::uint64_t value() const { return whole_.value(); }

 private:
  std::string name_;
  Hash whole_;
};

struct Data {
  std::string dir;
  geocdt::testing::PolylineSet rings(const std::string& name) const {
    geocdt::testing::PolylineSet set;
    const std::string error = geocdt::testing::readPolylineFile(dir + "/" + name + ".gpl", set);
    if (!error.empty()) {
      std::fprintf(stderr, "mesh_hashes: %s\n", error.c_str());
      std::exit(1);
    }
    return set;
  }
  std::vector<std::int32_t> polygons(const std::string& name) const {
    std::vector<std::int32_t> polygons;
    const std::string error = geocdt::testing::readPolygonFile(dir + "/" + name + ".gpg", polygons);
    if (!error.empty()) {
      std::fprintf(stderr, "mesh_hashes: %s\n", error.c_str());
      std::exit(1);
    }
    return polygons;
  }
};

void check(const geocdt::Status& s, const std::string& name) {
  if (s.ok()) return;
  std::fprintf(stderr, "mesh_hashes: %s: %s\n", name.c_str(), s.message.c_str());
  std::exit(1);
}

geocdt::MeshOptions everything(std::vector<std::int32_t> polygons = {}) {
  geocdt::MeshOptions o;
  o.insideFlags = true;
  o.segmentSources = true;
  o.regions = !polygons.empty();
  o.polylinePolygons = std::move(polygons);
  return o;
}

// Two values a point, smooth and signed, with NaN at every 97th point.
std::vector<double> valuesOf(const std::vector<double>& xy) {
  const std::size_t n = xy.size() / 2;
  std::vector<double> values(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    values[2 * i] = i % 97 == 0 ? NAN : std::sin(xy[2 * i] * 0.1) + xy[2 * i + 1];
    values[2 * i + 1] = xy[2 * i] * xy[2 * i + 1];
  }
  return values;
}

// Query points over the bounding box of xy, a few outside it.
std::vector<double> queriesOver(const std::vector<double>& xy, std::size_t count) {
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  for (std::size_t i = 0; i < xy.size(); i += 2) {
    minX = std::fmin(minX, xy[i]), maxX = std::fmax(maxX, xy[i]);
    minY = std::fmin(minY, xy[i + 1]), maxY = std::fmax(maxY, xy[i + 1]);
  }
  const std::vector<double> unit = bench::uniformPointsMt19937(count, 11);
  std::vector<double> q(2 * count);
  for (std::size_t i = 0; i < count; ++i) {
    q[2 * i] = minX - 0.01 * (maxX - minX) + unit[2 * i] * 1.02 * (maxX - minX);
    q[2 * i + 1] = minY - 0.01 * (maxY - minY) + unit[2 * i + 1] * 1.02 * (maxY - minY);
  }
  return q;
}

using Case = std::function<void(Report&)>;

// The polylines of a file in one insertPolylines call, everything exported.
Case polylineCase(const Data& data, const std::string& file, geocdt::Options options = {},
                  bool withPolygons = true) {
  return [=, &data](Report& r) {
    const geocdt::testing::PolylineSet set = data.rings(file);
    const std::vector<geocdt::PolylineView> views = set.views();
    geocdt::Triangulation t(options);
    std::vector<std::uint32_t> ids(set.pointCount());
    check(t.insertPolylines(views.data(), views.size(), ids.data()), file);
    r.add("inputToVertex", ids);
    r.add(t.stats());
    r.add(t.release(everything(withPolygons ? data.polygons(file) : std::vector<std::int32_t>())));
  };
}

Case refineCase(const Data& data, const std::string& file, geocdt::RefineOptions refine) {
  return [=, &data](Report& r) {
    const geocdt::testing::PolylineSet set = data.rings(file);
    const std::vector<geocdt::PolylineView> views = set.views();
    geocdt::Triangulation t;
    check(t.insertPolylines(views.data(), views.size()), file);
    check(t.refine(refine), file);
    r.add(t.stats());
    geocdt::MeshOptions o = everything(data.polygons(file));
    o.keep = refine.keep;
    r.add(t.release(o));
  };
}

Case valuesCase(const Data& data, const std::string& file) {
  return [=, &data](Report& r) {
    const geocdt::testing::PolylineSet set = data.rings(file);
    const std::vector<geocdt::PolylineView> views = set.views();
    geocdt::Options options;
    options.valuesPerPoint = 2;
    geocdt::Triangulation t(options);
    const std::vector<double> values = valuesOf(set.xy);
    check(t.insertPolylines(views.data(), views.size(), nullptr, values.data()), file);
    geocdt::RefineOptions refine;
    refine.minAngle = 25;
    refine.keep = geocdt::Keep::Inside;
    check(t.refine(refine), file);
    const std::vector<double> q = queriesOver(set.xy, 20000);
    std::vector<double> out(q.size());
    t.interpolate(q.data(), q.size() / 2, geocdt::Interpolation::Linear, out.data());
    r.add("linear", out);
    t.interpolate(q.data(), q.size() / 2, geocdt::Interpolation::Natural, out.data());
    r.add("natural", out);
    geocdt::RasterGrid grid{-180, -90, 180, 90, 360, 180};
    std::vector<float> raster(grid.width * grid.height * 2);
    check(t.rasterize(grid, geocdt::Interpolation::Linear, raster.data()), file);
    r.add("rasterLinear", raster);
    check(t.rasterize(grid, geocdt::Interpolation::Natural, raster.data()), file);
    r.add("rasterNatural", raster);
    r.add(t.stats());
    r.add(t.release(everything()));
  };
}

// locate() at query points, and polylines inserted one call at a time after the points.
Case incrementalCase(const Data& data, const std::string& file) {
  return [=, &data](Report& r) {
    const geocdt::testing::PolylineSet set = data.rings(file);
    geocdt::Triangulation t;
    const std::vector<double> q = queriesOver(set.xy, 5000);
    check(t.insertPoints(q.data(), q.size() / 2), file);
    for (std::size_t i = 0; i < set.polylineCount(); ++i) {
      const geocdt::PolylineView v = set.view(i);
      check(t.insertPolyline(v.xy, v.count), file);
    }
    std::vector<std::int64_t> located;
    for (std::size_t i = 0; i < q.size(); i += 2) {
      const geocdt::Location l = t.locate(q[i] * 0.999, q[i + 1] * 1.001);
      located.insert(located.end(), {static_cast<std::int64_t>(l.kind), l.triangle, l.vertices[0],
                                     l.vertices[1], l.vertices[2]});
    }
    r.add("locate", located);
    r.add(t.stats());
    r.add(t.release(everything()));
  };
}

// The edits' counter, on a line of its own (the other cases' lines stay as they were).
void addRemoved(Report& r, const geocdt::Stats& s) {
  const std::uint64_t removed = s.removed;
  r.add("removed", &removed, 1);
}

// The triangles by vertex id, each from its least id, sorted: the mesh whatever slots its
// triangles took (edits may reuse slots in another order and still make the same mesh).
void addCanonical(Report& r, const geocdt::Mesh& m) {
  std::vector<std::array<std::uint32_t, 3>> t(m.triangles.size() / 3);
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::uint32_t v[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t local = m.triangles[3 * i + k];
      v[k] = m.vertexIds.empty() ? local : m.vertexIds[local];
    }
    const int first = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    t[i] = {v[first], v[(first + 1) % 3], v[(first + 2) % 3]};
  }
  std::sort(t.begin(), t.end());
  r.add("canonical", t.data(), t.size());
}

// Points removed and moved one call each, in an order of their own, on n uniform points.
Case pointEditsCase(std::size_t n) {
  return [=](Report& r) {
    const std::vector<double> xy = bench::uniformPointsMt19937(n, 13);
    const std::vector<double> to = bench::uniformPointsMt19937(n / 5, 17);
    geocdt::Triangulation t;
    std::vector<std::uint32_t> ids(n);
    check(t.insertPoints(xy.data(), n, ids.data()), "points");
    // Every 5th point removed, every 5th from the 2nd moved, in a scattered order.
    for (std::size_t k = 0; k < n / 5; ++k) {
      const std::size_t i = (k * 7919) % (n / 5);
      check(t.removePoint(ids[5 * i]), "removePoint");
      check(t.movePoint(ids[5 * i + 1], to[2 * i], to[2 * i + 1]), "movePoint");
    }
    r.add(t.stats());
    addRemoved(r, t.stats());
    const geocdt::Mesh m = t.release();
    addCanonical(r, m);
    r.add(m);
  };
}

// A file's polylines with points among them; then every 4th polyline removed, every 3rd
// point removed, and every 50th polyline's first vertex moved a little.
Case polylineEditsCase(const Data& data, const std::string& file, geocdt::Options options = {}) {
  return [=, &data](Report& r) {
    const geocdt::testing::PolylineSet set = data.rings(file);
    const std::vector<geocdt::PolylineView> views = set.views();
    geocdt::Triangulation t(options);
    const std::vector<double> q = queriesOver(set.xy, 3000);
    std::vector<std::uint32_t> pointIds(q.size() / 2), ids(set.pointCount());
    check(t.insertPoints(q.data(), q.size() / 2, pointIds.data()), file);
    check(t.insertPolylines(views.data(), views.size(), ids.data()), file);
    for (std::size_t i = 0; i < views.size(); i += 4) check(t.removePolyline(i), file);
    for (std::size_t i = 0; i < pointIds.size(); i += 3) check(t.removePoint(pointIds[i]), file);
    for (std::size_t i = 1; i < views.size(); i += 50) {
      const std::size_t first = set.offsets[i];
      const double x = set.xy[2 * first], y = set.xy[2 * first + 1];
      check(t.movePoint(ids[first], x + 1e-3, y - 1e-3), file);
    }
    r.add(t.stats());
    addRemoved(r, t.stats());
    const geocdt::Mesh m = t.release(everything());
    addCanonical(r, m);
    r.add(m);
  };
}

// insertPolylines taking over a buffer in GeoArrow's layout.
Case adoptedCase(const Data& data, const std::string& file) {
  return [=, &data](Report& r) {
    geocdt::testing::PolylineSet set = data.rings(file);
    geocdt::Triangulation t;
    std::vector<std::uint32_t> ids(set.pointCount());
    const std::vector<std::uint32_t> offsets = set.offsets;
    check(t.insertPolylines(std::move(set.xy), offsets.data(), offsets.size() - 1, ids.data()),
          file);
    r.add("inputToVertex", ids);
    r.add(t.stats());
    r.add(t.release(everything(data.polygons(file))));
  };
}

Case pointsCase(std::vector<double> xy, std::uint32_t threads) {
  return [=](Report& r) {
    geocdt::Options options;
    options.threads = threads;
    geocdt::Triangulation t(options);
    std::vector<std::uint32_t> ids(xy.size() / 2);
    check(t.insertPoints(xy.data(), xy.size() / 2, ids.data()), "points");
    r.add("inputToVertex", ids);
    r.add(t.stats());
    r.add(t.release());
  };
}

Case segmentsCase(std::size_t count) {
  return [=](Report& r) {
    const geocdt::testing::PolylineSet set = bench::randomSegments(count, 7);
    const std::vector<geocdt::PolylineView> views = set.views();
    geocdt::Triangulation t;
    check(t.insertPolylines(views.data(), views.size()), "segments");
    r.add(t.stats());
    r.add(t.release(everything()));
  };
}

}  // namespace

int main(int argc, char** argv) {
  Data data{GEOCDT_BENCH_DATA_DIR};
  std::vector<std::string> only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--data") == 0 && i + 1 < argc) {
      data.dir = argv[++i];
    } else if (argv[i][0] == '-') {
      std::fprintf(stderr, "usage: mesh_hashes [--data DIR] [case name prefix...]\n");
      return 2;
    } else {
      only.push_back(argv[i]);
    }
  }
  geocdt::Options always;
  always.snapRounding = geocdt::SnapRounding::Always;
  geocdt::Options twoThreads, fourThreads;
  twoThreads.threads = 2;
  fourThreads.threads = 4;
  geocdt::RefineOptions counties20, ne25, uniform30;
  counties20.minAngle = 20;
  counties20.keep = geocdt::Keep::Inside;
  ne25.minAngle = 25;
  uniform30.minAngle = 30;
  uniform30.maxArea = 1e-4;
  const std::pair<const char*, Case> cases[] = {
      {"ne_110m_rings", polylineCase(data, "ne_110m_rings")},
      {"ne_50m_rings", polylineCase(data, "ne_50m_rings")},
      {"ne_10m_rings", polylineCase(data, "ne_10m_rings")},
      {"ne_10m_arcs", polylineCase(data, "ne_10m_arcs", {}, false)},
      {"us_counties_rings", polylineCase(data, "us_counties_rings")},
      {"ne_110m_snap_always", polylineCase(data, "ne_110m_rings", always)},
      {"ne_50m_snap_always", polylineCase(data, "ne_50m_rings", always)},
      {"random_segments_3000", segmentsCase(3000)},
      {"refine_counties_20_in", refineCase(data, "us_counties_rings", counties20)},
      {"refine_ne_50m_25", refineCase(data, "ne_50m_rings", ne25)},
      {"values_ne_50m", valuesCase(data, "ne_50m_rings")},
      {"incremental_ne_110m", incrementalCase(data, "ne_110m_rings")},
      {"adopted_ne_50m", adoptedCase(data, "ne_50m_rings")},
      {"uniform_300k_1thread", pointsCase(bench::uniformPointsMt19937(300000, 3), 1)},
      {"uniform_300k_2threads", pointsCase(bench::uniformPointsMt19937(300000, 3), 2)},
      {"uniform_300k_4threads", pointsCase(bench::uniformPointsMt19937(300000, 3), 4)},
      {"clusters_200k_2threads", pointsCase(bench::clustersOfManySpreads(200000, 5), 2)},
      {"lattice_300_2threads", pointsCase(geocdt::testing::latticePoints(300), 2)},
      {"ne_10m_rings_2threads", polylineCase(data, "ne_10m_rings", twoThreads)},
      {"edits_uniform_100k", pointEditsCase(100000)},
      {"edits_counties", polylineEditsCase(data, "us_counties_rings")},
      {"edits_ne_110m_snap", polylineEditsCase(data, "ne_110m_rings", always)},
  };
  Hash all;
  for (const auto& [name, run] : cases) {
    bool wanted = only.empty();
    for (const std::string& prefix : only) wanted |= std::string(name).rfind(prefix, 0) == 0;
    if (!wanted) continue;
    Report report(name);
    run(report);
    const std::uint64_t v = report.value();
    std::printf("%-24s %-16s %10s  %016llx\n", name, "(case)", "",
                static_cast<unsigned long long>(v));
    all.bytes(&v, sizeof v);
  }
  std::printf("%-24s %-16s %10s  %016llx\n", "(all)", "", "",
              static_cast<unsigned long long>(all.value()));
  return 0;
}
