// A large first batch of points on several threads. The points are cut into vertical strips
// at quantiles of x; each strip is triangulated on a thread of its own, into its own range of
// the shared slots; then the strips are joined along their seams.
//
// The join rests on one fact: a triangle of a strip whose circumcircle lies inside the strip's
// slab (lo <= x < hi) has no point of any other strip in its circle, so it is a Delaunay
// triangle of all the points and stays as it is. The others (near the seams, and along each
// strip's hull) are replaced. Their vertices, the seam vertices, are triangulated on their own
// (a few per thousand points), with the edges where kept triangles meet replaced ones as
// constraints; the part of that triangulation outside the kept triangles is exactly what the
// replaced ones leave to fill. Where four points are cocircular the strips and the seam may
// choose different diagonals: the constraints make the seam agree with the kept triangles,
// and the result is still a Delaunay triangulation. Without cocircular points it is the same
// set of triangles as one thread makes.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "base/in_parallel.h"
#include "constraints/segment_inserter.h"
#include "delaunay/delaunay.h"
#include "delaunay/first_triangle.h"
#include "delaunay/insertion_order.h"
#include "delaunay/vertex_edges.h"
#include "geocdt/predicates.h"

namespace geocdt {

// Below this many points a strip costs more in threads and seams than it saves.
constexpr std::uint32_t kMinStripPoints = 16384;

bool Delaunay::wantsStrips(std::uint32_t count) const {
#ifdef GEOCDT_THREADS
  return options_.threads > 1 && count / kMinStripPoints >= 2 && !built_ && pending_.empty() &&
         firstSlot_ < 0 && !constrained() && options_.start == LocateStart::LastTriangle;
#else
  (void)count;
  return false;  // a build without threads
#endif
}

#ifdef GEOCDT_THREADS
namespace {

// The x values that cut count points into k strips of about equal size: strip s holds the
// points with cuts[s - 1] <= x < cuts[s]. From a sample of the points, which is plenty for
// balance. Empty when the points do not spread over k distinct x values enough.
std::vector<double> stripCuts(const double* xy, std::uint32_t count, std::uint32_t k) {
  const std::uint32_t step = std::max<std::uint32_t>(1, count / 65536);
  std::vector<double> sample;
  sample.reserve(count / step + 1);
  for (std::uint32_t i = 0; i < count; i += step) sample.push_back(xy[2 * i]);
  std::sort(sample.begin(), sample.end());
  std::vector<double> cuts;
  for (std::uint32_t s = 1; s < k; ++s) {
    const double cut = sample[sample.size() * s / k];
    if (!cuts.empty() && cut <= cuts.back()) return {};
    if (cut <= sample.front()) return {};
    cuts.push_back(cut);
  }
  return cuts;
}

// Whether the circumcircle of a, b, c (counter-clockwise) lies in lo <= x < hi, with room
// for every rounding error of its computation: when in doubt, no. The sides are scaled by a
// power of two (exactly) to about 1 first, so that their squares neither overflow nor
// underflow at the ends of the coordinate range.
bool circleInSlab(const double* p, std::uint32_t a, std::uint32_t b, std::uint32_t c, double lo,
                  double hi) {
  const double ax = p[2 * a], ay = p[2 * a + 1];
  double bx = p[2 * b] - ax, by = p[2 * b + 1] - ay;
  double cx = p[2 * c] - ax, cy = p[2 * c + 1] - ay;
  const double longest =
      std::max(std::max(std::fabs(bx), std::fabs(by)), std::max(std::fabs(cx), std::fabs(cy)));
  if (!(longest > 0) || !std::isfinite(longest)) return false;
  int exponent = 0;
  std::frexp(longest, &exponent);
  bx = std::ldexp(bx, -exponent);
  by = std::ldexp(by, -exponent);
  cx = std::ldexp(cx, -exponent);
  cy = std::ldexp(cy, -exponent);
  const double bb = bx * bx + by * by, cc = cx * cx + cy * cy;
  const double cross = std::fabs(bx * cy) + std::fabs(by * cx);
  const double d = 2 * (bx * cy - by * cx);
  if (!(std::fabs(d) > 1e-6 * cross)) return false;  // nearly collinear: a huge circle anyway
  const double ux = (cy * bb - by * cc) / d, uy = (bx * cc - cx * bb) / d;
  const double r = std::sqrt(ux * ux + uy * uy);
  // Each quantity above carries a relative error of a few units of 2^-53 of its terms'
  // magnitudes; the sum below bounds the centre's and the radius's errors with a wide margin
  // (the translation by a included, through |ax| and the sides' rounding).
  const double magnitude =
      ((std::fabs(cy) + std::fabs(cx)) * bb + (std::fabs(by) + std::fabs(bx)) * cc) / std::fabs(d) +
      (std::fabs(ux) + std::fabs(uy)) * 2 * cross / std::fabs(d) + std::fabs(ux) + std::fabs(uy) +
      r + 1;
  const double error = 64 * std::numeric_limits<double>::epsilon() *
                       (std::ldexp(magnitude, exponent) + std::fabs(ax));
  const double centre = ax + std::ldexp(ux, exponent), radius = std::ldexp(r, exponent);
  return centre - radius - error >= lo && centre + radius + error < hi;
}

// A strip's share of the join, found on its own thread.
struct StripSeam {
  std::vector<std::int32_t> holes;      // slots to refill: replaced triangles, unused slots
  std::vector<std::uint32_t> vertices;  // corners of replaced triangles
  std::vector<std::int32_t> borders;    // half-edges of kept triangles facing replaced ones
};

// Finds the strip's triangles to replace, from ghost, one of its ghost triangles, and lists
// its share of the join; its slots are [first, used), and [used, end) are unused. A triangle
// whose circumcircle reaches past the slab holds in its circle a point q outside the strip's
// hull, and the triangles whose circles hold q are connected to the ghost triangles (they are
// what inserting q would replace): a flood from the ghosts through the triangles that fail
// the test finds all of them, and only touches the seams. Those it does not reach are kept
// even when the test was only unsure. `state` (per slot: 0 to replace, 1 untested, 2 kept)
// and `seen` (per vertex) are shared: the strip writes only its own slots and vertices.
void findSeam(const Delaunay& d, std::int32_t ghost, std::int32_t first, std::int32_t used,
              std::int32_t end, double lo, double hi, std::vector<std::uint8_t>& state,
              std::vector<std::uint8_t>& seen, StripSeam& seam) {
  const double* p = d.xy.data();
  const std::uint32_t* tri = d.topo.tri.data();
  const std::int32_t* adj = d.topo.adj.data();
  std::fill(state.begin() + first, state.begin() + end, 1);
  const auto replaced = [&](std::int32_t t) {
    const std::uint32_t a = tri[3 * t], b = tri[3 * t + 1], c = tri[3 * t + 2];
    return a == kGhost || b == kGhost || c == kGhost || !circleInSlab(p, a, b, c, lo, hi);
  };
  std::vector<std::int32_t> stack{ghost};
  state[ghost] = 0;
  while (!stack.empty()) {
    const std::int32_t t = stack.back();
    stack.pop_back();
    seam.holes.push_back(t);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = tri[3 * t + k];
      if (v != kGhost && !seen[v]) {
        seen[v] = 1;
        seam.vertices.push_back(v);
      }
      const std::int32_t twin = adj[3 * t + k], n = twin / 3;
      if (state[n] == 0) continue;
      if (state[n] == 1) state[n] = replaced(n) ? 0 : 2;
      if (state[n] == 0) {
        stack.push_back(n);
      } else {
        seam.borders.push_back(twin);
      }
    }
  }
  std::sort(seam.holes.begin(), seam.holes.end());
  for (std::int32_t t = used; t < end; ++t) seam.holes.push_back(t);
}

Status broken(const char* what) {
  return {StatusCode::InternalError, std::string("joining the strips: ") + what};
}

// The seam's own triangulation, and what joinStrips learns of it step by step.
//
//      strip 0 : strip 1          The strips' triangles whose circles cross a cut (:)
//     kept  /\/:\/\  kept         or reach past a strip's hull are replaced. Their
//          / /\:/\ \              vertices are triangulated again on their own, with the
//      border  seam  border       borders (edges between kept and replaced triangles) as
//                                 constraints; the part beyond the borders is dropped.
struct Seam {
  explicit Seam(const Options& options) : z(options) {}
  Delaunay z;                          // the seam vertices triangulated on their own
  std::vector<std::uint32_t> vertex;   // seam vertex i is vertex[i] of the strips
  std::vector<std::uint8_t> dropped;   // per slot of z: on the kept triangles' side
  std::vector<std::int32_t> borderOf;  // per half-edge of z on a border: the kept half-edge
  std::vector<std::int32_t> holes;     // the strips' slots to refill, lowest first per strip
  std::size_t filled = 0;              // holes taken by z's triangles
  std::int32_t last = -1;              // a real triangle, for the next walk
};

Options seamOptions(const Options& options) {
  Options o = options;
  o.threads = 1;
  o.progress = Progress();
  return o;
}

// The seam vertices, triangulated on their own.
Status triangulateSeam(const Delaunay& d, std::vector<StripSeam>& seams, Seam& seam) {
  std::vector<std::uint32_t>& seamVertex = seam.vertex;
  for (StripSeam& s : seams) {
    seamVertex.insert(seamVertex.end(), s.vertices.begin(), s.vertices.end());
    std::vector<std::uint32_t>().swap(s.vertices);
  }
  const double* p = d.xy.data();
  std::vector<double> coords(2 * seamVertex.size());
  for (std::size_t i = 0; i < seamVertex.size(); ++i) {
    coords[2 * i] = p[2 * seamVertex[i]];
    coords[2 * i + 1] = p[2 * seamVertex[i] + 1];
  }
  std::vector<std::uint32_t> zid(seamVertex.size());
  const Status s = seam.z.insertBatch(std::move(coords), zid.data());
  if (!s.ok()) return s;
  if (seam.z.vertexCount() != seamVertex.size()) return broken("seam vertices repeat");
  return Status::success();
}

// The borders, as constraints of the seam's triangulation: then its triangles on their far
// side are the kept triangles' region, to drop.
Status dropKeptSide(const Delaunay& d, const std::vector<StripSeam>& seams, Seam& seam) {
  Delaunay& z = seam.z;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> seamOf(seam.vertex.size());
  for (std::uint32_t i = 0; i < seam.vertex.size(); ++i) seamOf[i] = {seam.vertex[i], i};
  std::sort(seamOf.begin(), seamOf.end());
  const auto local = [&](std::uint32_t v) {
    const auto it =
        std::lower_bound(seamOf.begin(), seamOf.end(), std::make_pair(v, std::uint32_t{0}));
    return it != seamOf.end() && it->first == v ? it->second : kGhost;
  };
  const std::uint32_t* tri = d.topo.tri.data();
  VertexEdges ends;
  ends.build(z);
  SegmentInserter inserter(z, ends);
  struct Border {
    std::uint32_t u, v;  // its ends among the seam vertices
    std::int32_t kept;   // its half-edge in the kept triangle
  };
  std::vector<Border> borders;
  for (const StripSeam& strip : seams)
    for (const std::int32_t e : strip.borders) {
      const std::uint32_t u = local(tri[e]), v = local(tri[nextEdge(e)]);
      if (u == kGhost || v == kGhost) return broken("a border's end is not a seam vertex");
      borders.push_back({u, v, e});
      if (inserter.insert(u, v, EdgeSource{}) != Outcome::Inserted) return inserter.error();
    }
  const Topology& zt = z.topo;
  std::vector<std::uint8_t>& dropped = seam.dropped;
  dropped.assign(static_cast<std::size_t>(zt.slotCount()), 0);
  seam.borderOf.assign(zt.tri.size(), -1);
  std::vector<std::int32_t> stack;
  for (const Border& b : borders) {
    const std::int32_t h = zt.edgeAround(ends.find(z, b.u), b.v);
    if (h < 0 || !zt.fixed[h]) return broken("a border is missing from the seam");
    seam.borderOf[h] = b.kept;
    if (!dropped[h / 3]) {
      dropped[h / 3] = 1;
      stack.push_back(h / 3);
    }
  }
  while (!stack.empty()) {
    const std::int32_t t = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      const std::int32_t e = 3 * t + k;
      if (zt.fixed[e] || dropped[zt.adj[e] / 3]) continue;
      dropped[zt.adj[e] / 3] = 1;
      stack.push_back(zt.adj[e] / 3);
    }
  }
  return Status::success();
}

