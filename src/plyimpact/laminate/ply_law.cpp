#include "plyimpact/laminate/ply_law.hpp"

#include "plyimpact/laminate/ply_damage.hpp"

namespace plyimpact {

std::unique_ptr<PlyLaw> make_ply_law(const Material& material, const PlyDamageOptions& options) {
  return std::make_unique<PlyDamageLaw>(material, options);
}

} // namespace plyimpact
