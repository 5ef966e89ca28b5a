#include "refine/refinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "exact/power_of_two.h"
#include "labels/slot_windings.h"
#include "refine/refiner.h"

namespace geocdt {

namespace refinement {

double projection(double ax, double ay, double bx, double by, double px, double py) {
  const double scale = powerOfTwo(-scaleExponent({bx - ax, by - ay, px - ax, py - ay}));
  const double ex = (bx - ax) * scale, ey = (by - ay) * scale;
  const double qx = (px - ax) * scale, qy = (py - ay) * scale;
  return std::clamp((qx * ex + qy * ey) / (ex * ex + ey * ey), 0.0, 1.0);
}

inline Shape Refiner::shape(std::int32_t t) const {
  const std::uint32_t* corner = &topo_.tri[3 * t];
  const double* xy = d_.xy.data();
  const double* a = xy + 2 * corner[0];
  const double* b = xy + 2 * corner[1];
  const double* c = xy + 2 * corner[2];
  double abx = b[0] - a[0], aby = b[1] - a[1], acx = c[0] - a[0], acy = c[1] - a[1];
  double cross = abx * acy - aby * acx;
  Shape s;
  // The area from the differences as they are: coordinates within 1e150 keep the products
  // finite, where the scaled frame below flushes the smaller side to zero when the sides'
  // sizes differ by hundreds of orders of magnitude (fuzz: a subnormal across from 1e58).
  s.area = 0.5 * std::fabs(cross);
  // The angle in a frame scaled by a power of two (exactly) to the triangle's size, so that
  // squares and their products neither overflow nor underflow at any coordinate magnitude;
  // sizes from 2^-200 to 2^200 need no scaling (products of squares stay finite).
  const double size =
      std::max(std::max(std::fabs(abx), std::fabs(aby)), std::max(std::fabs(acx), std::fabs(acy)));
  s.scale = 0;
  if (!(size >= 0x1p-200 && size <= 0x1p200)) {
    s.scale = scaleExponent({abx, aby, acx, acy});
    const double scale = powerOfTwo(-s.scale);
    abx *= scale, aby *= scale, acx *= scale, acy *= scale;
    cross = abx * acy - aby * acx;
  }
  const double bcx = acx - abx, bcy = acy - aby;
  const double lab = abx * abx + aby * aby, lac = acx * acx + acy * acy;
  const double lbc = bcx * bcx + bcy * bcy;
  // The smallest angle faces the shortest edge; its sin is twice the area over the product of
  // the two longer edges, whose squares' product is the largest of the three pairs'.
  s.cross2 = cross * cross;
  s.product = std::max(std::max(lab * lac, lab * lbc), lac * lbc);
  s.shortest2 = std::min(std::min(lab, lac), lbc);
  return s;
}

void Refiner::checkTriangle(std::int32_t t) {
  // Every slot an insertion or a flip rewrites is checked: the place to list them.
  if (trackChanges_) changed_.push_back(t);
  if (!inRegion(t)) return;
  const Shape s = shape(t);
  const bool skinny = s.skinny(sin2_);
  if (!skinny && !(s.area > maxArea_)) return;
  const std::uint32_t a = topo_.tri[3 * t], b = topo_.tri[3 * t + 1], c = topo_.tri[3 * t + 2];
  const bool boundary = onSubsegment(a) || onSubsegment(b) || onSubsegment(c);
  bad_.push(BadQueue::bucket(boundary, skinny, skinny ? s.sin2() : 0, s.lengthExponent()),
            {t, a, b, c, skinny});
}

std::int32_t Refiner::findEdge(std::uint32_t u, std::uint32_t v) const {
  return topo_.edgeAround(vertexEdge_[u], v);
}

void Refiner::rebuild() {
  // Without rings every slot winds 0 (open polylines wind nothing): no flood needed.
  const std::vector<std::uint8_t>& ring = d_.constraints.ring;
  if (std::find(ring.begin(), ring.end(), std::uint8_t{1}) == ring.end()) {
    winding_.assign(static_cast<std::size_t>(topo_.slotCount()), 0);
  } else {
    winding_ = slotWindings(d_);
  }
  vertexEdge_.assign(d_.vertexCount(), -1);
  onSubsegment_.assign(d_.vertexCount(), 0);
  // A byte per slot for whether it is a ghost: the twins' slots are read in no order, and
  // their corners are three times the memory (bench/EXPERIMENTS.md, TN31).
  const std::uint32_t* tri = topo_.tri.data();
  const auto slots = static_cast<std::size_t>(topo_.slotCount());
  ghostSlot_.resize(slots);
  for (std::size_t t = 0; t < slots; ++t)
    ghostSlot_[t] =
        (tri[3 * t] == kGhost) | (tri[3 * t + 1] == kGhost) | (tri[3 * t + 2] == kGhost);
  // One pass: a half-edge out of each vertex (the last one), and the ends of subsegments
  // (the flag first, the corners of the triangle only for the few that have it).
  forChunks(0, topo_.tri.size(), [&](std::size_t begin, std::size_t end) {
    for (auto e = static_cast<std::int32_t>(begin); e < static_cast<std::int32_t>(end); ++e) {
      const std::uint32_t v = tri[e];
      if (v == kGhost) continue;  // (then a ghost triangle's edge, on no subsegment)
      vertexEdge_[v] = e;
      if (!ghostSlot_[e / 3] && startSubsegment(e)) onSubsegment_[v] = 1;
    }
  });
}

// After a vertex was inserted: the triangles around it take their windings from the caller,
// or else from the unchanged triangles beyond them (every triangle the insertion changed has
// it as a corner), tell their corners where they are, and are checked. `from` is a half-edge
// out of it.
void Refiner::afterInsert(std::int32_t from, std::int32_t winding) {
  // Grown by half again when short, not by each insertion's two slots and one vertex: in
  // wasm every resize is a call. Entries past the slots and vertices are not read; run()
  // trims the windings to the slots at its end.
  const auto slots = static_cast<std::size_t>(topo_.slotCount());
  const std::size_t vertices = d_.vertexCount();
  if (winding_.size() < slots) winding_.resize(slots + slots / 2);
  if (vertexEdge_.size() < vertices) vertexEdge_.resize(vertices + vertices / 2, -1);
  if (winding != kUnknownWinding) {
    // Joined to a cavity's border: every triangle takes the cavity's winding; the spokes are
    // new and unconstrained, none on the hull (no ghost was in the cavity), so only the
    // border edges can be subsegments. Nothing here changes the topology: one turn round the
    // vertex does it all, each triangle checked once its winding and corners are set.
    const std::uint32_t* tri = topo_.tri.data();
    const std::int32_t* adj = topo_.adj.data();
    std::int32_t* vertexEdge = vertexEdge_.data();
    vertexEdge[tri[from]] = from;
    std::int32_t h = from;
    do {
      const auto t = static_cast<std::int32_t>(static_cast<std::uint32_t>(h) / 3);
      const std::int32_t k = h - 3 * t, outer = k == 2 ? h - 2 : h + 1;
      winding_[t] = winding;
      if (tri[outer] != kGhost) vertexEdge[tri[outer]] = outer;
      checkTriangle(t);
      if (isSubsegment(outer)) queueIfEncroached(outer);
      h = adj[k == 0 ? h + 2 : h - 1];
    } while (h != from);
    return;
  }
  around_.clear();
  std::int32_t e = from;
  do {
    around_.push_back(e);
    e = topo_.adj[prevEdge(e)];
  } while (e != from);
  // The triangles take their windings from the unchanged triangles beyond them.
  for (const std::int32_t h : around_) {
    const std::int32_t t = h / 3, outer = nextEdge(h);
    if (topo_.isGhost(t)) {
      winding_[t] = 0;
    } else {
      const std::int32_t g = topo_.adj[outer];
      winding_[t] = winding_[g / 3];
      if (topo_.fixed[outer])
        winding_[t] += d_.constraints.windingAcross(topo_.tri[g], topo_.tri[nextEdge(g)]);
    }
    // Every slot the insertion rewrote is one of these, and every vertex that pointed into
    // one is a corner of them: v, or the start of an outer edge.
    if (topo_.tri[outer] != kGhost) vertexEdge_[topo_.tri[outer]] = outer;
  }
  vertexEdge_[topo_.tri[from]] = from;
  for (const std::int32_t h : around_) checkAround(h / 3);
}

void Refiner::noteCorners(std::int32_t t) {
  for (std::int32_t k = 3 * t; k < 3 * t + 3; ++k)
    if (topo_.tri[k] != kGhost) vertexEdge_[topo_.tri[k]] = k;
}

void Refiner::checkAround(std::int32_t t) {
  checkTriangle(t);
  if (topo_.isGhost(t)) return;
  for (std::int32_t k = 3 * t; k < 3 * t + 3; ++k)
    if (isSubsegment(k)) queueIfEncroached(k);
}

// Flips the edges on the stack until each is locally Delaunay, as Delaunay::restoreDelaunay
// does, keeping windings (a flipped edge is unconstrained: both its triangles wind alike),
// corners and checks up to date.
void Refiner::restoreDelaunay(std::vector<std::int32_t>& stack) {
  while (!stack.empty()) {
    const std::int32_t e = stack.back();
    stack.pop_back();
    if (topo_.fixed[e] || d_.isLocallyDelaunay(e)) continue;
    const std::int32_t f = topo_.adj[e];
    topo_.flip(e);
    ++d_.stats.flips;
    winding_[f / 3] = winding_[e / 3];
    for (const std::int32_t t : {e / 3, f / 3}) {
      noteCorners(t);
      checkAround(t);
    }
    stack.push_back(e);
    stack.push_back(nextEdge(e));
    stack.push_back(f);
    stack.push_back(nextEdge(f));
  }
}

Refiner::Step Refiner::refineStep(std::vector<BadTriangle>& retry,
                                  std::vector<BadTriangle>& unresolved) {
  if (capped_) return Step::Stop;
  if (!subsegments_.empty()) {
    const Subsegment s = subsegments_.back();
    subsegments_.pop_back();
    const std::int32_t e = findEdge(s.u, s.v);
    if (e < 0) return Step::Go;
    return splitSubsegment(e, s.forced) == Outcome::Failed ? Step::Stop : Step::Go;
  }
  for (const BadTriangle& b : retry) checkTriangle(b.slot);
  retry.clear();
  if (bad_.empty()) return Step::Stop;
  const BadTriangle b = bad_.pop();
  if (!holds(b)) return Step::Go;
  const Outcome o = splitTriangle(b);
  if (o == Outcome::Failed) return Step::Failed;
  if (o == Outcome::Retry) {
    retry.push_back(b);
  } else if (holds(b)) {
    unresolved.push_back(b);  // skipped, or the cap stopped it
  }
  return Step::Go;
}

Refiner::Step Refiner::refineSteps(std::vector<BadTriangle>& retry,
                                   std::vector<BadTriangle>& unresolved) {
  for (std::size_t i = 0; i < kChunk; ++i) {
    const Step step = refineStep(retry, unresolved);
    if (step != Step::Go) return step;
  }
  return Step::Go;
}

Status Refiner::run() {
  if (!d_.built()) return Status::success();
  start();
  return resume();
}

void Refiner::start() {
  // Steiner vertices take ids past the constraint store's id-ordered slots (EdgeSlot).
  d_.constraints.scatter();
  rebuild();
  steinerFlag_.assign(d_.vertexCount(), 0);
  for (const SteinerVertex& s : d_.steiner) steinerFlag_[s.vertex] = 1;
  // The default cap holds at every angle: below kProvenAngle refinement ends in theory, but a
  // terrain mesh with breaklines ending on the raster's border once refined for ever at 17
  // degrees (tests/cpp/terrain_test.cpp, seed 48633), and a cap beats a hang.
  if (cap_ == 0) {
    double domainArea = 0;
    for (std::int32_t t = 0; std::isfinite(maxArea_) && t < topo_.slotCount(); ++t) {
      if (!inRegion(t)) continue;
      domainArea += shape(t).area;
    }
    const double byArea = std::isfinite(maxArea_) ? 4 * domainArea / maxArea_ : 0;
    cap_ = 64 * static_cast<std::uint64_t>(d_.vertexCount()) + 1024 +
           static_cast<std::uint64_t>(std::min(byArea, 1e18));
  }
  for (std::int32_t e = 0; keepAll_ && e < static_cast<std::int32_t>(topo_.tri.size()); ++e) {
    if (ghostSlot_[e / 3] || !ghostSlot_[topo_.adj[e] / 3] || topo_.fixed[e]) continue;
    const std::uint32_t a = topo_.tri[e], b = topo_.tri[nextEdge(e)];
    hullOf_[ConstraintStore::key(a, b)] = static_cast<std::uint32_t>(hull_.size());
    hull_.push_back({x(a), y(a), x(b), y(b)});
  }
  // The scan and the loop's steps in chunks (chunks.h): run() is called once, and with both
  // inlined it was 18 KB of wasm that a first call ran in its baseline code throughout
  // (bench/EXPERIMENTS.md, first call 21).
  forChunks(
      0, static_cast<std::size_t>(topo_.slotCount()), [&](std::size_t begin, std::size_t end) {
        for (auto t = static_cast<std::int32_t>(begin); t < static_cast<std::int32_t>(end); ++t) {
          if (ghostSlot_[t]) continue;
          checkTriangle(t);
          for (int k = 0; k < 3; ++k) {
            const std::int32_t e = 3 * t + k, twin = topo_.adj[e];
            if (startSubsegment(e) && (ghostSlot_[twin / 3] || e < twin)) queueIfEncroached(e);
          }
        }
      });
  ghostSlot_ = {};
}

Status Refiner::resume() {
  changed_.clear();
  std::vector<BadTriangle> retry;
  Step step = Step::Go;
  while (step == Step::Go) step = refineSteps(retry, unresolved_);
  if (step == Step::Failed) return d_.lastError();
  unresolved_.insert(unresolved_.end(), retry.begin(), retry.end());
  countLeft();
  return Status::success();
}

std::uint64_t Refiner::countLeft() {
  // What is left bad: every triangle was checked when it was made, and a bad one queued; a
  // queued one was split (then it is gone, or it is among these), skipped, or is still
  // waiting. A pass over all the slots instead missed the cache for every one of them.
  // (Those left by an earlier resume() that still hold are among them too.)
  bad_.drainInto(unresolved_);
  std::uint64_t left = 0;
  ++epoch_;
  stamp_.resize(topo_.slotCount(), 0);
  std::size_t kept = 0;
  forChunks(0, unresolved_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const BadTriangle& b = unresolved_[i];
      if (stamp_[b.slot] == epoch_ || !holds(b) || !inRegion(b.slot)) continue;
      stamp_[b.slot] = epoch_;
      const Shape s = shape(b.slot);
      const bool bad = s.skinny(sin2_) || s.area > maxArea_;
      left += bad;
      if (bad) unresolved_[kept++] = b;
    }
  });
  unresolved_.resize(kept);
  winding_.resize(topo_.slotCount());
  d_.stats.steinerPoints += added_ - reported_;
  reported_ = added_;
  d_.stats.refineSkipped = left;
  d_.stats.refineCapped = capped_;
  return left;
}