// The seam's other triangles fill the holes, lowest slots first, joined to each other and to
// the kept triangles across the borders.
Status fillHoles(Delaunay& d, std::vector<StripSeam>& seams, Seam& seam) {
  const Topology& zt = seam.z.topo;
  std::vector<std::int32_t>& holes = seam.holes;
  for (StripSeam& strip : seams) {
    holes.insert(holes.end(), strip.holes.begin(), strip.holes.end());
    std::vector<std::int32_t>().swap(strip.holes);
  }
  std::vector<std::int32_t> slotOf(static_cast<std::size_t>(zt.slotCount()), -1);
  for (std::int32_t t = 0; t < zt.slotCount(); ++t) {
    if (seam.dropped[t]) continue;
    if (seam.filled == holes.size()) return broken("more seam triangles than holes");
    slotOf[t] = holes[seam.filled++];
  }
  Topology& topo = d.topo;
  for (std::int32_t t = 0; t < zt.slotCount(); ++t) {
    if (seam.dropped[t]) continue;
    const std::int32_t g = slotOf[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = zt.tri[3 * t + k];
      topo.tri[3 * g + k] = v == kGhost ? kGhost : seam.vertex[v];
      topo.fixed[3 * g + k] = 0;
      const std::int32_t twin = zt.adj[3 * t + k];
      std::int32_t to;
      if (!seam.dropped[twin / 3]) {
        to = 3 * slotOf[twin / 3] + twin % 3;
      } else {
        to = seam.borderOf[twin];
        if (to < 0) return broken("a seam triangle meets a dropped one off the borders");
        topo.adj[to] = 3 * g + k;
      }
      topo.adj[3 * g + k] = to;
    }
    if (seam.last < 0 && !zt.isGhost(t)) seam.last = g;
  }
  return Status::success();
}

