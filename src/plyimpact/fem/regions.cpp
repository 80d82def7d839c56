#include "plyimpact/fem/regions.hpp"

namespace plyimpact {

std::vector<int> element_laminates(const Mesh& mesh, const std::vector<Region>& regions) {
  if (regions.empty()) return {};
  const double tol = 1e-9 * mesh.bounds().size();
  std::vector<int> of_element(static_cast<std::size_t>(mesh.element_count()), 0);
  for (int e = 0; e < mesh.element_count(); ++e) {
    const Eigen::Vector2d c = mesh.map(e, 0.0, 0.0);
    for (const Region& r : regions)
      if (r.contains(c.x(), c.y(), tol)) of_element[static_cast<std::size_t>(e)] = r.laminate;
  }
  return of_element;
}

} // namespace plyimpact
