#include "edit_model.h"

#include <algorithm>
#include <array>
#include <set>
#include <sstream>
#include <tuple>

#include "constraint_invariants.h"
#include "invariants.h"

namespace geocdt::testing {

namespace {

using Point = std::pair<double, double>;
using CoordinateTriangle = std::array<Point, 3>;

Point at(const Mesh& m, std::uint32_t v) { return {m.points[2 * v], m.points[2 * v + 1]}; }

// Each triangle by its corners' coordinates, turned to start at the least.
std::vector<CoordinateTriangle> coordinateTriangles(const Mesh& m) {
  std::vector<CoordinateTriangle> out;
  for (std::size_t t = 0; t < m.triangles.size() / 3; ++t) {
    CoordinateTriangle c{at(m, m.triangles[3 * t]), at(m, m.triangles[3 * t + 1]),
                         at(m, m.triangles[3 * t + 2])};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Each constrained edge by its ends' coordinates (the lesser first), with the polylines it
// names (mapped by `number`), and each triangle's inside flag.
std::map<std::pair<Point, Point>, std::vector<std::size_t>> constrainedEdges(
    const Mesh& m, const std::vector<std::size_t>& number) {
  std::map<std::pair<Point, Point>, std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < m.constraintEdges.size(); ++i) {
    const std::uint32_t e = m.constraintEdges[i];
    Point a = at(m, m.triangles[e]), b = at(m, m.triangles[e % 3 == 2 ? e - 2 : e + 1]);
    if (b < a) std::swap(a, b);
    std::vector<std::size_t> names;
    for (std::uint32_t k = m.sourceOffsets[i]; k < m.sourceOffsets[i + 1]; ++k)
      names.push_back(number.empty() ? m.sources[k] : number[m.sources[k]]);
    std::sort(names.begin(), names.end());
    out[{a, b}] = names;
  }
  return out;
}

std::map<CoordinateTriangle, int> insideFlags(const Mesh& m) {
  std::map<CoordinateTriangle, int> out;
  for (std::size_t t = 0; t < m.inside.size(); ++t) {
    CoordinateTriangle c{at(m, m.triangles[3 * t]), at(m, m.triangles[3 * t + 1]),
                         at(m, m.triangles[3 * t + 2])};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out[c] = m.inside[t];
  }
  return out;
}

std::string describe(const Point& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.first << ", " << p.second << ")";
  return s.str();
}

}  // namespace

Status EditModel::insertPoints(Triangulation& t, const std::vector<double>& xy) {
  std::vector<std::uint32_t> ids(xy.size() / 2);
  const Status s = t.insertPoints(xy.data(), ids.size(), ids.data());
  if (!s.ok()) return s;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    places_[ids[i]] = {xy[2 * i], xy[2 * i + 1]};
    ++pointUses_[ids[i]];
  }
  return s;
}

Status EditModel::insertPolyline(Triangulation& t, const std::vector<double>& xy) {
  Line line;
  line.ids.resize(xy.size() / 2);
  const Status s = t.insertPolyline(xy.data(), line.ids.size(), line.ids.data());
  if (!s.ok()) return s;
  for (std::size_t i = 0; i < line.ids.size(); ++i)
    places_[line.ids[i]] = {xy[2 * i], xy[2 * i + 1]};
  lines_.push_back(line);
  return s;
}

Status EditModel::removePoint(Triangulation& t, std::uint32_t id, bool* removed) {
  const Status s = t.removePoint(id, removed);
  if (s.ok()) pointUses_.erase(id);
  return s;
}

Status EditModel::removePoints(Triangulation& t, const std::vector<std::uint32_t>& ids,
                               std::size_t* removed) {
  const Status s = t.removePoints(ids.data(), ids.size(), removed);
  if (s.ok())
    for (const std::uint32_t id : ids) pointUses_.erase(id);
  return s;
}

Status EditModel::removePolyline(Triangulation& t, std::size_t polyline) {
  const Status s = t.removePolyline(polyline);
  if (s.ok()) lines_[polyline].live = false;
  return s;
}

Status EditModel::movePoint(Triangulation& t, std::uint32_t id, double x, double y) {
  const Status s = t.movePoint(id, x, y);
  if (s.ok()) places_[id] = {x, y};
  return s;
}

std::vector<std::uint32_t> EditModel::pointIds() const {
  std::vector<std::uint32_t> ids;
  for (const auto& [id, uses] : pointUses_) ids.push_back(id);
  return ids;
}

std::vector<std::size_t> EditModel::polylineNumbers() const {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < lines_.size(); ++k)
    if (lines_[k].live) out.push_back(k);
  return out;
}