// Holes left below the final count of `slots` take the triangles above it.
Status closeHoles(Delaunay& d, std::int32_t slots, Seam& seam) {
  Topology& topo = d.topo;
  const std::vector<std::int32_t>& holes = seam.holes;
  std::int32_t from = static_cast<std::int32_t>(topo.slotCount()) - 1;
  std::vector<std::uint8_t> isHole;  // for the slots at and above `slots` only
  isHole.assign(static_cast<std::size_t>(topo.slotCount() - slots), 0);
  for (std::size_t i = seam.filled; i < holes.size(); ++i)
    if (holes[i] >= slots) isHole[holes[i] - slots] = 1;
  for (std::size_t i = seam.filled; i < holes.size() && holes[i] < slots; ++i) {
    while (from >= slots && isHole[from - slots]) --from;
    if (from < slots) return broken("too few triangles to close the holes");
    const std::int32_t to = holes[i];
    for (int k = 0; k < 3; ++k) {
      topo.tri[3 * to + k] = topo.tri[3 * from + k];
      topo.fixed[3 * to + k] = topo.fixed[3 * from + k];
      const std::int32_t twin = topo.adj[3 * from + k];
      topo.adj[3 * to + k] = twin;
      topo.adj[twin] = 3 * to + k;
    }
    if (seam.last == from) seam.last = to;
    --from;
  }
  topo.resizeSlots(static_cast<std::size_t>(slots));
  return Status::success();
}

