#include "geocdt/triangulation.h"
#include "triangulation_state.h"

namespace geocdt {

Status Triangulation::insertPolyline(const double* xy, std::size_t count, std::uint32_t* vertexIds) {
  (void)xy;
  (void)count;
  (void)vertexIds;
  return {StatusCode::InternalError, "constraints are not implemented yet"};
}

}  // namespace geocdt
