#include "plyimpact/fem/discrete_plate.hpp"

#include "plyimpact/fem/structured_mesh.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace plyimpact {

double PointSampler::value(const Eigen::VectorXd& u) const {
  double w = 0.0;
  for (const auto& [eq, n] : w_terms)
    w += n * u(eq);
  return w;
}

Eigen::VectorXd PointSampler::as_vector(int size) const {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(size);
  for (const auto& [eq, n] : w_terms)
    s(eq) += n;
  return s;
}

namespace {

PlateSections checked(PlateSections s, const Mesh& mesh) {
  if (s.laminates.empty()) throw std::invalid_argument("plate model: no laminate");
  if (!s.of_element.empty()) {
    if (static_cast<int>(s.of_element.size()) != mesh.element_count())
      throw std::invalid_argument("plate model: one section index per element expected");
    for (const int i : s.of_element)
      if (i < 0 || i >= static_cast<int>(s.laminates.size()))
        throw std::invalid_argument("plate model: element section index out of range");
  }
  return s;
}

} // namespace

DiscretePlate::DiscretePlate(Mesh mesh, PlateSections sections, Discretization discretization,
                             BoundaryConditions bc)
    : mesh_(std::move(mesh)), sections_(checked(std::move(sections), mesh_)), discretization_(discretization),
      bc_(std::move(bc)), dofs_(mesh_, bc_),
      element_(make_plate_element(resolve_formulation(discretization.element, mesh_, bc_))) {
  discretization_.element = element_->formulation();
  for (const Laminate& lam : sections_.laminates)
    section_data_.push_back(section_of(lam));
  for (int e = 0; e < mesh_.element_count(); ++e)
    equations_.push_back(dofs_.element_equations(mesh_, e));
  build_pattern();
}

DiscretePlate::DiscretePlate(Laminate laminate, PlateGeometry plate, MeshSpec spec, BoundaryConditions bc)
    : DiscretePlate(structured_rectangle(plate, spec.nx, spec.ny), PlateSections{{std::move(laminate)}, {}},
                    Discretization{spec.mass, spec.element}, std::move(bc)) {}

ElementFormulation resolve_formulation(ElementFormulation requested, const Mesh& /*mesh*/,
                                       const BoundaryConditions& /*bc*/) {
  // MITC9 has no spurious mode on any support; q9's mode w = c(3ξ² − 1)(3η² − 1) is held only by
  // edges with w restrained, and it softens a load on an element-corner node by 3–5 % even then
  // (docs/validation.md, mesh-objective contact). q9 stays for reproducing the thesis.
  return requested == ElementFormulation::automatic ? ElementFormulation::mitc9 : requested;
}

void DiscretePlate::build_pattern() {
  // Node adjacency (nodes sharing an element), then the CSC structure column by column. Equations
  // are numbered node by node, so the free DOFs of one node are consecutive rows.
  const int nn = mesh_.node_count();
  std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(nn));
  for (int e = 0; e < mesh_.element_count(); ++e)
    for (const int a : mesh_.element_nodes(e))
      for (const int b : mesh_.element_nodes(e))
        adjacent[static_cast<std::size_t>(a)].push_back(b);
  for (auto& adj : adjacent) {
    std::sort(adj.begin(), adj.end());
    adj.erase(std::unique(adj.begin(), adj.end()), adj.end());
  }
  first_equation_.assign(static_cast<std::size_t>(nn), -1);
  for (int n = 0; n < nn; ++n)
    for (int d = dofs_per_node - 1; d >= 0; --d)
      if (dofs_.equation(n, d) >= 0) first_equation_[static_cast<std::size_t>(n)] = dofs_.equation(n, d);

  const int neq = dofs_.free_count();
  std::vector<int> outer(static_cast<std::size_t>(neq) + 1, 0);
  std::vector<int> inner;
  for (int n = 0; n < nn; ++n)
    for (int d = 0; d < dofs_per_node; ++d) {
      const int col = dofs_.equation(n, d);
      if (col < 0) continue;
      for (const int m : adjacent[static_cast<std::size_t>(n)])
        for (int dm = 0; dm < dofs_per_node; ++dm)
          if (const int row = dofs_.equation(m, dm); row >= 0) inner.push_back(row);
      outer[static_cast<std::size_t>(col) + 1] = static_cast<int>(inner.size());
    }
  pattern_.resize(neq, neq);
  pattern_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), pattern_.innerIndexPtr());
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + inner.size(), 0.0);
}

