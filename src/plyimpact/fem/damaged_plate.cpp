#include "plyimpact/fem/damaged_plate.hpp"

#include "plyimpact/fem/element_loop.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

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

using Section8 = Eigen::Matrix<double, 8, 8>;

Section8 as_matrix(const SectionStiffness& s) {
  Section8 C = Section8::Zero();
  C.topLeftCorner<6, 6>() = s.C_mb;
  C.bottomRightCorner<2, 2>() = s.F;
  return C;
}

} // namespace

/// One ply's data at the points through its thickness.
struct DamagedPlateModel::PlyPoints {
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
  void cache_undamaged(const PlyDamageLaw& law, double k) {
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

/// Plies of one section with the same material and angle, and the z range they span: the Hashin indices
/// are convex in z, so their largest value over the range is at one of its ends (the screening bound).
struct DamagedPlateModel::Group {
  std::size_t material = 0;
  Eigen::Matrix3d T_strain;
  Eigen::Matrix3d Q; ///< undamaged reduced stiffness, material axes
  double z_min = 0.0, z_max = 0.0;
  /// Material-axes stress of the undamaged ply at z_min and z_max from (ε0, κ): Q T_ε [I, z I].
  Eigen::Matrix<double, 3, 6> at_min = Eigen::Matrix<double, 3, 6>::Zero();
  Eigen::Matrix<double, 3, 6> at_max = Eigen::Matrix<double, 3, 6>::Zero();
  /// Hashin's coefficients (PD2): 1/Xt², α/S12², 1/Xc², 1/Yt², 1/S12², 1/(2S23)², [(Yc/2S23)² − 1]/Yc.
  double ft = 0.0, ft_shear = 0.0, fc = 0.0, mt = 0.0, shear = 0.0, mc = 0.0, mc_linear = 0.0;

  void finish(const Strengths& st, double alpha) {
    for (auto [M, z] : {std::pair{&at_min, z_min}, std::pair{&at_max, z_max}}) {
      M->leftCols<3>() = Q * T_strain;
      M->rightCols<3>() = z * (Q * T_strain);
    }
    const auto inv2 = [](double x) { return 1.0 / (x * x); };
    ft = inv2(*st.Xt);
    fc = inv2(*st.Xc);
    mt = inv2(*st.Yt);
    shear = inv2(*st.S12);
    ft_shear = alpha * shear;
    mc = inv2(2.0 * *st.S23);
    mc_linear = (*st.Yc * *st.Yc * mc - 1.0) / *st.Yc;
  }
  /// The active Hashin index of the fibre and matrix pairs at stress s (sign conditions applied).
  [[nodiscard]] double index(const Eigen::Vector3d& s) const {
    const double t2 = s(2) * s(2);
    const double fibre = s(0) >= 0.0 ? ft * s(0) * s(0) + ft_shear * t2 : fc * s(0) * s(0);
    const double matrix =
        s(1) >= 0.0 ? mt * s(1) * s(1) + shear * t2 : mc * s(1) * s(1) + mc_linear * s(1) + shear * t2;
    return std::max(fibre, matrix);
  }
  /// An upper bound of the undamaged plies' active Hashin index over the group's z range at a point with
  /// membrane strain and curvature `strain`. Each branch of a pair (fibre, matrix) is convex in z and the
  /// stress affine: the largest active index is at an end of the range or where the sign of σ11 (σ22)
  /// changes, where both branches reduce to their shear terms.
  [[nodiscard]] double bound(const Eigen::Matrix<double, 6, 1>& strain) const {
    const Eigen::Vector3d s0 = at_min * strain, s1 = at_max * strain;
    double b = std::max(index(s0), index(s1));
    for (const int c : {0, 1})
      if (s0(c) * s1(c) < 0.0) {
        const double f = s0(c) / (s0(c) - s1(c)); // where σ_cc = 0
        const double t = s0(2) + f * (s1(2) - s0(2));
        b = std::max(b, (c == 0 ? ft_shear : shear) * t * t);
      }
    return b;
  }
};

/// Throws unless the rows ε0 and κ of S are (2.74) of the gradients (dN_dx, dN_dy), entry for entry: what
/// DamagedPlateModel::membrane_bending_strain computes from the gradients instead of S.
void check_membrane_bending_rows(const StrainOperator& S, const Eigen::Matrix<double, 9, 1>& dN_dx,
                                 const Eigen::Matrix<double, 9, 1>& dN_dy) {
  Eigen::Matrix<double, 6, q9_dofs> B = Eigen::Matrix<double, 6, q9_dofs>::Zero();
  for (Eigen::Index a = 0; a < 9; ++a) {
    B(0, plate_dof(a, 0)) = B(2, plate_dof(a, 1)) = B(3, plate_dof(a, 3)) = B(5, plate_dof(a, 4)) = dN_dx(a);
    B(1, plate_dof(a, 1)) = B(2, plate_dof(a, 0)) = B(4, plate_dof(a, 4)) = B(5, plate_dof(a, 3)) = dN_dy(a);
  }
  if (B != S.topRows<6>())
    throw std::logic_error("damaged plate: the element's rows ε0, κ are not (2.74) of its gradients");
}

/// The transverse-shear rows of S_p on the DOFs they read, (w, θx, θy) of each node in DOF order (their
/// u and v entries are zero). `rows` adds the same products in the same ascending-column order as the
/// full S_p uₑ, so γ is the same to the last bit.
class ShearRows {
public:
  ShearRows() = default;
  explicit ShearRows(const StrainOperator& S) {
    for (Eigen::Index r = 0; r < 2; ++r) {
      for (Eigen::Index j = 0; j < 27; ++j)
        A_(r, j) = S(6 + r, transverse_dof(j));
      for (Eigen::Index a = 0; a < 9; ++a)
        if (S(6 + r, plate_dof(a, 0)) != 0.0 || S(6 + r, plate_dof(a, 1)) != 0.0)
          throw std::logic_error("damaged plate: a transverse-shear strain reading u or v");
    }
  }
  /// Rows 6 and 7 of S_p uₑ, written into e.
  void rows(const ElementVector& ue, Eigen::Matrix<double, 8, 1>& e) const {
    for (Eigen::Index r = 0; r < 2; ++r) {
      double sum = 0.0;
      for (Eigen::Index j = 0; j < 27; ++j)
        sum += A_(r, j) * ue(transverse_dof(j));
      e(6 + r) = sum;
    }
  }

private:
  Eigen::Matrix<double, 2, 27, Eigen::RowMajor> A_;
};

/// The strain operators S_p, shape-function gradients and weights w_p = w det J at the 3×3 Gauss points
/// of one element shape.
struct DamagedPlateModel::ElementOperators {
  std::array<StrainOperator, 9> S;
  std::array<ShearRows, 9> S_shear; ///< S_p's rows γ, for γ = S_p uₑ
  std::array<Eigen::Matrix<double, 9, 1>, 9> dN_dx, dN_dy;
  std::array<double, 9> w{};
};

namespace {

/// The deflection's slopes (w,x, w,y) at point p.
Eigen::Vector2d slopes(const DamagedPlateModel::ElementOperators& ops, std::size_t p,
                       const ElementVector& ue) {
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (Eigen::Index a = 0; a < 9; ++a) {
    g(0) += ops.dN_dx[p](a) * ue(plate_dof(a, 2));
    g(1) += ops.dN_dy[p](a) * ue(plate_dof(a, 2));
  }
  return g;
}

/// E_p = ∂e/∂uₑ at point p: S_p plus the von Kármán rows of the membrane strains (2.47).
StrainOperator von_karman_operator(const DamagedPlateModel::ElementOperators& ops, std::size_t p,
                                   const Eigen::Vector2d& g) {
  StrainOperator E = ops.S[p];
  for (Eigen::Index a = 0; a < 9; ++a) {
    const double nx = ops.dN_dx[p](a), ny = ops.dN_dy[p](a);
    E(0, plate_dof(a, 2)) += g(0) * nx;
    E(1, plate_dof(a, 2)) += g(1) * ny;
    E(2, plate_dof(a, 2)) += g(0) * ny + g(1) * nx;
  }
  return E;
}

} // namespace

namespace {

std::vector<DamagedPlateModel::PlyPoints> ply_points(const Laminate& lam) {
  std::vector<DamagedPlateModel::PlyPoints> plies;
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

} // namespace

namespace {

/// The laminate's materials as the law of an element of characteristic length Lc sees them: the data of
/// the deck, or (Lc > 0) with the strengths lowered to the band limit of Lc (band_limited_strengths).
std::vector<Material> class_materials(const Laminate& lam, double Lc, double alpha) {
  std::vector<Material> materials = lam.materials();
  if (Lc > 0.0)
    for (Material& m : materials)
      if (m.toughness.G_ft && m.toughness.G_fc && m.toughness.G_mt && m.toughness.G_mc && m.strength.Xt &&
          m.strength.Xc && m.strength.Yt && m.strength.Yc && m.strength.S12)
        m.strength = band_limited_strengths(m, Lc, alpha);
  return materials;
}

/// One damage law per material the laminate's plies use (null for the others).
std::vector<std::unique_ptr<PlyDamageLaw>>
section_laws(const Laminate& lam, const std::vector<Material>& materials, const PlyDamageOptions& options) {
  std::vector<std::unique_ptr<PlyDamageLaw>> laws;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const bool used =
        std::any_of(lam.plies().begin(), lam.plies().end(), [i](const Ply& p) { return p.material == i; });
    if (!used) {
      laws.emplace_back();
      continue;
    }
    try {
      laws.push_back(std::make_unique<PlyDamageLaw>(materials[i], options));
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
  std::vector<DamagedPlateModel::Group> groups;
  std::vector<std::size_t> of_ply;
};

SectionGroups section_groups(const Laminate& lam, const std::vector<Material>& materials, double alpha) {
  SectionGroups sg;
  std::vector<DamagedPlateModel::Group>& groups = sg.groups;
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    const Ply& ply = lam.plies()[k];
    auto it = std::find_if(groups.begin(), groups.end(), [&](const DamagedPlateModel::Group& g) {
      return g.material == ply.material && g.T_strain.isApprox(strain_to_material(ply.angle_deg), 0.0);
    });
    sg.of_ply.push_back(static_cast<std::size_t>(it - groups.begin()));
    if (it == groups.end()) {
      DamagedPlateModel::Group g;
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
  for (DamagedPlateModel::Group& g : groups)
    g.finish(materials[g.material].strength, alpha);
  return sg;
}

} // namespace

void DamagedPlateModel::build_element_operators() {
  const Mesh& mesh = model_.mesh();
  for (int c = 0; c < mesh.shape_class_count(); ++c) {
    const ElementCoordinates xy = mesh.element_coordinates(mesh.representative(c));
    ElementOperators ops;
    for (std::size_t p = 0; p < gauss3x3.size(); ++p) {
      ops.S[p] = model_.element().strain_operator(xy, gauss3x3[p].xi, gauss3x3[p].eta);
      ops.S_shear[p] = ShearRows(ops.S[p]);
      const PointKinematics k = point_kinematics(xy, gauss3x3[p].xi, gauss3x3[p].eta);
      ops.w[p] = gauss3x3[p].weight * k.detJ;
      ops.dN_dx[p] = k.dN_dx;
      ops.dN_dy[p] = k.dN_dy;
      check_membrane_bending_rows(ops.S[p], ops.dN_dx[p], ops.dN_dy[p]);
    }
    operators_.push_back(ops);
  }
  for (int e = 0; e < mesh.element_count(); ++e) {
    double a = 0.0;
    for (const double w : operators_of(e).w)
      a += w;
    area_.push_back(a);
    length_.push_back(std::sqrt(a));
  }
}

void DamagedPlateModel::build_length_classes() {
  // Without strength reduction the laws do not depend on L_c: one class (length 0 = the deck's data).
  class_of_element_.assign(length_.size(), 0);
  if (!settings_.reduce_strengths_above_band_limit) {
    class_length_ = {0.0};
    return;
  }
  for (std::size_t e = 0; e < length_.size(); ++e) {
    const double L = length_[e];
    const auto same = [L](double c) { return std::abs(c - L) <= 1e-9 * L; };
    auto it = std::find_if(class_length_.begin(), class_length_.end(), same);
    if (it == class_length_.end()) it = class_length_.insert(class_length_.end(), L);
    class_of_element_[e] = static_cast<int>(it - class_length_.begin());
  }
}

DamagedPlateModel::DamagedPlateModel(const PlateModel& model, ProgressiveDamageSettings settings,
                                     Kinematics kinematics)
    : model_(model), settings_(settings) {
  if (model.formulation() != ElementFormulation::mitc9)
    throw std::invalid_argument("progressive damage needs the MITC9 element ([mesh] element = \"mitc9\" or "
                                "\"auto\"): the q9 element integrates transverse shear at other points than "
                                "the 3x3 Gauss points where the plies' damage lives");
  for (const Laminate& lam : model.laminates())
    if (lam.stiffness_model() != ReducedStiffnessModel::exact)
      throw std::invalid_argument("progressive damage needs the exact reduced stiffness (1.3) "
                                  "([laminate] reduced_stiffness = \"exact\"): the damage law degrades it");
  build_element_operators();
  build_length_classes();
  std::vector<std::vector<std::size_t>> group_of_ply; // [section][ply]: the same plies in every class
  for (const double Lc : class_length_) {
    std::vector<std::vector<std::unique_ptr<PlyDamageLaw>>> laws;
    std::vector<std::vector<Group>> groups;
    group_of_ply.clear();
    for (const Laminate& lam : model.laminates()) {
      const std::vector<Material> materials = class_materials(lam, Lc, settings_.law.alpha);
      laws.push_back(section_laws(lam, materials, settings_.law));
      SectionGroups sg = section_groups(lam, materials, settings_.law.alpha);
      groups.push_back(std::move(sg.groups));
      group_of_ply.push_back(std::move(sg.of_ply));
    }
    laws_.push_back(std::move(laws));
    groups_.push_back(std::move(groups));
  }
  for (std::size_t s = 0; s < model.laminates().size(); ++s) {
    const Laminate& lam = model.laminates()[s];
    std::vector<PlyPoints> plies = ply_points(lam);
    for (std::size_t k = 0; k < plies.size(); ++k) {
      plies[k].cache_undamaged(*laws_.front()[s][plies[k].material], lam.shear_correction());
      plies[k].group = group_of_ply[s][k];
    }
    plies_.push_back(std::move(plies));
  }
  K0_ = model.stiffness();
  const SparseMatrix& pattern = model.pattern();
  if (K0_.nonZeros() != pattern.nonZeros())
    throw std::logic_error("damaged plate: the stiffness does not have the model's sparsity pattern");
  slot_ = element_slots(model, K0_);
  K0_by_rows_ = K0_;
  if (kinematics == Kinematics::von_karman)
    von_karman_ = std::make_unique<NonlinearPlateModel>(model, StrainMeasure::von_karman);
}

Eigen::Matrix<double, 8, 1> DamagedPlateModel::point_strain(const ElementOperators& ops, std::size_t p,
                                                            const ElementVector& ue) const {
  Eigen::Matrix<double, 8, 1> e = membrane_bending_strain(ops, p, ue);
  ops.S_shear[p].rows(ue, e);
  return e;
}

Eigen::Matrix<double, 8, 1> DamagedPlateModel::membrane_bending_strain(const ElementOperators& ops,
                                                                       std::size_t p,
                                                                       const ElementVector& ue) const {
  // (2.74), term by term in the column order of S_p (node by node, u before v, θx before θy): the same
  // sums as the rows ε0 and κ of S_p uₑ to the last bit, without its zero entries.
  Eigen::Matrix<double, 8, 1> e = Eigen::Matrix<double, 8, 1>::Zero();
  for (Eigen::Index a = 0; a < 9; ++a) {
    const double Nx = ops.dN_dx[p](a), Ny = ops.dN_dy[p](a);
    const double u = ue(plate_dof(a, 0)), v = ue(plate_dof(a, 1)), tx = ue(plate_dof(a, 3)),
                 ty = ue(plate_dof(a, 4));
    e(0) += Nx * u; // εx = u,x
    e(1) += Ny * v; // εy = v,y
    e(2) += Ny * u; // γxy = u,y + v,x
    e(2) += Nx * v;
    e(3) += Nx * tx; // κx = θx,x
    e(4) += Ny * ty; // κy = θy,y
    e(5) += Ny * tx; // κxy = θx,y + θy,x
    e(5) += Nx * ty;
  }
  if (von_karman_) { // (2.47): the membrane strains of the slopes
    const Eigen::Vector2d g = slopes(ops, p, ue);
    e(0) += 0.5 * g(0) * g(0);
    e(1) += 0.5 * g(1) * g(1);
    e(2) += g(0) * g(1);
  }
  return e;
}

DamagedPlateModel::~DamagedPlateModel() = default;

const DamagedPlateModel::ElementOperators& DamagedPlateModel::operators_of(int e) const {
  return operators_[static_cast<std::size_t>(model_.mesh().shape_class(e))];
}

std::optional<std::string> DamagedPlateModel::strength_reduction_warning() const {
  struct Largest {
    double ratio = 1.0;
    std::string material, strength;
    double deck = 0.0, used = 0.0;
  } largest;
  std::vector<bool> class_reduced(class_length_.size(), false);
  for (std::size_t c = 0; c < class_length_.size(); ++c)
    for (std::size_t s = 0; s < laws_[c].size(); ++s)
      for (std::size_t i = 0; i < laws_[c][s].size(); ++i) {
        if (!laws_[c][s][i]) continue;
        const Material& m = laws_[c][s][i]->material();
        const Material& deck = model_.laminates()[s].materials()[i];
        const std::tuple<const char*, std::optional<double>, std::optional<double>> pairs[] = {
            {"Xt", deck.strength.Xt, m.strength.Xt},
            {"Xc", deck.strength.Xc, m.strength.Xc},
            {"Yt", deck.strength.Yt, m.strength.Yt},
            {"Yc", deck.strength.Yc, m.strength.Yc},
            {"S12", deck.strength.S12, m.strength.S12}};
        for (const auto& [name, before, after] : pairs) {
          const double ratio = *after / *before;
          if (ratio >= 1.0) continue;
          class_reduced[c] = true;
          if (ratio < largest.ratio) largest = {ratio, m.name, name, *before, *after};
        }
      }
  int elements = 0;
  for (const int c : class_of_element_)
    elements += class_reduced[static_cast<std::size_t>(c)] ? 1 : 0;
  if (elements == 0) return std::nullopt;
  return fmt::format(
      "progressive damage: {} of {} elements are larger than a band limit; their strengths are lowered so "
      "that each mode still dissipates G (Maimi et al. 2007, [damage] oversize = \"reduce-strength\"), by "
      "up to {:.0f} % ({} of '{}': {:.4g} -> {:.4g} MPa): damage starts earlier there than the strengths "
      "say; refine the mesh toward the impact point for onset results",
      elements, model_.mesh().element_count(), 100.0 * (1.0 - largest.ratio), largest.strength,
      largest.material, largest.deck * 1e-6, largest.used * 1e-6);
}

DamageField DamagedPlateModel::virgin_field() const {
  DamageField f;
  f.slot_of_element_.assign(static_cast<std::size_t>(model_.mesh().element_count()), -1);
  f.ply_area_.assign(model_.laminate().ply_count(), 0.0);
  f.bound_.assign(static_cast<std::size_t>(model_.mesh().element_count()), 0.0);
  f.u_committed_ = Eigen::VectorXd::Zero(model_.size());
  for (const Laminate& lam : model_.laminates())
    f.ply_area_.resize(std::max(f.ply_area_.size(), lam.ply_count()), 0.0);
  for (const std::vector<Group>& groups : groups_.front())
    f.groups_ = std::max(f.groups_, groups.size());
  return f;
}

DamagedPlateModel::PointStrains DamagedPlateModel::evaluate_element(int e, const Eigen::VectorXd& u,
                                                                    double dt, DamageField& field,
                                                                    std::vector<double>& group_bound) const {
  DamageField::ActiveElement& a = field.active_[static_cast<std::size_t>(field.slot_of_element_[e])];
  const int section = model_.section_index(e);
  const Laminate& lam = model_.laminates()[static_cast<std::size_t>(section)];
  const std::vector<PlyPoints>& plies = plies_[static_cast<std::size_t>(section)];
  const auto& laws = laws_[class_of(e)][static_cast<std::size_t>(section)];
  const std::vector<Group>& groups = groups_[class_of(e)][static_cast<std::size_t>(section)];
  const double root_k = std::sqrt(lam.shear_correction());
  const double k = lam.shear_correction();
  const double Lc = characteristic_length(e);
  const ElementOperators& ops = operators_of(e);
  const SectionStiffness& undamaged = model_.section(section).stiffness;
  const ElementVector ue = model_.element_dofs(u, e);
  const std::size_t per_point = 2 * plies.size();
  a.trial_dissipation = {};
  PointStrains strains;
  for (std::size_t p = 0; p < 9; ++p) {
    strains[p] = point_strain(ops, p, ue);
    const Eigen::Matrix<double, 8, 1>& strain = strains[p];
    const std::size_t first = p * per_point;
    if (a.pristine[p]) {
      if (hashin_bound(groups, strain.head<6>()) < 1.0) {
        // Undamaged and below every Hashin surface: the elastic section, no law call.
        if (a.trial_touched[p])
          std::copy_n(a.committed.begin() + static_cast<std::ptrdiff_t>(first), per_point,
                      a.trial.begin() + static_cast<std::ptrdiff_t>(first));
        a.trial_touched[p] = false;
        a.pristine_trial[p] = true;
        a.sections[p] = undamaged;
        continue;
      }
      // The law integrates from the strain of the committed state: the point's strain at the last commit.
      const Eigen::Matrix<double, 8, 1> before =
          point_strain(ops, p, model_.element_dofs(field.u_committed_, e));
      std::size_t index = first;
      for (const PlyPoints& ply : plies)
        for (const double z : ply.z)
          a.committed[index++].strain = ply.strain_at(z, before, root_k);
    }
    SectionStiffness sec = empty_section();
    bool initiated = false;
    std::size_t index = first;
    std::fill(group_bound.begin(), group_bound.end(), -1.0);
    // A virgin ply whose group is below every Hashin surface: the law would answer it elastically
    // (PlyDamageLaw::advance), so its state and the cached section terms stand for the call.
    const auto below_surfaces = [&](const PlyPoints& ply) {
      double& bound = group_bound[ply.group];
      if (bound < 0.0) bound = groups[ply.group].bound(strain.head<6>());
      return bound < 1.0;
    };
    for (const PlyPoints& ply : plies) {
      const PlyDamageLaw& law = *laws[ply.material];
      for (const double z : ply.z) {
        if (a.committed[index].virgin() && below_surfaces(ply)) {
          a.trial[index] = a.committed[index];
          a.trial[index].strain = ply.strain_at(z, strain, root_k);
          ++index;
          ply.add_undamaged_to(sec, z); // (DP1)
          for (const DamageMode m : all_damage_modes)
            a.trial_dissipation[m] += 0.0; // the law's zero dissipation: -0 + 0 = +0 as with the call
          continue;
        }
        const PlyDamageUpdate r = law.advance(a.committed[index], ply.strain_at(z, strain, root_k), Lc, dt);
        a.trial[index] = r.state;
        ++index;
        for (const DamageMode m : all_damage_modes)
          initiated = initiated || r.state.initiated(m);
        if (r.undamaged())
          ply.add_undamaged_to(sec, z); // (DP1)
        else
          ply.add_to(sec, z, k, r.secant, r.transverse_shear_secant); // (DP1)
        for (const DamageMode m : all_damage_modes)
          a.trial_dissipation[m] += r.dissipation[m] * ply.weight * ops.w[p];
      }
    }
    symmetric_section(sec);
    a.sections[p] = sec;
    a.trial_touched[p] = true;
    a.pristine_trial[p] = !initiated;
  }
  a.evaluated = true;
  a.has_sections = true;
  return strains;
}

void DamagedPlateModel::section_force(DamageField& field, std::size_t slot, const PointStrains& strains,
                                      const Eigen::VectorXd& u) const {
  const DamageField::ActiveElement& a = field.active_[slot];
  const int e = a.element;
  const ElementOperators& ops = operators_of(e);
  const Section8 C0 = as_matrix(model_.section(model_.section_index(e)).stiffness);
  ElementVector& fe = field.element_forces_[slot];
  fe.setZero();
  bool changed = false;
  const ElementVector ue = von_karman_ ? model_.element_dofs(u, e) : ElementVector();
  for (std::size_t p = 0; p < 9; ++p) {
    if (a.pristine_trial[p]) continue; // the undamaged section: K0 u (or f_vK) holds it
    if (von_karman_)
      fe.noalias() += von_karman_operator(ops, p, slopes(ops, p, ue)).transpose() *
                      (ops.w[p] * ((as_matrix(a.sections[p]) - C0) * strains[p]));
    else
      fe.noalias() += ops.S[p].transpose() * (ops.w[p] * ((as_matrix(a.sections[p]) - C0) * strains[p]));
    changed = true;
  }
  field.force_changed_[slot] = changed ? 1 : 0;
}

template <class Sections>
void DamagedPlateModel::assemble_force(const Eigen::VectorXd& u, DamageField& field, Eigen::VectorXd& f,
                                       const Sections& sections) const {
  elastic_force(u, f, field);
  const std::size_t n = field.active_.size();
  field.element_forces_.resize(n);
  field.force_changed_.resize(n);
  field.group_bounds_.resize(
      std::max(field.group_bounds_.size(), static_cast<std::size_t>(element_threads())));
  for (std::vector<double>& scratch : field.group_bounds_)
    scratch.resize(field.groups_);
  for_each_element(static_cast<int>(n), [&](int i) {
    const auto slot = static_cast<std::size_t>(i);
    std::vector<double>& group_bound = field.group_bounds_[static_cast<std::size_t>(omp_get_thread_num())];
    section_force(field, slot, sections(slot, group_bound), u);
  });
  for (std::size_t slot = 0; slot < n; ++slot) // in slot order, as a loop on one thread adds them
    if (field.force_changed_[slot] != 0)
      scatter_add(f, model_.element_equations(field.active_[slot].element), field.element_forces_[slot]);
}

Eigen::VectorXd DamagedPlateModel::internal_force(const Eigen::VectorXd& u, double dt,
                                                  DamageField& field) const {
  Eigen::VectorXd f(u.size());
  internal_force_into(u, dt, field, f);
  return f;
}

void DamagedPlateModel::internal_force_into(const Eigen::VectorXd& u, double dt, DamageField& field,
                                            Eigen::VectorXd& f) const {
  assemble_force(u, field, f, [&](std::size_t slot, std::vector<double>& group_bound) {
    return evaluate_element(field.active_[slot].element, u, dt, field, group_bound);
  });
}

DamagedPlateModel::PointStrains DamagedPlateModel::frozen_sections(DamageField& field, std::size_t slot,
                                                                   const Eigen::VectorXd& u) const {
  DamageField::ActiveElement& a = field.active_[slot];
  const int e = a.element;
  const int section = model_.section_index(e);
  const std::vector<PlyPoints>& plies = plies_[static_cast<std::size_t>(section)];
  const auto& laws = laws_[class_of(e)][static_cast<std::size_t>(section)];
  const double k = model_.laminates()[static_cast<std::size_t>(section)].shear_correction();
  const double root_k = std::sqrt(k);
  const ElementOperators& ops = operators_of(e);
  const ElementVector ue = model_.element_dofs(u, e);
  PointStrains strains;
  for (std::size_t p = 0; p < 9; ++p) {
    a.pristine_trial[p] = a.pristine[p];
    if (a.pristine[p]) continue; // never initiated: the undamaged section (K0 u holds it)
    strains[p] = point_strain(ops, p, ue);
    SectionStiffness sec = empty_section();
    std::size_t index = p * 2 * plies.size();
    for (const PlyPoints& ply : plies)
      for (const double z : ply.z) {
        const PlySecant c = laws[ply.material]->secant_at(a.committed[index].regularised_damage,
                                                          ply.strain_at(z, strains[p], root_k));
        if (a.modes[index] != c.modes) {
          a.modes[index] = static_cast<unsigned char>(c.modes);
          a.modes_changed = true;
        }
        ++index;
        ply.add_to(sec, z, k, c.in_plane, c.transverse_shear); // (DP1)
      }
    symmetric_section(sec);
    a.sections[p] = sec;
  }
  a.has_sections = true;
  return strains;
}

Eigen::VectorXd DamagedPlateModel::frozen_internal_force(const Eigen::VectorXd& u, DamageField& field) const {
  Eigen::VectorXd f(u.size());
  frozen_internal_force_into(u, field, f);
  return f;
}

void DamagedPlateModel::frozen_internal_force_into(const Eigen::VectorXd& u, DamageField& field,
                                                   Eigen::VectorXd& f) const {
  assemble_force(u, field, f, [&](std::size_t slot, std::vector<double>& /*group_bound*/) {
    return frozen_sections(field, slot, u);
  });
  for (DamageField::ActiveElement& a : field.active_)
    field.modes_changed_ = std::exchange(a.modes_changed, false) || field.modes_changed_;
}

SparseMatrix DamagedPlateModel::secant_stiffness(const DamageField& field) const {
  SparseMatrix K = K0_;
  add_section_differences(K, field, nullptr);
  return K;
}

void DamagedPlateModel::elastic_force(const Eigen::VectorXd& u, Eigen::VectorXd& f,
                                      DamageField& field) const {
  if (von_karman_)
    von_karman_->internal_force(u, f, field.elastic_forces_);
  else
    parallel_rows_product(K0_by_rows_, u, f);
}

SparseMatrix DamagedPlateModel::iteration_matrix(const Eigen::VectorXd& u, const DamageField& field) const {
  if (!von_karman_) return secant_stiffness(field);
  SparseMatrix K = von_karman_->tangent_stiffness(u);
  if (K.nonZeros() != K0_.nonZeros())
    throw std::logic_error("damaged plate: the tangent does not have the model's sparsity pattern");
  add_section_differences(K, field, &u);
  return K;
}

void DamagedPlateModel::add_section_differences(SparseMatrix& K, const DamageField& field,
                                                const Eigen::VectorXd* u) const {
  double* values = K.valuePtr();
  for (const DamageField::ActiveElement& a : field.active_) {
    if (!a.has_sections) continue;
    const int e = a.element;
    const ElementOperators& ops = operators_of(e);
    const Section8 C0 = as_matrix(model_.section(model_.section_index(e)).stiffness);
    const ElementVector ue = u ? model_.element_dofs(*u, e) : ElementVector::Zero();
    ElementMatrix dK = ElementMatrix::Zero();
    bool changed = false;
    for (std::size_t p = 0; p < 9; ++p) {
      if (a.pristine_trial[p]) continue;
      changed = true;
      if (!u) { // w outside the parentheses would change the product's rounding (Eigen takes it out)
        dK.noalias() += ops.S[p].transpose() * (ops.w[p] * (as_matrix(a.sections[p]) - C0)) * ops.S[p];
        continue;
      }
      const Section8 dC = ops.w[p] * (as_matrix(a.sections[p]) - C0);
      const Eigen::Vector2d g = slopes(ops, p, ue);
      const StrainOperator E = von_karman_operator(ops, p, g);
      dK.noalias() += E.transpose() * dC * E;
      // (2.103): the initial-stress term of the membrane resultants' difference, on the w DOFs
      const Eigen::Vector3d dN = (dC * point_strain(ops, p, ue)).head<3>();
      for (Eigen::Index i = 0; i < 9; ++i)
        for (Eigen::Index j = 0; j < 9; ++j)
          dK(plate_dof(i, 2), plate_dof(j, 2)) +=
              dN(0) * ops.dN_dx[p](i) * ops.dN_dx[p](j) + dN(1) * ops.dN_dy[p](i) * ops.dN_dy[p](j) +
              dN(2) * (ops.dN_dx[p](i) * ops.dN_dy[p](j) + ops.dN_dy[p](i) * ops.dN_dx[p](j));
    }
    if (changed) add_element_values(values, slot_[static_cast<std::size_t>(e)], dK);
  }
}

double DamagedPlateModel::hashin_bound(const std::vector<Group>& groups,
                                       const Eigen::Matrix<double, 6, 1>& strain) {
  double bound = 0.0;
  for (const Group& g : groups)
    bound = std::max(bound, g.bound(strain));
  return bound;
}

double DamagedPlateModel::element_bound(int e, const Eigen::VectorXd& u) const {
  const std::vector<Group>& groups = groups_[class_of(e)][static_cast<std::size_t>(model_.section_index(e))];
  const ElementOperators& ops = operators_of(e);
  const ElementVector ue = model_.element_dofs(u, e);
  double bound = 0.0;
  for (std::size_t p = 0; p < 9; ++p)
    bound = std::max(bound, hashin_bound(groups, membrane_bending_strain(ops, p, ue).head<6>()));
  return bound;
}

void DamagedPlateModel::activate(int e, DamageField& field) const {
  DamageField::ActiveElement a;
  a.element = e;
  const std::size_t n =
      9 * 2 * model_.laminates()[static_cast<std::size_t>(model_.section_index(e))].ply_count();
  a.committed.assign(n, PlyDamageState{});
  a.trial = a.committed;
  a.modes.assign(n, 0);
  for (SectionStiffness& sec : a.sections) {
    sec.C_mb.setZero();
    sec.F.setZero();
  }
  field.slot_of_element_[static_cast<std::size_t>(e)] = static_cast<int>(field.active_.size());
  field.active_.push_back(std::move(a));
}

void DamagedPlateModel::inactive_bounds(const Eigen::VectorXd& u, DamageField& field) const {
  for_each_element(model_.mesh().element_count(), [&](int e) {
    if (field.slot_of_element_[static_cast<std::size_t>(e)] < 0)
      field.bound_[static_cast<std::size_t>(e)] = element_bound(e, u);
  });
}

int DamagedPlateModel::activate_bounded_above(double threshold, DamageField& field) const {
  int added = 0;
  for (int e = 0; e < model_.mesh().element_count(); ++e) // in element order: the slots' order
    if (field.slot_of_element_[static_cast<std::size_t>(e)] < 0 &&
        field.bound_[static_cast<std::size_t>(e)] >= threshold) {
      activate(e, field);
      ++added;
    }
  return added;
}

int DamagedPlateModel::screen(const Eigen::VectorXd& u, DamageField& field) const {
  inactive_bounds(u, field);
  return activate_bounded_above(settings_.screen_fraction, field);
}

bool DamagedPlateModel::activate_reached(const Eigen::VectorXd& u, DamageField& field) const {
  // One pass over the inactive elements per step: their bounds at the converged u serve commit() too.
  inactive_bounds(u, field);
  const bool reached = activate_bounded_above(1.0, field) > 0;
  field.bounds_current_ = !reached;
  return reached;
}

void DamagedPlateModel::commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f_int,
                               DamageField& field) const {
  for (const DamageField::ActiveElement& a : field.active_)
    if (!a.evaluated)
      throw std::logic_error("damaged plate: commit of an element whose trial state was not evaluated");
  std::fill(field.ply_area_.begin(), field.ply_area_.end(), 0.0);
  field.projected_area_ = 0.0;
  field.damaged_points_.clear();
  double growth = 0.0;
  const double threshold = settings_.area_threshold;
  for (DamageField::ActiveElement& a : field.active_) {
    const ElementOperators& ops = operators_of(a.element);
    const std::size_t plies = a.trial.size() / 18;
    for (std::size_t p = 0; p < 9; ++p) {
      if (a.pristine_trial[p]) continue; // no damage at this point
      bool any = false;
      for (std::size_t k = 0; k < plies; ++k) {
        bool damaged = false;
        for (std::size_t g = 0; g < 2; ++g) {
          const std::size_t i = (p * plies + k) * 2 + g;
          for (const DamageMode m : all_damage_modes) {
            const double d = a.trial[i].regularised_damage[m];
            growth = std::max(growth, d - a.committed[i].regularised_damage[m]);
            damaged = damaged || d >= threshold;
            if (d > 0.0) {
              const DamageField::FirstDamage here{m, a.element, static_cast<int>(k)};
              if (!field.first_) field.first_ = here;
              auto& of_mode = field.first_by_mode_[m];
              if (!of_mode) of_mode = here;
            }
          }
        }
        if (damaged) field.ply_area_[k] += ops.w[p];
        any = any || damaged;
      }
      if (any) {
        field.projected_area_ += ops.w[p];
        field.damaged_points_.push_back({a.element, static_cast<int>(p), ops.w[p]});
      }
    }
    a.committed.swap(a.trial);
    a.pristine = a.pristine_trial;
    // trial now holds the previous committed states: for the points still pristine those are virgin too
    // (damage never heals), for the others the next evaluation overwrites them.
    a.trial_touched.fill(false);
    for (const DamageMode m : all_damage_modes)
      field.dissipated_[m] += a.trial_dissipation[m];
    a.trial_dissipation = {};
    a.evaluated = false;
  }
  field.growth_ += growth;
  field.stored_energy_ = 0.5 * u.dot(f_int);
  field.u_committed_ = u;
  // Elements near a surface join (bounds of activate_reached() at this u when it ran last).
  if (field.bounds_current_)
    activate_bounded_above(settings_.screen_fraction, field);
  else
    screen(u, field);
  field.bounds_current_ = false;
}

std::vector<ElementPlyDamage> DamageField::element_ply_damage() const {
  std::vector<ElementPlyDamage> out;
  for (const ActiveElement& a : active_) {
    const std::size_t plies = a.committed.size() / 18;
    for (std::size_t k = 0; k < plies; ++k) {
      ElementPlyDamage d{a.element, static_cast<int>(k), {}};
      for (std::size_t p = 0; p < 9; ++p)
        for (std::size_t g = 0; g < 2; ++g)
          for (const DamageMode m : all_damage_modes)
            d.damage[m] = std::max(d.damage[m], a.committed[(p * plies + k) * 2 + g].regularised_damage[m]);
      out.push_back(d);
    }
  }
  return out;
}

} // namespace plyimpact
