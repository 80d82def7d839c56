#include "plyimpact/fem/stacked_plate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

double slice_shear_correction(double z1, double z2, double h) {
  const auto F1 = [](double s) { return s - 4.0 * s * s * s / 3.0; };                        // ∫ f ds
  const auto F2 = [](double s) { return s - 8.0 * s * s * s / 3.0 + 3.2 * std::pow(s, 5); }; // ∫ f² ds
  const double s1 = z1 / h, s2 = z2 / h;
  const double Q = F1(s2) - F1(s1);
  return Q * Q / ((s2 - s1) * (F2(s2) - F2(s1)));
}

std::vector<int> interfaces_after_ply(const std::vector<int>& cuts) {
  std::vector<int> after;
  after.reserve(cuts.size());
  for (const int cut : cuts)
    after.push_back(cut + 1);
  return after;
}

std::vector<Laminate> split_laminate(const Laminate& laminate, const std::vector<int>& cuts,
                                     std::optional<double> shear_correction) {
  const int plies = static_cast<int>(laminate.ply_count());
  const double h = laminate.thickness();
  std::vector<Laminate> parts;
  int first = 0;
  double z_top = -0.5 * h;       // of the next part
  auto add_part = [&](int end) { // plies [first, end)
    std::vector<Ply> sub(laminate.plies().begin() + first, laminate.plies().begin() + end);
    double t = 0.0;
    for (const Ply& p : sub)
      t += p.thickness;
    const double kappa = shear_correction.value_or(slice_shear_correction(z_top, z_top + t, h) *
                                                   laminate.shear_correction() / (5.0 / 6.0));
    parts.emplace_back(laminate.materials(), std::move(sub), kappa, laminate.stiffness_model());
    z_top += t;
    first = end;
  };
  for (const int cut : cuts) {
    if (cut < first || cut > plies - 2)
      throw std::invalid_argument(
          fmt::format("delamination interface after ply {} (1-based) does not exist or is out of order: a "
                      "laminate of {} plies "
                      "has interfaces after plies 1 to {}, listed in increasing order",
                      cut + 1, plies, plies - 1));
    add_part(cut + 1);
  }
  add_part(plies);
  return parts;
}

std::vector<int> interfaces_between_orientations(const Laminate& laminate) {
  std::vector<int> cuts;
  for (std::size_t k = 0; k + 1 < laminate.ply_count(); ++k)
    if (laminate.plies()[k].angle_deg != laminate.plies()[k + 1].angle_deg)
      cuts.push_back(static_cast<int>(k));
  return cuts;
}

double turon_penalty_stiffness(const Laminate& laminate, const std::vector<int>& cuts, double alpha) {
  if (cuts.empty()) throw std::invalid_argument("turon_penalty_stiffness: no interface to tie");
  const std::vector<Laminate> parts = split_laminate(laminate, cuts);
  double K = 0.0;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const auto ply = static_cast<std::size_t>(cuts[i]);
    const double E3 = std::max(laminate.material_of(ply).E2, laminate.material_of(ply + 1).E2);
    const double t = std::min(parts[i].thickness(), parts[i + 1].thickness());
    K = std::max(K, turon_penalty_stiffness(E3, t, alpha));
  }
  return K;
}

namespace {
/// The smallest of `value` over the plies that meet at `cuts`; empty where one of them has none.
template <class Value>
std::optional<double> smallest_at_cuts(const Laminate& laminate, const std::vector<int>& cuts, Value value) {
  std::optional<double> smallest;
  for (const int cut : cuts)
    for (const auto ply : {static_cast<std::size_t>(cut), static_cast<std::size_t>(cut) + 1}) {
      const std::optional<double> v = value(laminate.material_of(ply));
      if (!v) return std::nullopt;
      smallest = std::min(smallest.value_or(*v), *v);
    }
  return smallest;
}
} // namespace

PlyInterfaceValues interface_values_from_plies(const Laminate& laminate, const std::vector<int>& cuts) {
  PlyInterfaceValues v;
  v.G_Ic = smallest_at_cuts(laminate, cuts, [](const Material& m) { return m.toughness.G_mt; });
  v.G_IIc = smallest_at_cuts(laminate, cuts, [](const Material& m) { return m.toughness.G_mc; });
  v.normal_strength = smallest_at_cuts(laminate, cuts, [](const Material& m) { return m.strength.Yt; });
  return v;
}

double turon_shear_strength(double normal_strength, double G_Ic, double G_IIc) {
  return normal_strength * std::sqrt(G_IIc / G_Ic);
}

StackedPlate::StackedPlate(const Mesh& mesh, const Laminate& laminate, const StackSettings& stack,
                           Discretization discretization,
                           const std::function<BoundaryConditions(int sublaminate)>& bc_of)
    : seed_radius_(stack.seed_radius), seed_centre_(stack.seed_x, stack.seed_y) {
  const std::vector<Laminate> parts = split_laminate(laminate, stack.cuts, stack.shear_correction);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const int kk = static_cast<int>(k);
    plates_.push_back(
        std::make_unique<DiscretePlate>(mesh, PlateSections{{parts[k]}, {}}, discretization, bc_of(kk)));
    offset_.push_back(size_);
    size_ += plates_.back()->size();
  }
  const CohesiveLaw law(stack.interface);
  for (std::size_t i = 0; i + 1 < plates_.size(); ++i)
    interfaces_.push_back(std::make_unique<CohesiveInterface>(
        *plates_[i], *plates_[i + 1], offset_[i], offset_[i + 1], law, stack.rule, stack.loading_band));
  K_plates_ = block_diagonal([](const DiscretePlate& plate) { return plate.stiffness(); });
}

