#include "edit_refusals.h"

namespace geocdt {

Status invalidEdit(const std::string& message, std::size_t index) {
  return {StatusCode::InvalidArgument, message, index};
}

std::string describeVertex(const EditState& edit, std::uint32_t v) {
  const std::uint8_t kind = edit.kind(v);
  if (kind & kPointVertex) return "a point";
  if (kind & kPolylineVertex) return "a polyline's vertex";
  if (kind & kSteinerVertex) return "a Steiner point of refinement";
  return "a crossing of polylines";
}

Status checkId(const Delaunay& d, std::uint32_t id, const char* call) {
  if (id >= d.vertexCount())
    return invalidEdit(std::string(call) + ": no vertex has id " + std::to_string(id) +
                           " (ids given so far run below " + std::to_string(d.vertexCount()) + ")",
                       id);
  if (d.isRemoved(id))
    return invalidEdit(std::string(call) + ": vertex " + std::to_string(id) + " was removed", id);
  return Status::success();
}

}  // namespace geocdt
