#include "plyimpact/fem/layered_section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace plyimpact {

namespace {

/// Engineering strain (x, y, xy) in plate axes → (11, 22, 12) in material axes.
Eigen::Matrix3d strain_to_material(double angle_deg) {
  const auto [c, s] = cos_sin_degrees(angle_deg);
  Eigen::Matrix3d T;
  T << c * c, s * s, c * s, s * s, c * c, -c * s, -2.0 * c * s, 2.0 * c * s, c * c - s * s;
  return T;
}

/// Transverse shear strain (yz, xz) in plate axes → (23, 13) in material axes.
Eigen::Matrix2d shear_to_material(double angle_deg) {
  const auto [c, s] = cos_sin_degrees(angle_deg);
  Eigen::Matrix2d T;
  T << c, -s, s, c;
  return T;
}

} // namespace

/// One ply's data at the points through its thickness.
struct LayeredSection::PlyPoints {
  std::size_t material = 0;
  Eigen::Matrix3d T_strain;
  Eigen::Matrix2d T_shear;
  std::array<double, 2> z{};
  double weight = 0.0;   ///< t/2
  std::size_t group = 0; ///< its Group in the section's groups (the same in every length class)

  /// The ply strain in material axes at height z from the generalized strains (ε0, κ, γ) of a point;
  /// root_k = √K puts the plate's transverse shear energy into the ply.
  [[nodiscard]] PlyStrain strain_at(double z_point, const Eigen::Matrix<double, 8, 1>& s,
                                    double root_k) const {
    PlyStrain ps;
    ps.in_plane = T_strain * (s.head<3>() + z_point * s.segment<3>(3));
    ps.transverse_shear = root_k * (T_shear * s.tail<2>());
    return ps;
  }

  /// The undamaged ply's terms of add_to(), T_εᵀ Q T_ε and k t/2 T_γᵀ G T_γ: every undamaged point of the ply
  /// adds these, computed once by the same expressions (so the sections are the same bit for bit).
  Eigen::Matrix3d undamaged_in_plane = Eigen::Matrix3d::Zero();
  Eigen::Matrix2d undamaged_shear_term = Eigen::Matrix2d::Zero();

  /// Adds this ply's point at height z, with secant stiffnesses C (in-plane) and G (transverse shear) in
  /// material axes, to the section (DP1); k is the shear correction. Only the upper triangle of the
  /// membrane–bending block: symmetric_section() completes it.
  void add_to(SectionStiffness& sec, double z_point, double k, const Eigen::Matrix3d& C,
              const Eigen::Matrix2d& G) const {
    add_in_plane(sec, z_point, T_strain.transpose() * C * T_strain);
    sec.F += (weight * k) * (T_shear.transpose() * G * T_shear);
  }
  /// add_to() with the undamaged stiffnesses.
  void add_undamaged_to(SectionStiffness& sec, double z_point) const {
    add_in_plane(sec, z_point, undamaged_in_plane);
    sec.F += undamaged_shear_term;
  }
  /// Caches the undamaged terms from the ply law's undamaged stiffnesses; k is the shear correction.
  void cache_undamaged(const PlyLaw& law, double k) {
    undamaged_in_plane = T_strain.transpose() * law.undamaged_stiffness() * T_strain;
    undamaged_shear_term = (weight * k) * (T_shear.transpose() * law.undamaged_transverse_shear() * T_shear);
  }

private:
  void add_in_plane(SectionStiffness& sec, double z_point, const Eigen::Matrix3d& Cbar) const {
    sec.C_mb.topLeftCorner<3, 3>() += weight * Cbar;
    sec.C_mb.topRightCorner<3, 3>() += (weight * z_point) * Cbar;
    sec.C_mb.bottomRightCorner<3, 3>() += (weight * z_point * z_point) * Cbar;
  }
};

namespace {

SectionStiffness empty_section() {
  SectionStiffness sec;
  sec.C_mb.setZero();
  sec.F.setZero();
  return sec;
}

/// Completes the B block below the diagonal of a section built with PlyPoints::add_to.
void symmetric_section(SectionStiffness& sec) {
  sec.C_mb.bottomLeftCorner<3, 3>() = sec.C_mb.topRightCorner<3, 3>().transpose();
}

} // namespace

