#include "plyimpact/laminate/ply_law.hpp"

#include "plyimpact/laminate/fracture_plane_law.hpp"
#include "plyimpact/laminate/ply_damage.hpp"

namespace plyimpact {

std::unique_ptr<PlyLaw> make_ply_law(const Material& material, const PlyDamageOptions& options) {
  switch (options.law) {
  case PlyLawKind::hashin:
    return std::make_unique<PlyDamageLaw>(material, options);
  case PlyLawKind::fracture_plane:
    return std::make_unique<FracturePlaneLaw>(material, options);
  }
  return nullptr;
}

} // namespace plyimpact
