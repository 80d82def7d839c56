#include "plyimpact/analysis/impact/mass_scaling.hpp"

#include "plyimpact/analysis/integrators/step_policy.hpp"
#include "plyimpact/fem/element_loop.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace plyimpact {

namespace {

bool is_rotation(int dof) {
  return dof >= 3; // θx, θy (dof_map.hpp)
}

bool in_group(int dof, DofGroup group) {
  return group == DofGroup::all || is_rotation(dof) == (group == DofGroup::rotations);
}

/// K_ii and S_i = Σ_{j≠i} |K_ij|/√m_j of every row i (K symmetric: its columns).
struct RowSums {
  Eigen::VectorXd diagonal, off_diagonal;
};

RowSums row_sums(const SparseMatrix& K, const Eigen::VectorXd& m) {
  RowSums r{Eigen::VectorXd::Zero(K.cols()), Eigen::VectorXd::Zero(K.cols())};
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      if (it.row() == col)
        r.diagonal[col] = it.value();
      else
        r.off_diagonal[col] += std::abs(it.value()) / std::sqrt(m[it.row()]);
    }
  return r;
}

/// g_i of MS1.
double gershgorin_row(const RowSums& r, const Eigen::VectorXd& m, Eigen::Index i) {
  return r.diagonal[i] / m[i] + r.off_diagonal[i] / std::sqrt(m[i]);
}

/// The mass of MS2 that brings row i's g_i to ω_t² (its neighbours' masses held).
double mass_for(const RowSums& r, Eigen::Index i, double omega_t2) {
  const double kii = r.diagonal[i], s = r.off_diagonal[i];
  const double x = 2.0 * omega_t2 / (std::sqrt(s * s + 4.0 * kii * omega_t2) + s); // 1/√m_i, MS2's root
  return 1.0 / (x * x);
}

/// MS1 over the equations of `group`, from the rows `r` of K on the mass `m`.
double gershgorin_bound(const RowSums& r, const Eigen::VectorXd& m, std::span<const EquationPlace> places,
                        DofGroup group) {
  double g = 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (in_group(places[static_cast<std::size_t>(i)].dof, group))
      g = std::max(g, gershgorin_row(r, m, i)); // MS1
  return g;
}

/// ω_t² of MS2: from the target step, or for rotary scaling without one the translations' MS1.
double target_omega_squared(const RowSums& r, const Eigen::VectorXd& m, std::span<const EquationPlace> places,
                            const MassScaling& scaling) {
  if (scaling.target_dt) {
    const double omega = stable_time_step(1.0) / *scaling.target_dt; // CD5 solved for ω
    return omega * omega;
  }
  if (scaling.kind == MassScalingKind::nodal)
    throw std::invalid_argument("time.mass_scaling = \"nodal\" adds mass up to a stable step that the deck "
                                "gives: add [time] target_dt (s)");
  return gershgorin_bound(r, m, places, DofGroup::translations);
}

/// Per node of each sub-laminate (index k · nodes + node): the largest of a quantity over its DOFs.
struct NodeTable {
  std::vector<double> translation, rotation;
  explicit NodeTable(std::size_t size) : translation(size, 0.0), rotation(size, 0.0) {}
  void raise(std::size_t slot, int dof, double value) {
    double& v = is_rotation(dof) ? rotation[slot] : translation[slot];
    v = std::max(v, value);
  }
  [[nodiscard]] double of(std::size_t slot, int dof) const {
    return is_rotation(dof) ? rotation[slot] : translation[slot];
  }
};

std::size_t slot_of(const EquationPlace& p, int nodes) {
  return static_cast<std::size_t>(p.sublaminate) * static_cast<std::size_t>(nodes) +
         static_cast<std::size_t>(p.node);
}

/// The masses per sub-laminate of `node_values` (a node's mass counted once, not per DOF).
std::vector<double> per_sublaminate(const std::vector<double>& node_values, int nodes, int sublaminates) {
  std::vector<double> out(static_cast<std::size_t>(sublaminates), 0.0);
  for (std::size_t slot = 0; slot < node_values.size(); ++slot)
    out[slot / static_cast<std::size_t>(nodes)] += node_values[slot];
  return out;
}

} // namespace