/// Plies of one section with the same material and angle, and the z range they span: the undamaged ply's
/// stress is affine in z, so the law bounds its onset index over the range from the stresses at its ends
/// (PlyLaw::onset_bound): the screen.
struct LayeredSection::Group {
  std::size_t material = 0;
  Eigen::Matrix3d T_strain;
  Eigen::Matrix3d Q; ///< undamaged reduced stiffness, material axes
  double z_min = 0.0, z_max = 0.0;
  /// Material-axes stress of the undamaged ply at z_min and z_max from (ε0, κ): Q T_ε [I, z I].
  Eigen::Matrix<double, 3, 6> at_min = Eigen::Matrix<double, 3, 6>::Zero();
  Eigen::Matrix<double, 3, 6> at_max = Eigen::Matrix<double, 3, 6>::Zero();
  const PlyLaw* law = nullptr;

  void finish(const PlyLaw& ply_law) {
    for (auto [M, z] : {std::pair{&at_min, z_min}, std::pair{&at_max, z_max}}) {
      M->leftCols<3>() = Q * T_strain;
      M->rightCols<3>() = z * (Q * T_strain);
    }
    law = &ply_law;
  }
  /// An upper bound of the undamaged plies' onset index over the group's z range at a point with
  /// membrane strain and curvature `strain`.
  [[nodiscard]] double bound(const Eigen::Matrix<double, 6, 1>& strain) const {
    return law->onset_bound(at_min * strain, at_max * strain);
  }
};

namespace {

std::vector<LayeredSection::PlyPoints> ply_points(const Laminate& lam) {
  std::vector<LayeredSection::PlyPoints> plies;
  const double offset = 0.5 / std::sqrt(3.0);
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    const Ply& ply = lam.plies()[k];
    const double mid = 0.5 * (lam.z_top(k) + lam.z_bottom(k));
    const double t = lam.z_bottom(k) - lam.z_top(k);
    plies.push_back({ply.material,
                     strain_to_material(ply.angle_deg),
                     shear_to_material(ply.angle_deg),
                     {mid - offset * t, mid + offset * t},
                     0.5 * t});
  }
  return plies;
}

/// One damage law per material the laminate's plies use (null for the others).
std::vector<std::unique_ptr<PlyLaw>> section_laws(const Laminate& lam, const std::vector<Material>& materials,
                                                  const PlyDamageOptions& options) {
  std::vector<std::unique_ptr<PlyLaw>> laws;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const bool used =
        std::any_of(lam.plies().begin(), lam.plies().end(), [i](const Ply& p) { return p.material == i; });
    if (!used) {
      laws.emplace_back();
      continue;
    }
    try {
      laws.push_back(make_ply_law(materials[i], options));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format(
          "{} ([materials.{}]: strengths in Pa, fracture toughnesses G_ft, G_fc, G_mt, G_mc in J/m^2; "
          "docs/progressive_damage.md lists published values)",
          e.what(), materials[i].name));
    }
  }
  return laws;
}

/// The laminate's plies grouped by (material, angle), each group with the z range it spans (the
/// screening bound), and the group of each ply.
struct SectionGroups {
  std::vector<LayeredSection::Group> groups;
  std::vector<std::size_t> of_ply;
};

SectionGroups section_groups(const Laminate& lam, const std::vector<Material>& materials,
                             const std::vector<std::unique_ptr<PlyLaw>>& laws) {
  SectionGroups sg;
  std::vector<LayeredSection::Group>& groups = sg.groups;
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    const Ply& ply = lam.plies()[k];
    auto it = std::find_if(groups.begin(), groups.end(), [&](const LayeredSection::Group& g) {
      return g.material == ply.material && g.T_strain.isApprox(strain_to_material(ply.angle_deg), 0.0);
    });
    sg.of_ply.push_back(static_cast<std::size_t>(it - groups.begin()));
    if (it == groups.end()) {
      LayeredSection::Group g;
      g.material = ply.material;
      g.T_strain = strain_to_material(ply.angle_deg);
      g.Q = reduced_stiffness(materials[ply.material]);
      g.z_min = lam.z_top(k);
      g.z_max = lam.z_bottom(k);
      groups.push_back(g);
      continue;
    }
    it->z_min = std::min(it->z_min, lam.z_top(k));
    it->z_max = std::max(it->z_max, lam.z_bottom(k));
  }
  for (LayeredSection::Group& g : groups)
    g.finish(*laws[g.material]);
  return sg;
}

} // namespace