std::vector<std::uint32_t> EditModel::polylineVertexIds(std::size_t polyline) const {
  return lines_[polyline].ids;
}

std::vector<double> EditModel::place(std::uint32_t id) const {
  const auto& p = places_.at(id);
  return {p.first, p.second};
}

std::string EditModel::check(const Triangulation& t) const {
  MeshOptions options;
  options.insideFlags = true;
  const Mesh m = t.mesh(options);
  std::map<std::uint32_t, std::uint32_t> index;  // id -> output vertex
  for (std::uint32_t i = 0; i < m.points.size() / 2; ++i)
    index[m.vertexIds.empty() ? i : m.vertexIds[i]] = i;
  std::vector<double> inputXY;
  std::vector<std::uint32_t> inputToVertex;
  Polylines polylines(lines_.size());
  std::vector<std::uint32_t> lineVertices;
  const auto add = [&](std::uint32_t id) {
    const std::vector<double> p = place(id);
    inputXY.insert(inputXY.end(), p.begin(), p.end());
    const auto found = index.find(id);
    inputToVertex.push_back(found == index.end() ? 0xFFFFFFFFu : found->second);
    return found == index.end();
  };
  for (const auto& [id, uses] : pointUses_)
    if (add(id)) return "point " + std::to_string(id) + " is not a vertex of the mesh";
  for (std::size_t k = 0; k < lines_.size(); ++k) {
    if (!lines_[k].live) continue;
    for (const std::uint32_t id : lines_[k].ids) {
      if (add(id)) return "a vertex of polyline " + std::to_string(k) + " is missing";
      const std::vector<double> p = place(id);
      polylines[k].insert(polylines[k].end(), p.begin(), p.end());
      lineVertices.push_back(inputToVertex.back());
    }
  }
  CheckOptions c;
  c.inputXY = &inputXY;
  c.inputToVertex = &inputToVertex;
  std::string s = checkTriangulation(m, c);
  if (!s.empty()) return s;
  // All collinear: no triangles, and the constraints wait for some (README).
  if (m.triangles.empty()) return "";
  return checkConstraints(m, polylines, lineVertices);
}

std::string EditModel::compare(const Triangulation& t, bool triangles) const {
  std::vector<double> points;
  for (const auto& [id, uses] : pointUses_) {
    const std::vector<double> p = place(id);
    points.insert(points.end(), p.begin(), p.end());
  }
  Polylines polylines;
  std::vector<std::size_t> number;  // fresh polyline -> the edited triangulation's number
  for (std::size_t k = 0; k < lines_.size(); ++k) {
    if (!lines_[k].live) continue;
    std::vector<double> line;
    for (const std::uint32_t id : lines_[k].ids) {
      const std::vector<double> p = place(id);
      line.insert(line.end(), p.begin(), p.end());
    }
    polylines.push_back(line);
    number.push_back(k);
  }
  std::vector<PolylineView> views;
  for (const auto& l : polylines) views.push_back({l.data(), l.size() / 2});
  MeshOptions options;
  options.insideFlags = true;
  Mesh fresh;
  const Status s =
      triangulate(points.data(), points.size() / 2, views.data(), views.size(), {}, options, fresh);
  if (!s.ok()) return "triangulate: " + s.message;
  const Mesh edited = t.mesh(options);
  if (!triangles) {
    std::set<Point> va, vb;
    for (std::uint32_t v = 0; v < edited.points.size() / 2; ++v) va.insert(at(edited, v));
    for (std::uint32_t v = 0; v < fresh.points.size() / 2; ++v) vb.insert(at(fresh, v));
    return va == vb ? "" : "vertices differ";
  }
  const auto a = coordinateTriangles(edited), b = coordinateTriangles(fresh);
  if (a != b) {
    std::vector<CoordinateTriangle> onlyA, onlyB;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(onlyA));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(onlyB));
    std::ostringstream out;
    out << "triangles differ: " << a.size() << " edited, " << b.size() << " fresh";
    if (!onlyA.empty())
      out << "; edited only: " << describe(onlyA[0][0]) << describe(onlyA[0][1])
          << describe(onlyA[0][2]);
    if (!onlyB.empty())
      out << "; fresh only: " << describe(onlyB[0][0]) << describe(onlyB[0][1])
          << describe(onlyB[0][2]);
    return out.str();
  }
  if (constrainedEdges(edited, {}) != constrainedEdges(fresh, number))
    return "constrained edges or their polylines differ";
  if (insideFlags(edited) != insideFlags(fresh)) return "inside flags differ";
  return "";
}

}  // namespace geocdt::testing