double ScaledMass::added_kinetic_energy(const Eigen::VectorXd& v) const {
  // In 2 × 64 fixed chunks on the element loops' threads (ascending equations, then ascending columns of
  // K_c/ω_c²), their sums added in chunk order: the same bits for any thread count, no vector per step.
  constexpr int chunks = fixed_blocks;
  std::array<double, 2 * chunks> partial{};
  const auto n = static_cast<Eigen::Index>(equations.size());
  for_each_element(2 * chunks, [&](int b) {
    double e = 0.0;
    if (b < chunks) {
      const IndexRange r = block_range(n, b, chunks);
      for (Eigen::Index k = r.first; k < r.last; ++k) {
        const double vk = v[equations[static_cast<std::size_t>(k)]];
        e += added[static_cast<std::size_t>(k)] * vk * vk;
      }
    } else {
      const IndexRange r = block_range(coupling.outerSize(), b - chunks, chunks);
      for (Eigen::Index col = r.first; col < r.last; ++col) // vᵀ (K_c/ω_c²) v
        for (SparseMatrix::InnerIterator it(coupling, col); it; ++it)
          e += v[it.row()] * it.value() * v[col];
    }
    partial[static_cast<std::size_t>(b)] = e;
  });
  double e = 0.0;
  for (const double p : partial)
    e += p;
  return 0.5 * e;
}

SparseMatrix ScaledMass::matrix() const {
  SparseMatrix M = MassOperator(mass).matrix();
  if (coupling.size() > 0) M += coupling;
  return M;
}

double gershgorin_bound(const SparseMatrix& K, const Eigen::VectorXd& m,
                        std::span<const EquationPlace> places, DofGroup group) {
  return gershgorin_bound(row_sums(K, m), m, places, group);
}

namespace {

/// K − K_c: the sub-laminates alone, which the rotary part of selective scaling bounds.
SparseMatrix plates_alone(const SparseMatrix& K, const MassScaling& scaling, const SparseMatrix* interfaces) {
  if (scaling.kind != MassScalingKind::selective) return K;
  if (!interfaces || interfaces->nonZeros() == 0)
    throw std::invalid_argument(
        "time.mass_scaling = \"selective\" scales the relative motion of a stack's interfaces, and this "
        "plate has none: use \"rotary\" or \"nodal\", or add [delamination]");
  SparseMatrix Kp = K - *interfaces;
  Kp.prune(0.0);
  return Kp;
}

/// MS3's K_c/ω_c² and its largest diagonal entry over the lumped mass of its DOF.
void add_interface_mass(ScaledMass& out, const SparseMatrix& interfaces, double omega_t2) {
  const double omega_c = interface_frequency_ratio * std::sqrt(omega_t2);
  out.coupling = interfaces / (omega_c * omega_c); // MS3
  out.report.interface_factor = out.coupling.diagonal().cwiseQuotient(out.mass).maxCoeff();
  try {
    out.blocks = std::make_shared<const BlockDiagonalMass>(out.matrix());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format(
        "time.mass_scaling = \"selective\" needs interfaces whose points are the nodes "
        "([delamination] points = \"nodal\", the default): the mass then couples one node's faces only ({})",
        e.what()));
  }
}

} // namespace

