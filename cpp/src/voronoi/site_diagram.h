#pragma once
// The Delaunay triangulation of the sites, whose dual is their Voronoi diagram: the cell of a
// site is bounded by the bisectors with its neighbours, its corners are the circumcentres of
// the triangles around it. Three guard sites far outside the region of interest (the sites and
// the domain) close it: every real site then has a bounded cell with triangles around it, also
// when the sites are collinear or alone, and no guard's cell reaches the region.
#include <cstdint>
#include <memory>
#include <vector>

#include "delaunay/delaunay.h"
#include "exact/bisector_predicates.h"
#include "geocdt/status.h"

namespace geocdt {

class SiteDiagram {
 public:
  // sites: 2 * count doubles, already checked. Region: bounds that hold the sites and the
  // domain. threads: Options::threads for the sites' triangulation.
  Status build(const double* sites, std::uint32_t count, double minX, double minY, double maxX,
               double maxY, std::uint32_t threads);

  // The real sites' convex hull counter-clockwise, before the guards came (empty when the sites
  // are collinear); filled by build().
  const std::vector<XY>& hull() const { return hull_; }

  // The vertex each input site became (equal sites share one).
  const std::vector<std::uint32_t>& siteVertices() const { return siteVertex_; }
  std::uint32_t vertexCount() const { return realVertices_; }  // real sites only
  std::uint32_t threads() const { return static_cast<std::uint32_t>(threads_); }
  bool isGuard(std::uint32_t v) const { return v >= realVertices_ && v != kGhost; }

  XY point(std::uint32_t v) const { return {delaunay_->xy[2 * v], delaunay_->xy[2 * v + 1]}; }
  const Topology& topo() const { return delaunay_->topo; }
  std::uint32_t origin(std::int32_t e) const { return delaunay_->topo.tri[e]; }
  std::uint32_t target(std::int32_t e) const { return delaunay_->topo.tri[nextEdge(e)]; }
  std::int32_t twin(std::int32_t e) const { return delaunay_->topo.adj[e]; }
  // The half-edge after e counter-clockwise around its origin.
  std::int32_t turn(std::int32_t e) const { return delaunay_->topo.adj[prevEdge(e)]; }
  // A half-edge out of real site v: the one whose triangle has the least centre (by x, then y),
  // where its cell's ring starts.
  std::int32_t outEdge(std::uint32_t v) const { return outEdge_[v]; }
  // The edges out of real site v whose two triangles' centres differ: the distinct corners of
  // its cell's ring (cocircular sites make runs of equal centres).
  std::uint32_t cornerCount(std::uint32_t v) const { return corners_[v]; }
  // The circumcentre of slot t (a real triangle): a vertex of the Voronoi diagram.
  XY center(std::int32_t t) const { return centers_[t]; }

  // A half-edge out of the site nearest p, ties broken as nearerTo() breaks them.
  std::int32_t nearest(XY p);

 private:
  void recordHull();
  Status addGuards(double minX, double minY, double maxX, double maxY);
  void computeCenters();

  std::unique_ptr<Delaunay> delaunay_;
  std::vector<std::uint32_t> siteVertex_;
  std::uint32_t realVertices_ = 0;
  std::uint64_t threads_ = 1;  // that triangulated the sites
  std::vector<XY> hull_;
  std::vector<std::int32_t> outEdge_;
  std::vector<std::uint32_t> corners_;
  std::vector<XY> centers_;
};

}  // namespace geocdt