LayeredSection::LayeredSection(const Laminate& laminate, const std::vector<Material>& materials,
                               const PlyDamageOptions& options)
    : laws_(section_laws(laminate, materials, options)), shear_correction_(laminate.shear_correction()) {
  SectionGroups sg = section_groups(laminate, materials, laws_);
  groups_ = std::move(sg.groups);
  plies_ = ply_points(laminate);
  for (std::size_t k = 0; k < plies_.size(); ++k) {
    plies_[k].cache_undamaged(*laws_[plies_[k].material], shear_correction_);
    plies_[k].group = sg.of_ply[k];
  }
}

LayeredSection::~LayeredSection() = default;
LayeredSection::LayeredSection(LayeredSection&&) noexcept = default;
LayeredSection& LayeredSection::operator=(LayeredSection&&) noexcept = default;

std::size_t LayeredSection::states_per_point() const {
  return 2 * plies_.size();
}

std::size_t LayeredSection::group_count() const {
  return groups_.size();
}

double LayeredSection::onset_bound(const Eigen::Matrix<double, 6, 1>& strain) const {
  double bound = 0.0;
  for (const Group& g : groups_)
    bound = std::max(bound, g.bound(strain));
  return bound;
}

void LayeredSection::set_strains(std::span<PlyDamageState> states, const GeneralizedStrain& strain) const {
  const double root_k = std::sqrt(shear_correction_);
  std::size_t index = 0;
  for (const PlyPoints& ply : plies_)
    for (const double z : ply.z)
      states[index++].strain = ply.strain_at(z, strain, root_k);
}

LayeredSection::Increment LayeredSection::advance(std::span<const PlyDamageState> committed,
                                                  std::span<PlyDamageState> trial,
                                                  const GeneralizedStrain& strain,
                                                  double characteristic_length, double dt,
                                                  double point_weight, PerDamageMode& dissipation,
                                                  std::span<double> group_bound) const {
  const double k = shear_correction_;
  const double root_k = std::sqrt(k);
  Increment out{empty_section(), false};
  std::fill(group_bound.begin(), group_bound.end(), -1.0);
  // A virgin ply whose group is below every Hashin surface: the law would answer it elastically
  // (PlyLaw::advance), so its state and the cached section terms stand for the call.
  const auto below_surfaces = [&](const PlyPoints& ply) {
    double& bound = group_bound[ply.group];
    if (bound < 0.0) bound = groups_[ply.group].bound(strain.head<6>());
    return bound < 1.0;
  };
  std::size_t index = 0;
  for (const PlyPoints& ply : plies_) {
    const PlyLaw& law = *laws_[ply.material];
    for (const double z : ply.z) {
      if (committed[index].virgin() && below_surfaces(ply)) {
        trial[index] = committed[index];
        trial[index].strain = ply.strain_at(z, strain, root_k);
        ++index;
        ply.add_undamaged_to(out.secant, z); // (DP1)
        for (const DamageMode m : all_damage_modes)
          dissipation[m] += 0.0; // the law's zero dissipation: -0 + 0 = +0 as with the call
        continue;
      }
      const PlyDamageUpdate r =
          law.advance(committed[index], ply.strain_at(z, strain, root_k), characteristic_length, dt);
      trial[index] = r.state;
      ++index;
      for (const DamageMode m : all_damage_modes)
        out.initiated = out.initiated || r.state.initiated(m);
      if (r.undamaged())
        ply.add_undamaged_to(out.secant, z); // (DP1)
      else
        ply.add_to(out.secant, z, k, r.secant, r.transverse_shear_secant); // (DP1)
      for (const DamageMode m : all_damage_modes)
        dissipation[m] += r.dissipation[m] * ply.weight * point_weight;
    }
  }
  symmetric_section(out.secant);
  return out;
}

LayeredSection::Held LayeredSection::held(std::span<const PlyDamageState> committed,
                                          std::span<unsigned char> modes,
                                          const GeneralizedStrain& strain) const {
  const double k = shear_correction_;
  const double root_k = std::sqrt(k);
  Held out{empty_section(), false};
  std::size_t index = 0;
  for (const PlyPoints& ply : plies_)
    for (const double z : ply.z) {
      const PlySecant c = laws_[ply.material]->secant_at(committed[index].regularised_damage,
                                                         ply.strain_at(z, strain, root_k));
      if (modes[index] != c.modes) {
        modes[index] = static_cast<unsigned char>(c.modes);
        out.modes_changed = true;
      }
      ++index;
      ply.add_to(out.secant, z, k, c.in_plane, c.transverse_shear); // (DP1)
    }
  symmetric_section(out.secant);
  return out;
}

} // namespace plyimpact