ScaledMass scaled_mass(const SparseMatrix& K, const Eigen::VectorXd& m, std::span<const EquationPlace> places,
                       int nodes, const MassScaling& scaling, const SparseMatrix* interfaces) {
  ScaledMass out;
  out.mass = m;
  out.report.kind = scaling.kind;
  int sublaminates = 1;
  for (const EquationPlace& p : places)
    sublaminates = std::max(sublaminates, p.sublaminate + 1);
  const std::size_t slots = static_cast<std::size_t>(sublaminates) * static_cast<std::size_t>(nodes);
  NodeTable original(slots), needed(slots);
  for (std::size_t i = 0; i < places.size(); ++i)
    original.raise(slot_of(places[i], nodes), places[i].dof, m[static_cast<Eigen::Index>(i)]);
  if (scaling.kind != MassScalingKind::none) {
    const RowSums r = row_sums(plates_alone(K, scaling, interfaces), m);
    const double omega_t2 = target_omega_squared(r, m, places, scaling);
    out.report.target_omega = std::sqrt(omega_t2);
    out.report.target_dt = stable_time_step(out.report.target_omega);
    const DofGroup group = scaling.kind == MassScalingKind::nodal ? DofGroup::all : DofGroup::rotations;
    for (std::size_t i = 0; i < places.size(); ++i) {
      const auto eq = static_cast<Eigen::Index>(i);
      if (in_group(places[i].dof, group) && gershgorin_row(r, m, eq) > omega_t2)
        needed.raise(slot_of(places[i], nodes), places[i].dof, mass_for(r, eq, omega_t2)); // MS2
    }
    for (std::size_t i = 0; i < places.size(); ++i) {
      const auto eq = static_cast<Eigen::Index>(i);
      const double target = needed.of(slot_of(places[i], nodes), places[i].dof);
      if (!(target > m[eq])) continue;
      out.mass[eq] = target;
      out.equations.push_back(static_cast<int>(i));
      out.added.push_back(target - m[eq]);
      out.report.largest_factor = std::max(out.report.largest_factor, target / m[eq]);
    }
    if (scaling.kind == MassScalingKind::selective) add_interface_mass(out, *interfaces, omega_t2);
  }
  NodeTable added(slots);
  for (std::size_t k = 0; k < out.equations.size(); ++k) {
    const EquationPlace& p = places[static_cast<std::size_t>(out.equations[k])];
    added.raise(slot_of(p, nodes), p.dof, out.added[k]);
  }
  for (std::size_t slot = 0; slot < slots; ++slot)
    if (added.translation[slot] > 0.0 || added.rotation[slot] > 0.0) ++out.report.scaled_nodes;
  out.report.mass_kg = per_sublaminate(original.translation, nodes, sublaminates);
  out.report.added_mass_kg = per_sublaminate(added.translation, nodes, sublaminates);
  out.report.rotary_inertia_kg_m2 = per_sublaminate(original.rotation, nodes, sublaminates);
  out.report.added_rotary_inertia_kg_m2 = per_sublaminate(added.rotation, nodes, sublaminates);
  return out;
}

const char* to_string(MassScalingKind kind) {
  switch (kind) {
  case MassScalingKind::none:
    return "none";
  case MassScalingKind::rotary:
    return "rotary";
  case MassScalingKind::nodal:
    return "nodal";
  case MassScalingKind::selective:
    return "selective";
  }
  return "?";
}

std::string mass_scaling_text(const MassScalingReport& r) {
  const auto sum = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); };
  const double inertia = sum(r.rotary_inertia_kg_m2), added_inertia = sum(r.added_rotary_inertia_kg_m2);
  const double mass = sum(r.mass_kg), added_mass = sum(r.added_mass_kg);
  std::string s =
      fmt::format("{} mass scaling to a stable step of {:.4g} ns: {} nodes scaled, by up to {:.3g}x",
                  to_string(r.kind), 1e9 * r.target_dt, r.scaled_nodes, r.largest_factor);
  if (added_inertia > 0.0)
    s += fmt::format("; rotary inertia +{:.4g} kg m^2 ({:.3g} % of the plate's)", added_inertia,
                     inertia > 0.0 ? 100.0 * added_inertia / inertia : 0.0);
  if (r.kind == MassScalingKind::selective)
    s += fmt::format("; interfaces: K_c/omega_c^2 (omega_c = {:.3g} omega_t) on the faces' relative motion, "
                     "up to {:.3g}x a DOF's lumped mass, none on the plate's motion",
                     interface_frequency_ratio, r.interface_factor);
  if (r.kind == MassScalingKind::nodal)
    s += fmt::format("; mass +{:.4g} kg ({:.3g} % of the plate's {:.4g} kg)", added_mass,
                     mass > 0.0 ? 100.0 * added_mass / mass : 0.0, mass);
  return s;
}

std::optional<std::string> added_mass_suspicion(const MassScalingReport& report) {
  double mass = 0.0, added = 0.0;
  for (const double m : report.mass_kg)
    mass += m;
  for (const double m : report.added_mass_kg)
    added += m;
  if (!(mass > 0.0) || !(added > added_mass_fraction_tolerance * mass)) return std::nullopt;
  return fmt::format(
      "[time] mass_scaling = \"{}\" added {:.4g} kg to a plate of {:.4g} kg ({:.3g} times its mass, more "
      "than "
      "the {:.0f} % an explicit run may add without changing the answer): the plate's modes that move its "
      "mass together fall in frequency by a factor {:.3g}, and the contact force, deflection and energies "
      "are those of a heavier plate. Give a shorter [time] target_dt (the step of the unscaled mesh is "
      "the honest one), or use mass_scaling = \"rotary\" (docs/mass_scaling.md)",
      to_string(report.kind), added, mass, added / mass, 100.0 * added_mass_fraction_tolerance,
      std::sqrt(mass / (mass + added)));
}

} // namespace plyimpact