void DiscretePlate::add_element(SparseMatrix& K, int e, const ElementMatrix& Ke) const {
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  double* values = K.valuePtr();
  const ElementNodes& conn = mesh_.element_nodes(e);
  for (int b = 0; b < 9; ++b) {
    const int nb = conn[static_cast<std::size_t>(b)];
    for (int db = 0; db < dofs_per_node; ++db) {
      const int col = dofs_.equation(nb, db);
      if (col < 0) continue;
      for (int a = 0; a < 9; ++a) {
        const int na = conn[static_cast<std::size_t>(a)];
        const int first = first_equation_[static_cast<std::size_t>(na)];
        if (first < 0) continue;
        const int* pos = std::lower_bound(inner + outer[col], inner + outer[col + 1], first);
        auto p = static_cast<std::ptrdiff_t>(pos - inner);
        for (int da = 0; da < dofs_per_node; ++da)
          if (dofs_.equation(na, da) >= 0) values[p++] += Ke(5 * a + da, 5 * b + db);
      }
    }
  }
}

SparseMatrix DiscretePlate::assemble(const ElementKernel& kernel) const {
  // Elements with equal shape and section have equal matrices: each is computed once, on the shape's
  // representative element, and kept while there are few kinds (the cache changes no number: a matrix
  // recomputed later is the same). Assembly runs in element order whatever the kinds.
  constexpr std::size_t max_cached = 256;
  std::map<std::pair<int, int>, ElementMatrix> cache;
  SparseMatrix K = pattern_;
  ElementMatrix Ke;
  std::pair<int, int> current{-1, -1};
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const std::pair<int, int> key{section_index(e), mesh_.shape_class(e)};
    if (key != current) {
      current = key;
      if (const auto it = cache.find(key); it != cache.end()) {
        Ke = it->second;
      } else {
        Ke = kernel(mesh_.representative(key.second), key.first);
        if (cache.size() < max_cached) cache.emplace(key, Ke);
      }
    }
    add_element(K, e, Ke);
  }
  return K;
}

SparseMatrix DiscretePlate::stiffness() const {
  return assemble([this](int e, int s) {
    return element_->stiffness(mesh_.element_coordinates(e), ElementSection(section(s).stiffness));
  });
}

SparseMatrix DiscretePlate::stiffness(const std::function<ElementSection(int)>& section_of_element) const {
  SparseMatrix K = pattern_;
  for (int e = 0; e < mesh_.element_count(); ++e)
    add_element(K, e, element_->stiffness(mesh_.element_coordinates(e), section_of_element(e)));
  return K;
}

SparseMatrix DiscretePlate::mass() const {
  return mass(discretization_.mass);
}

SparseMatrix DiscretePlate::mass(MassMatrix kind) const {
  return assemble([this, kind](int e, int s) {
    return PlateElement::mass(mesh_.element_coordinates(e), section(s).inertia, kind);
  });
}

SparseMatrix DiscretePlate::geometric_stiffness(const Eigen::Matrix2d& N) const {
  return assemble([this, &N](int e, int /*section*/) {
    return PlateElement::geometric_stiffness(mesh_.element_coordinates(e), N);
  });
}

PointSampler DiscretePlate::sampler(double x, double y) const {
  const auto loc = mesh_.locate(x, y);
  if (!loc)
    throw std::invalid_argument("point (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") m lies outside the plate");
  PointSampler s{*loc, {}};
  const Q9Shape sh = q9_shape(loc->xi, loc->eta);
  const ElementNodes& conn = mesh_.element_nodes(loc->element);
  for (int a = 0; a < 9; ++a) {
    const int eq = dofs_.equation(conn[static_cast<std::size_t>(a)], 2);
    if (eq >= 0 && sh.N(a) != 0.0) s.w_terms.emplace_back(eq, sh.N(a));
  }
  return s;
}