void Refiner::noteInsertion(std::int32_t from, std::uint32_t a, std::uint32_t b,
                            bool onSubsegment) {
  const std::uint32_t v = topo_.tri[from];
  if (onSubsegment) {
    markOnSubsegment(v);
    if (const EdgeSource* src = d_.constraints.find(a, v))
      noteSegment(v, src->segment);  // the segment the split edge stood for
    const auto hull = hullOf_.find(ConstraintStore::key(a, b));
    if (hull != hullOf_.end()) {
      const std::uint32_t original = hull->second;
      hullOf_.erase(hull);
      hullOf_[ConstraintStore::key(a, v)] = original;
      hullOf_[ConstraintStore::key(v, b)] = original;
    }
  }
  afterInsert(from);
}

}  // namespace refinement

std::string refineOptionsError(const RefineOptions& o) {
  if (!(o.minAngle >= 0 && o.minAngle < 60))
    return "refine: minAngle must be a number of degrees from 0 to less than 60";
  if (!(o.maxArea >= 0)) return "refine: maxArea must be a positive number of squared units";
  return "";
}

Status refineTriangulation(Delaunay& d, const RefineOptions& options,
                           std::vector<std::int32_t>* windings) {
  refinement::Refiner refiner(d, options);
  const Status s = refiner.run();
  if (s.ok() && windings) refiner.takeWindings(*windings);
  return s;
}

}  // namespace geocdt