// Replaces the strips' triangles that findSeam did not keep by the seam's triangulation and
// closes the slots up to `slots` in all.
Status joinStrips(Delaunay& d, const Options& options, std::vector<StripSeam>& seams,
                  std::int32_t slots, Stats& stats) {
  Seam seam(seamOptions(options));
  Status s = triangulateSeam(d, seams, seam);
  if (s.ok()) s = dropKeptSide(d, seams, seam);
  if (s.ok()) s = fillHoles(d, seams, seam);
  if (!s.ok()) return s;
  stats.flips += seam.z.stats.flips;
  stats.walkSteps += seam.z.stats.walkSteps;
  stats.locates += seam.z.stats.locates;
  s = closeHoles(d, slots, seam);
  if (!s.ok()) return s;
  d.setLastTriangle(seam.last >= 0 ? seam.last : 0);
  return Status::success();
}

// The strips of a batch: where they are cut, their points, boxes and slots.
struct Strips {
  std::uint32_t k = 0;
  std::vector<double> cuts;                       // stripCuts'
  std::vector<std::vector<std::uint32_t>> order;  // strip s's points in insertion order
  std::vector<Bounds> box;
  std::vector<std::int32_t> first;  // strip s has the slots [first[s], first[s + 1])

  std::pair<double, double> slab(std::uint32_t s) const {
    const double inf = std::numeric_limits<double>::infinity();
    return {s == 0 ? -inf : cuts[s - 1], s + 1 == k ? inf : cuts[s]};
  }
};

