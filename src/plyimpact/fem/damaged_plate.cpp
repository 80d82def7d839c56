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

using Section8 = Eigen::Matrix<double, 8, 8>;

Section8 as_matrix(const SectionStiffness& s) {
  Section8 C = Section8::Zero();
  C.topLeftCorner<6, 6>() = s.C_mb;
  C.bottomRightCorner<2, 2>() = s.F;
  return C;
}

} // namespace

/// Throws unless the rows ε0 and κ of S are (2.74) of the gradients (dN_dx, dN_dy), entry for entry: what
/// DamagedPlate::membrane_bending_strain computes from the gradients instead of S.
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
struct DamagedPlate::ElementOperators {
  std::array<StrainOperator, 9> S;
  std::array<ShearRows, 9> S_shear; ///< S_p's rows γ, for γ = S_p uₑ
  std::array<Eigen::Matrix<double, 9, 1>, 9> dN_dx, dN_dy;
  std::array<double, 9> w{};
};

namespace {

/// The deflection's slopes (w,x, w,y) at point p.
Eigen::Vector2d slopes(const DamagedPlate::ElementOperators& ops, std::size_t p, const ElementVector& ue) {
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (Eigen::Index a = 0; a < 9; ++a) {
    g(0) += ops.dN_dx[p](a) * ue(plate_dof(a, 2));
    g(1) += ops.dN_dy[p](a) * ue(plate_dof(a, 2));
  }
  return g;
}

/// E_p = ∂e/∂uₑ at point p: S_p plus the von Kármán rows of the membrane strains (2.47).
StrainOperator von_karman_operator(const DamagedPlate::ElementOperators& ops, std::size_t p,
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

/// The laminate's materials as the law of an element of characteristic length Lc sees them: the data of
/// the deck, or (Lc > 0) with the strengths lowered to the law's band limit of Lc.
std::vector<Material> class_materials(const Laminate& lam, double Lc, const PlyDamageOptions& options) {
  std::vector<Material> materials = lam.materials();
  if (Lc > 0.0)
    for (Material& m : materials) {
      std::unique_ptr<PlyLaw> law;
      try {
        law = make_ply_law(m, options);
      } catch (const std::invalid_argument&) {
        continue; // a material no ply uses may lack the law's data (LayeredSection checks those that are)
      }
      m.strength = law->band_limited_strengths(Lc);
    }
  return materials;
}

} // namespace

void DamagedPlate::build_element_operators() {
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

void DamagedPlate::build_length_classes() {
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

DamagedPlate::DamagedPlate(const DiscretePlate& model, ProgressiveDamageSettings settings,
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
  for (const double Lc : class_length_) {
    std::vector<LayeredSection> sections;
    for (const Laminate& lam : model.laminates())
      sections.emplace_back(lam, class_materials(lam, Lc, settings_.law), settings_.law);
    sections_.push_back(std::move(sections));
  }
  build_lowered_strengths();
  K0_ = model.stiffness();
  const SparseMatrix& pattern = model.pattern();
  if (K0_.nonZeros() != pattern.nonZeros())
    throw std::logic_error("damaged plate: the stiffness does not have the model's sparsity pattern");
  slot_ = element_slots(model, K0_);
  K0_by_rows_ = K0_;
  if (kinematics == Kinematics::von_karman)
    von_karman_ = std::make_unique<NonlinearPlate>(model, StrainMeasure::von_karman);
}

Eigen::Matrix<double, 8, 1> DamagedPlate::point_strain(const ElementOperators& ops, std::size_t p,
                                                       const ElementVector& ue) const {
  Eigen::Matrix<double, 8, 1> e = membrane_bending_strain(ops, p, ue);
  ops.S_shear[p].rows(ue, e);
  return e;
}

Eigen::Matrix<double, 8, 1> DamagedPlate::membrane_bending_strain(const ElementOperators& ops, std::size_t p,
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

DamagedPlate::~DamagedPlate() = default;

const LayeredSection& DamagedPlate::layered_section(int e) const {
  const auto c = static_cast<std::size_t>(class_of_element_[static_cast<std::size_t>(e)]);
  return sections_[c][static_cast<std::size_t>(model_.section_index(e))];
}

const DamagedPlate::ElementOperators& DamagedPlate::operators_of(int e) const {
  return operators_[static_cast<std::size_t>(model_.mesh().shape_class(e))];
}

void DamagedPlate::build_lowered_strengths() {
  lowered_.assign(sections_.size(), {});
  for (std::size_t c = 0; c < sections_.size(); ++c)
    for (std::size_t s = 0; s < sections_[c].size(); ++s) {
      std::optional<LoweredStrength> largest;
      for (std::size_t i = 0; i < model_.laminates()[s].materials().size(); ++i) {
        const PlyLaw* law = sections_[c][s].law(i);
        if (!law) continue;
        const Strengths& used = law->material().strength;
        const Strengths& deck = model_.laminates()[s].materials()[i].strength;
        const std::tuple<const char*, std::optional<double>, std::optional<double>> pairs[] = {
            {"Xt", deck.Xt, used.Xt},
            {"Xc", deck.Xc, used.Xc},
            {"Yt", deck.Yt, used.Yt},
            {"Yc", deck.Yc, used.Yc},
            {"S12", deck.S12, used.S12}};
        for (const auto& [name, before, after] : pairs) {
          if (!(*after < *before)) continue;
          const LoweredStrength l{law->material().name, name, *before, *after};
          if (!largest || l.reduction() > largest->reduction()) largest = l;
        }
      }
      lowered_[c].push_back(largest);
    }
}

std::optional<LoweredStrength> DamagedPlate::lowered_strength(int e) const {
  const auto c = static_cast<std::size_t>(class_of_element_[static_cast<std::size_t>(e)]);
  std::optional<LoweredStrength> l = lowered_[c][static_cast<std::size_t>(model_.section_index(e))];
  if (l) {
    l->element = e;
    l->centre = model_.mesh().map(e, 0.0, 0.0);
  }
  return l;
}

StrengthReduction DamagedPlate::lowered_elements() const {
  StrengthReduction r;
  for (int e = 0; e < model_.mesh().element_count(); ++e)
    if (const std::optional<LoweredStrength> l = lowered_strength(e)) {
      ++r.elements;
      keep_larger_reduction(r.largest, l);
    }
  return r;
}

StrengthReduction DamagedPlate::strength_reduction(const DamageField& field) const {
  StrengthReduction r = lowered_elements();
  if (!r.largest) return r;
  std::vector<int> damaged;
  for (const ElementPlyDamage& d : field.element_ply_damage())
    if (d.damage.sum() > 0.0) damaged.push_back(d.element);
  std::sort(damaged.begin(), damaged.end()); // element order: the first element of the largest
  for (const int e : damaged)
    keep_larger_reduction(r.largest_where_damaged, lowered_strength(e));
  return r;
}

std::optional<std::string> DamagedPlate::strength_reduction_warning() const {
  const StrengthReduction r = lowered_elements();
  if (!r.largest) return std::nullopt;
  const LoweredStrength& l = *r.largest;
  return fmt::format(
      "progressive damage: {} of {} elements are larger than a band limit; their strengths are lowered so "
      "that each mode still dissipates G (Maimi et al. 2007, [damage] oversize = \"reduce-strength\"), by "
      "up to {:.0f} % ({} of '{}': {:.4g} -> {:.4g} MPa): damage starts earlier there than the strengths "
      "say; refine the mesh toward the impact point for onset results",
      r.elements, model_.mesh().element_count(), 100.0 * l.reduction(), l.strength, l.material, l.deck * 1e-6,
      l.used * 1e-6);
}

DamageField DamagedPlate::virgin_field() const {
  DamageField f;
  f.plate_ = this;
  f.slot_of_element_.assign(static_cast<std::size_t>(model_.mesh().element_count()), -1);
  f.ply_area_.assign(model_.laminate().ply_count(), 0.0);
  f.bound_.assign(static_cast<std::size_t>(model_.mesh().element_count()), 0.0);
  f.u_committed_ = Eigen::VectorXd::Zero(model_.size());
  for (const Laminate& lam : model_.laminates())
    f.ply_area_.resize(std::max(f.ply_area_.size(), lam.ply_count()), 0.0);
  for (const LayeredSection& section : sections_.front())
    f.groups_ = std::max(f.groups_, section.group_count());
  return f;
}

DamagedPlate::PointStrains DamagedPlate::evaluate_element(int e, const Eigen::VectorXd& u, double dt,
                                                          DamageField& field,
                                                          std::vector<double>& group_bound) const {
  DamageField::ActiveElement& a = field.active_[static_cast<std::size_t>(field.slot_of_element_[e])];
  const LayeredSection& section = layered_section(e);
  const double Lc = characteristic_length(e);
  const ElementOperators& ops = operators_of(e);
  const SectionStiffness& undamaged = model_.section(model_.section_index(e)).stiffness;
  const ElementVector ue = model_.element_dofs(u, e);
  const std::size_t per_point = section.states_per_point();
  a.trial_dissipation = {};
  PointStrains strains;
  for (std::size_t p = 0; p < 9; ++p) {
    strains[p] = point_strain(ops, p, ue);
    const std::span<PlyDamageState> committed(a.committed.data() + p * per_point, per_point);
    const std::span<PlyDamageState> trial(a.trial.data() + p * per_point, per_point);
    if (a.pristine[p]) {
      if (section.onset_bound(strains[p].head<6>()) < 1.0) {
        // Undamaged and below every Hashin surface: the elastic section, no law call.
        if (a.trial_touched[p]) std::copy(committed.begin(), committed.end(), trial.begin());
        a.trial_touched[p] = false;
        a.pristine_trial[p] = true;
        a.sections[p] = undamaged;
        continue;
      }
      // The law integrates from the strain of the committed state: the point's strain at the last commit.
      section.set_strains(committed, point_strain(ops, p, model_.element_dofs(field.u_committed_, e)));
    }
    const LayeredSection::Increment r =
        section.advance(committed, trial, strains[p], Lc, dt, ops.w[p], a.trial_dissipation, group_bound);
    a.sections[p] = r.secant;
    a.trial_touched[p] = true;
    a.pristine_trial[p] = !r.initiated;
  }
  a.evaluated = true;
  a.has_sections = true;
  return strains;
}

void DamagedPlate::section_force(DamageField& field, std::size_t slot, const PointStrains& strains,
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
void DamagedPlate::assemble_force(const Eigen::VectorXd& u, DamageField& field, Eigen::VectorXd& f,
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

Eigen::VectorXd DamagedPlate::internal_force(const Eigen::VectorXd& u, double dt, DamageField& field) const {
  Eigen::VectorXd f(u.size());
  internal_force_into(u, dt, field, f);
  return f;
}

void DamagedPlate::internal_force_into(const Eigen::VectorXd& u, double dt, DamageField& field,
                                       Eigen::VectorXd& f) const {
  assemble_force(u, field, f, [&](std::size_t slot, std::vector<double>& group_bound) {
    return evaluate_element(field.active_[slot].element, u, dt, field, group_bound);
  });
}

DamagedPlate::PointStrains DamagedPlate::frozen_sections(DamageField& field, std::size_t slot,
                                                         const Eigen::VectorXd& u) const {
  DamageField::ActiveElement& a = field.active_[slot];
  const int e = a.element;
  const LayeredSection& section = layered_section(e);
  const std::size_t per_point = section.states_per_point();
  const ElementOperators& ops = operators_of(e);
  const ElementVector ue = model_.element_dofs(u, e);
  PointStrains strains;
  for (std::size_t p = 0; p < 9; ++p) {
    a.pristine_trial[p] = a.pristine[p];
    if (a.pristine[p]) continue; // never initiated: the undamaged section (K0 u holds it)
    strains[p] = point_strain(ops, p, ue);
    const LayeredSection::Held h =
        section.held(std::span<const PlyDamageState>(a.committed.data() + p * per_point, per_point),
                     std::span<unsigned char>(a.modes.data() + p * per_point, per_point), strains[p]);
    a.modes_changed = a.modes_changed || h.modes_changed;
    a.sections[p] = h.secant;
  }
  a.has_sections = true;
  return strains;
}

Eigen::VectorXd DamagedPlate::frozen_internal_force(const Eigen::VectorXd& u, DamageField& field) const {
  Eigen::VectorXd f(u.size());
  frozen_internal_force_into(u, field, f);
  return f;
}

void DamagedPlate::frozen_internal_force_into(const Eigen::VectorXd& u, DamageField& field,
                                              Eigen::VectorXd& f) const {
  assemble_force(u, field, f, [&](std::size_t slot, std::vector<double>& /*group_bound*/) {
    return frozen_sections(field, slot, u);
  });
  for (DamageField::ActiveElement& a : field.active_)
    field.modes_changed_ = std::exchange(a.modes_changed, false) || field.modes_changed_;
}

SparseMatrix DamagedPlate::secant_stiffness(const DamageField& field) const {
  SparseMatrix K = K0_;
  add_section_differences(K, field, nullptr);
  return K;
}

void DamagedPlate::elastic_force(const Eigen::VectorXd& u, Eigen::VectorXd& f, DamageField& field) const {
  if (von_karman_)
    von_karman_->internal_force(u, f, field.elastic_forces_);
  else
    parallel_rows_product(K0_by_rows_, u, f);
}

SparseMatrix DamagedPlate::iteration_matrix(const Eigen::VectorXd& u, const DamageField& field) const {
  if (!von_karman_) return secant_stiffness(field);
  SparseMatrix K = von_karman_->tangent_stiffness(u);
  if (K.nonZeros() != K0_.nonZeros())
    throw std::logic_error("damaged plate: the tangent does not have the model's sparsity pattern");
  add_section_differences(K, field, &u);
  return K;
}

void DamagedPlate::add_section_differences(SparseMatrix& K, const DamageField& field,
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

double DamagedPlate::element_bound(int e, const Eigen::VectorXd& u) const {
  const LayeredSection& section = layered_section(e);
  const ElementOperators& ops = operators_of(e);
  const ElementVector ue = model_.element_dofs(u, e);
  double bound = 0.0;
  for (std::size_t p = 0; p < 9; ++p)
    bound = std::max(bound, section.onset_bound(membrane_bending_strain(ops, p, ue).head<6>()));
  return bound;
}

void DamagedPlate::activate(int e, DamageField& field) const {
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

void DamagedPlate::inactive_bounds(const Eigen::VectorXd& u, DamageField& field) const {
  for_each_element(model_.mesh().element_count(), [&](int e) {
    if (field.slot_of_element_[static_cast<std::size_t>(e)] < 0)
      field.bound_[static_cast<std::size_t>(e)] = element_bound(e, u);
  });
}

int DamagedPlate::activate_bounded_above(double threshold, DamageField& field) const {
  int added = 0;
  for (int e = 0; e < model_.mesh().element_count(); ++e) // in element order: the slots' order
    if (field.slot_of_element_[static_cast<std::size_t>(e)] < 0 &&
        field.bound_[static_cast<std::size_t>(e)] >= threshold) {
      activate(e, field);
      ++added;
    }
  return added;
}

int DamagedPlate::screen(const Eigen::VectorXd& u, DamageField& field) const {
  inactive_bounds(u, field);
  return activate_bounded_above(settings_.screen_fraction, field);
}

bool DamagedPlate::activate_reached(const Eigen::VectorXd& u, DamageField& field) const {
  // One pass over the inactive elements per step: their bounds at the converged u serve commit() too.
  inactive_bounds(u, field);
  const bool reached = activate_bounded_above(1.0, field) > 0;
  field.bounds_current_ = !reached;
  return reached;
}

void DamagedPlate::commit(const Eigen::VectorXd& u, const Eigen::VectorXd& f_int, DamageField& field) const {
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

StrengthReduction DamageField::strength_reduction() const {
  return plate_->strength_reduction(*this);
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