SparseMatrix StackedPlate::block_diagonal(const std::function<SparseMatrix(const DiscretePlate&)>& of) const {
  // The sub-laminates' equations follow one another (offset_[k + 1] = offset_[k] + size of k), so the
  // compressed columns of the blocks, shifted, are the columns of the whole: copied in order, with no
  // triplets to sort and sum (the same entries, explicit zeros included, as setFromTriplets gave).
  std::vector<SparseMatrix> blocks;
  blocks.reserve(plates_.size());
  Eigen::Index nonzeros = 0;
  for (const auto& plate : plates_) {
    blocks.push_back(of(*plate));
    blocks.back().makeCompressed();
    nonzeros += blocks.back().nonZeros();
  }
  SparseMatrix out(size_, size_);
  out.resizeNonZeros(nonzeros);
  int* const outer = out.outerIndexPtr();
  int* const inner = out.innerIndexPtr();
  double* const values = out.valuePtr();
  outer[0] = 0;
  int at = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const SparseMatrix& A = blocks[k];
    for (int c = 0; c < A.outerSize(); ++c) {
      for (SparseMatrix::InnerIterator it(A, c); it; ++it, ++at) {
        inner[at] = offset_[k] + static_cast<int>(it.row());
        values[at] = it.value();
      }
      outer[offset_[k] + c + 1] = at;
    }
  }
  return out;
}

SparseMatrix StackedPlate::mass() const {
  return block_diagonal([](const DiscretePlate& plate) { return plate.mass(); });
}

StackedPlateState StackedPlate::virgin_state() const {
  StackedPlateState state;
  for (const auto& i : interfaces_)
    state.interfaces.emplace_back(static_cast<std::size_t>(i->point_count()));
  return state;
}

StackedPlateState StackedPlate::initial_state() const {
  StackedPlateState state = virgin_state();
  if (seed_radius_ <= 0.0) return state;
  for (int i = 0; i < interface_count(); ++i)
    crack(state, i, [this](const Eigen::Vector2d& p) { return (p - seed_centre_).norm() < seed_radius_; });
  return state;
}

void StackedPlate::crack(StackedPlateState& state, int i,
                         const std::function<bool(const Eigen::Vector2d&)>& cracked) const {
  const CohesiveInterface& face = interface(i);
  auto& points = state.interfaces[static_cast<std::size_t>(i)];
  for (int p = 0; p < face.point_count(); ++p)
    if (cracked(face.point_position(p))) points[static_cast<std::size_t>(p)].damage = 1.0;
}

StackedPlateEvaluation StackedPlate::assemble(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                              std::vector<Eigen::Triplet<double>>* tangent,
                                              CohesiveDamage damage) const {
  StackedPlateEvaluation out;
  out.force = K_plates_ * u;
  CohesiveWorkspace work;
  out.dissipated = add_interfaces(u, committed, out.force, out.trial, tangent, damage, work);
  return out;
}

double StackedPlate::add_interfaces(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                    Eigen::VectorXd& force, StackedPlateState& trial,
                                    std::vector<Eigen::Triplet<double>>* tangent, CohesiveDamage damage,
                                    CohesiveWorkspace& work) const {
  trial.interfaces.resize(interfaces_.size());
  double dissipated = 0.0;
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    dissipated += interfaces_[i]->assemble_into(u, committed.interfaces[i], force, tangent, damage,
                                                trial.interfaces[i], work);
  }
  return dissipated;
}

StackedPlateEvaluation StackedPlate::evaluate(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                              CohesiveDamage damage) const {
  std::vector<Eigen::Triplet<double>> triplets;
  StackedPlateEvaluation out = assemble(u, committed, &triplets, damage);
  SparseMatrix K_coh(size_, size_);
  K_coh.setFromTriplets(triplets.begin(), triplets.end());
  out.tangent = K_plates_ + K_coh;
  return out;
}

StackedPlateEvaluation StackedPlate::internal_force(const Eigen::VectorXd& u,
                                                    const StackedPlateState& committed,
                                                    CohesiveDamage damage) const {
  return assemble(u, committed, nullptr, damage);
}

double StackedPlate::stored_energy(const Eigen::VectorXd& u, const StackedPlateState& state) const {
  Eigen::VectorXd scratch;
  return stored_energy(u, state, scratch);
}

double StackedPlate::stored_energy(const Eigen::VectorXd& u, const StackedPlateState& state,
                                   Eigen::VectorXd& scratch) const {
  scratch.noalias() = K_plates_ * u;
  return 0.5 * u.dot(scratch) + interface_energy(u, state);
}

double StackedPlate::interface_energy(const Eigen::VectorXd& u, const StackedPlateState& state) const {
  CohesiveWorkspace work;
  return interface_energy(u, state, work);
}

double StackedPlate::interface_energy(const Eigen::VectorXd& u, const StackedPlateState& state,
                                      CohesiveWorkspace& work) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
    energy += interfaces_[i]->stored_energy(u, state.interfaces[i], work);
  return energy;
}

double StackedPlate::add_interface_forces(const Eigen::VectorXd& u, const StackedPlateState& committed,
                                          Eigen::VectorXd& force, StackedPlateState& trial,
                                          CohesiveDamage damage, CohesiveWorkspace& work) const {
  return add_interfaces(u, committed, force, trial, nullptr, damage, work);
}

int StackedPlate::equation(int k, int node, int dof) const {
  const int eq = sublaminate(k).dofs().equation(node, dof);
  return eq < 0 ? -1 : offset(k) + eq;
}

} // namespace plyimpact