// Each strip gathers its points from all of them (a pass over x per thread costs less than a
// pass that hands them out) and puts them in insertion order. False when a strip has too
// few points to pay for itself.
bool gatherStrips(const double* p, std::uint32_t count, InsertionOrder order, Strips& strips) {
  const std::uint32_t k = strips.k;
  strips.order.assign(k, {});
  strips.box.assign(k, {});
  const double inf = std::numeric_limits<double>::infinity();
  inParallel(k, [&](std::uint32_t s) {
    const double lo = strips.slab(s).first, hi = strips.slab(s).second;
    std::vector<std::uint32_t> mine;
    mine.reserve(count / k + count / 32);
    Bounds b{inf, inf, -inf, -inf};
    forChunks(0, count, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const double x = p[2 * i];
        if (x < lo || x >= hi) continue;
        const double y = p[2 * i + 1];
        mine.push_back(static_cast<std::uint32_t>(i));
        b.minX = std::min(b.minX, x);
        b.maxX = std::max(b.maxX, x);
        b.minY = std::min(b.minY, y);
        b.maxY = std::max(b.maxY, y);
      }
    });
    strips.box[s] = b;
    if (mine.size() < kMinStripPoints / 2) return;  // too few: checked below
    strips.order[s] =
        insertionOrder(p, mine.data(), static_cast<std::uint32_t>(mine.size()), order);
  });
  for (std::uint32_t s = 0; s < k; ++s)
    if (strips.order[s].size() < kMinStripPoints / 2) return false;
  return true;
}

// Each strip's slots: two a point are enough (a strip of n points uses 2n - 2). The arrays
// are sized side by side: most of their cost is the first touch of fresh memory, which one
// thread would pay alone (bench/EXPERIMENTS.md, T1).
void allocateStripSlots(Topology& topo, Strips& strips, std::uint32_t* ids, std::uint32_t count) {
  const std::uint32_t k = strips.k;
  strips.first.assign(k + 1, 0);
  for (std::uint32_t s = 0; s < k; ++s)
    strips.first[s + 1] = strips.first[s] + 2 * static_cast<std::int32_t>(strips.order[s].size());
  const std::uint32_t jobs = std::min(k, 3u);
  const std::size_t halfEdges = 3 * static_cast<std::size_t>(strips.first[k]);
  inParallel(jobs, [&](std::uint32_t job) {
    if (job == 0) topo.tri.resize(halfEdges);
    if (job == 1) topo.adj.resize(halfEdges);
    if (job == (jobs == 3 ? 2 : 0)) {  // the lighter arrays, with a job of their own if any
      topo.fixed.resize(halfEdges);
      std::fill(ids, ids + count, kGhost);
    }
  });
}

// What one strip's thread left: its status, the slots it used, one of its ghost triangles
// (where its share of the seam is looked for) and its counters.
struct StripRun {
  Status status;
  std::int32_t used = 0;
  std::int32_t ghost = -1;
  Stats stats;
};

// Triangulates each strip on a thread of its own into d's slots; returns the threads that ran.
std::uint32_t triangulateStrips(Delaunay& d, const Strips& strips, std::uint32_t* ids,
                                std::vector<StripRun>& runs) {
  Options workerOptions = d.options();
  workerOptions.threads = 1;
  workerOptions.progress = Progress();  // the caller's callback is not for other threads
  runs.assign(strips.k, {});
  return inParallel(strips.k, [&](std::uint32_t s) {
    Delaunay worker(workerOptions, d, strips.first[s]);
    StripRun& run = runs[s];
    const std::vector<std::uint32_t>& order = strips.order[s];
    run.status = worker.insertStrip(order.data(), static_cast<std::uint32_t>(order.size()), ids);
    run.used = worker.usedSlots();
    // A point right of the strip's box lies beyond one of its hull edges: a ghost triangle.
    const Bounds& box = strips.box[s];
    const double far = box.maxX + std::fabs(box.maxX) + 1;
    const Hit h = worker.locate(far, box.minY, false);
    if (h.kind == Hit::Kind::Outside) run.ghost = h.edge / 3;
    run.stats = worker.stats;
  });
}

