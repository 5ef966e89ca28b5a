#pragma once
// A model of what an edited triangulation should hold: the points and polylines inserted
// and not removed, with their places as moved. compare() triangulates the model afresh and
// checks that the edited mesh is the same triangulation (by coordinates: the numbering
// differs), with the same constrained edges, provenance and inside flags; check() runs the
// invariant checker on the edited mesh itself.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "geocdt/triangulation.h"

namespace geocdt::testing {

class EditModel {
 public:
  // Inserts into t and records: the ids t returned.
  Status insertPoints(Triangulation& t, const std::vector<double>& xy);
  Status insertPolyline(Triangulation& t, const std::vector<double>& xy);
  // Edits t and the model alike.
  Status removePoint(Triangulation& t, std::uint32_t id, bool* removed = nullptr);
  Status removePoints(Triangulation& t, const std::vector<std::uint32_t>& ids,
                      std::size_t* removed = nullptr);
  Status removePolyline(Triangulation& t, std::size_t polyline);
  Status movePoint(Triangulation& t, std::uint32_t id, double x, double y);

  // Ids of live points (inserted with insertPoints, not removed).
  std::vector<std::uint32_t> pointIds() const;
  // Live polylines (their numbers) and the ids of their vertices.
  std::vector<std::size_t> polylineNumbers() const;
  std::vector<std::uint32_t> polylineVertexIds(std::size_t polyline) const;

  // The checker on t's mesh (exact invariants, chains), with the model's input.
  std::string check(const Triangulation& t) const;
  // Whether t's mesh is the one triangulate() gives for the model's input (where no four
  // points are cocircular): triangles, constrained edges with their polylines, inside flags.
  // Without triangles: the vertices only (in ulp tangles, where cocircular points abound and
  // the routes of chains can depend on the triangles).
  std::string compare(const Triangulation& t, bool triangles = true) const;
  // Where vertex id is now: {x, y}.
  std::vector<double> place(std::uint32_t id) const;

 private:
  struct Line {
    std::vector<std::uint32_t> ids;
    bool live = true;
  };
  std::map<std::uint32_t, std::pair<double, double>> places_;  // every id seen, as moved
  std::map<std::uint32_t, int> pointUses_;                     // insertPoints references
  std::vector<Line> lines_;
};

}  // namespace geocdt::testing