Eigen::VectorXd DiscretePlate::to_nodal(const Eigen::VectorXd& u) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(dofs_.total_count());
  for (int i = 0; i < dofs_.total_count(); ++i)
    if (const int eq = dofs_.equation(i / dofs_per_node, i % dofs_per_node); eq >= 0) full(i) = u(eq);
  return full;
}

std::vector<std::string> unrestrained_rigid_motions(const DiscretePlate& model) {
  // The six rigid motions of a Mindlin plate, as nodal fields (u, v, w, θx, θy), and the rank of their
  // values on the restrained DOFs: a combination that vanishes on every restrained DOF is free.
  static const char* names[6] = {"translation along x (u)",  "translation along y (v)",
                                 "rotation about z (u, v)",  "translation along z (w)",
                                 "rotation about y (w, θx)", "rotation about x (w, θy)"};
  const Mesh& mesh = model.mesh();
  const BoundingBox& box = mesh.bounds();
  const Eigen::Vector2d c = box.centre();
  const double lx = box.x_max - box.x_min, ly = box.y_max - box.y_min;
  Eigen::Matrix<double, 6, 6> G = Eigen::Matrix<double, 6, 6>::Zero();
  for (int n = 0; n < mesh.node_count(); ++n) {
    const double x = (mesh.node(n).x() - c.x()) / lx, y = (mesh.node(n).y() - c.y()) / ly;
    Eigen::Matrix<double, 5, 6> R = Eigen::Matrix<double, 5, 6>::Zero();
    R(0, 0) = 1;                      // u = 1
    R(1, 1) = 1;                      // v = 1
    R(0, 2) = -y, R(1, 2) = x;        // u = −y, v = x
    R(2, 3) = 1;                      // w = 1
    R(2, 4) = x, R(3, 4) = -1.0 / lx; // w = x, θx = −w,x (γxz = 0)
    R(2, 5) = y, R(4, 5) = -1.0 / ly; // w = y, θy = −w,y
    for (int d = 0; d < dofs_per_node; ++d)
      if (model.dofs().equation(n, d) < 0) G += R.row(d).transpose() * R.row(d);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(G);
  std::vector<std::string> free;
  const double scale = std::max(1.0, eig.eigenvalues().maxCoeff());
  for (int k = 0; k < 6; ++k) {
    if (eig.eigenvalues()(k) > 1e-10 * scale) continue;
    const auto v = eig.eigenvectors().col(k);
    Eigen::Index main = 0;
    v.cwiseAbs().maxCoeff(&main);
    free.emplace_back(names[main]);
  }
  return free;
}

std::vector<ElementSlots> element_slots(const DiscretePlate& model, const SparseMatrix& pattern) {
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  std::vector<ElementSlots> slots;
  slots.reserve(static_cast<std::size_t>(model.mesh().element_count()));
  for (int e = 0; e < model.mesh().element_count(); ++e) {
    const ElementEquations& eq = model.element_equations(e);
    ElementSlots slot{};
    for (int j = 0; j < q9_dofs; ++j)
      for (int i = 0; i < q9_dofs; ++i) {
        const int row = eq[static_cast<std::size_t>(i)], col = eq[static_cast<std::size_t>(j)];
        int s = -1;
        if (row >= 0 && col >= 0)
          s = static_cast<int>(std::lower_bound(inner + outer[col], inner + outer[col + 1], row) - inner);
        slot[static_cast<std::size_t>(j) * q9_dofs + static_cast<std::size_t>(i)] = s;
      }
    slots.push_back(slot);
  }
  return slots;
}

void add_element_values(double* values, const ElementSlots& slots, const ElementMatrix& Ke) {
  for (int j = 0; j < q9_dofs; ++j)
    for (int i = 0; i < q9_dofs; ++i)
      if (const int s = slots[static_cast<std::size_t>(j) * q9_dofs + static_cast<std::size_t>(i)]; s >= 0)
        values[s] += Ke(i, j);
}

} // namespace plyimpact