// Each strip's share of the seam, found side by side, then the join.
Status joinAlongSeams(Delaunay& d, const Strips& strips, const std::vector<StripRun>& runs,
                      std::uint32_t count, Stats& stats) {
  const std::uint32_t k = strips.k;
  std::vector<std::uint8_t> state(static_cast<std::size_t>(strips.first[k]));
  std::vector<std::uint8_t> seen(count, 0);
  std::vector<StripSeam> seams(k);
  inParallel(k, [&](std::uint32_t s) {
    findSeam(d, runs[s].ghost, strips.first[s], runs[s].used, strips.first[s + 1],
             strips.slab(s).first, strips.slab(s).second, state, seen, seams[s]);
  });
  std::vector<std::uint8_t>().swap(seen);
  std::vector<std::uint8_t>().swap(state);
  const std::uint64_t vertices = stats.inserted;
  const auto slots = static_cast<std::int32_t>(2 * vertices - 2);
  return joinStrips(d, d.options(), seams, slots, stats);
}

}  // namespace

Status Delaunay::insertStrip(const std::uint32_t* order, std::uint32_t count, std::uint32_t* ids) {
  runSlots_ = firstSlot_;
  batch_ = {0, ids, nullptr};
  inBatch_ = true;
  const double* p = xy.data();
  std::size_t i1 = 0, i2 = 0;
  if (!findFirstTriangle(
          p, [order](std::size_t i) { return order[i]; }, count, i1, i2))
    return {StatusCode::InvalidArgument, "a strip of collinear points"};
  const std::uint32_t a = order[0], b = order[i1], c = order[i2];
  build(a, b, c);
  grid_.reset(p[2 * a], p[2 * a + 1], p[2 * a], p[2 * a + 1], 1);  // one cell: the run walks
  grid_.fill(last_);
  const Status s = insertRun(order, count, {a, b, c});
  inBatch_ = false;
  return s;
}

Status Delaunay::insertInStrips(std::uint32_t count, std::uint32_t* ids, bool& handled) {
  handled = false;
  Strips strips;
  strips.k = std::min(options_.threads, count / kMinStripPoints);
  strips.cuts = stripCuts(xy.data(), count, strips.k);
  if (strips.cuts.empty()) return Status::success();
  options_.progress(Phase::Sort, 0, count);
  const bool gathered = gatherStrips(xy.data(), count, options_.order, strips);
  options_.progress(Phase::Sort, count, count);
  if (!gathered) return Status::success();
  allocateStripSlots(topo, strips, ids, count);
  options_.progress(Phase::Points, 0, count);
  std::vector<StripRun> runs;
  const std::uint32_t running = triangulateStrips(*this, strips, ids, runs);
  for (const StripRun& run : runs) {
    if (run.status.ok()) continue;
    if (run.status.code == StatusCode::InternalError) return run.status;
    topo.clear();  // a strip of collinear points: one thread does it all
    return Status::success();
  }
  for (std::vector<std::uint32_t>& s : strips.order) std::vector<std::uint32_t>().swap(s);
  for (const StripRun& run : runs)
    if (run.ghost < 0) return broken("no ghost triangle found right of a strip");
  handled = true;
  for (const StripRun& run : runs) {
    stats.inserted += run.stats.inserted;
    stats.duplicates += run.stats.duplicates;
    stats.walkSteps += run.stats.walkSteps;
    stats.locates += run.stats.locates;
    stats.flips += run.stats.flips;
    stats.walkFallbacks += run.stats.walkFallbacks;
  }
  const Status joined = joinAlongSeams(*this, strips, runs, count, stats);
  if (!joined.ok()) return joined;
  built_ = true;
  stats.threads = running;

  // The batch's end, as insertStored's for a large batch.
  if (stats.duplicates != 0) {
    compactLargeBatch(0, count, ids, std::vector<std::uint32_t>(count));
  } else {
    for (std::uint32_t i = 0; i < count; ++i) ids[i] = i;
  }
  Bounds all = strips.box[0];
  for (const Bounds& b : strips.box) {
    all.minX = std::min(all.minX, b.minX);
    all.minY = std::min(all.minY, b.minY);
    all.maxX = std::max(all.maxX, b.maxX);
    all.maxY = std::max(all.maxY, b.maxY);
  }
  grid_.reset(all.minX, all.minY, all.maxX, all.maxY, options_.gridDensity);
  gridStale_ = true;
  options_.progress(Phase::Points, count, count);
  return Status::success();
}

#else

Status Delaunay::insertStrip(const std::uint32_t*, std::uint32_t, std::uint32_t*) {
  return {StatusCode::InternalError, "a build without threads has no strips"};
}

Status Delaunay::insertInStrips(std::uint32_t, std::uint32_t*, bool& handled) {
  handled = false;
  return Status::success();
}

#endif  // GEOCDT_THREADS

}  // namespace geocdt
