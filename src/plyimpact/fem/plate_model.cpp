#include "plyimpact/fem/plate_model.hpp"

#include "plyimpact/fem/quadrature.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
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

PlateModel::PlateModel(Laminate laminate, PlateGeometry plate, MeshSpec spec, BoundaryConditions bc)
    : laminate_(std::move(laminate)), mesh_(plate, spec.nx, spec.ny), spec_(spec), bc_(bc), dofs_(mesh_, bc_),
      element_(laminate_, resolve_formulation(spec.element, mesh_, bc_)) {
  spec_.element = element_.formulation();
  build_pattern();
}

ElementFormulation resolve_formulation(ElementFormulation requested, const PlateMesh& /*mesh*/,
                                       const BoundaryConditions& bc) {
  if (requested != ElementFormulation::automatic) return requested;
  // q9's spurious mode w = c(3ξ² − 1)(3η² − 1) is killed by w held along a whole edge, not by point
  // supports at element corners (docs/elements.md §4): only then is the thesis's element safe.
  for (const Restraint& edge : bc.edges)
    if (edge.fixed[2]) return ElementFormulation::q9;
  return ElementFormulation::mitc9;
}

void PlateModel::build_pattern() {
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

SparseMatrix PlateModel::assemble(const ElementKernel& kernel) const {
  SparseMatrix K = pattern_;
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  double* values = K.valuePtr();
  // A regular mesh has congruent elements: one element matrix serves all (hoisted out of the loop).
  const bool shared = mesh_.is_regular();
  const ElementMatrix Kshared = shared ? kernel(mesh_.element_coordinates(0)) : ElementMatrix::Zero();
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const ElementMatrix Ke_local = shared ? ElementMatrix::Zero() : kernel(mesh_.element_coordinates(e));
    const ElementMatrix& Ke = shared ? Kshared : Ke_local;
    const auto& conn = mesh_.element_nodes(e);
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
  return K;
}

SparseMatrix PlateModel::stiffness() const {
  return assemble([this](const ElementCoordinates& xy) { return element_.stiffness(xy); });
}

SparseMatrix PlateModel::mass() const {
  return mass(spec_.mass);
}

SparseMatrix PlateModel::mass(MassMatrix kind) const {
  return assemble([this, kind](const ElementCoordinates& xy) { return element_.mass(xy, kind); });
}

SparseMatrix PlateModel::geometric_stiffness(const Eigen::Matrix2d& N) const {
  return assemble([this, &N](const ElementCoordinates& xy) { return element_.geometric_stiffness(xy, N); });
}

PointSampler PlateModel::sampler(double x, double y) const {
  const auto loc = mesh_.locate(x, y);
  if (!loc)
    throw std::invalid_argument("point (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") m lies outside the plate");
  PointSampler s{*loc, {}};
  const Q9Shape sh = q9_shape(loc->xi, loc->eta);
  const auto& conn = mesh_.element_nodes(loc->element);
  for (int a = 0; a < 9; ++a) {
    const int eq = dofs_.equation(conn[static_cast<std::size_t>(a)], 2);
    if (eq >= 0 && sh.N(a) != 0.0) s.w_terms.emplace_back(eq, sh.N(a));
  }
  return s;
}

Eigen::VectorXd PlateModel::point_load(double x, double y, double force) const {
  return force * sampler(x, y).as_vector(size());
}

Eigen::VectorXd PlateModel::pressure_load(double q) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(size());
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const ElementVector fe = element_.pressure_load(mesh_.element_coordinates(e), q);
    const auto eq = dofs_.element_equations(mesh_, e);
    for (int i = 0; i < q9_dofs; ++i)
      if (eq[static_cast<std::size_t>(i)] >= 0) f(eq[static_cast<std::size_t>(i)]) += fe(i);
  }
  return f;
}

Eigen::VectorXd PlateModel::patch_load(const PatchLoad& patch) const {
  if (!mesh_.is_regular()) throw std::invalid_argument("patch loads need an undistorted (regular) mesh");
  const double q = patch.force / (patch.dx * patch.dy);
  const double x0 = std::max(0.0, patch.x - patch.dx / 2),
               x1 = std::min(mesh_.plate().a, patch.x + patch.dx / 2);
  const double y0 = std::max(0.0, patch.y - patch.dy / 2),
               y1 = std::min(mesh_.plate().b, patch.y + patch.dy / 2);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(size());
  for (int e = 0; e < mesh_.element_count(); ++e) {
    const ElementCoordinates xy = mesh_.element_coordinates(e);
    const double ex0 = xy(0, 0), ex1 = xy(1, 0), ey0 = xy(0, 1), ey1 = xy(3, 1);
    const double ox0 = std::max(x0, ex0), ox1 = std::min(x1, ex1), oy0 = std::max(y0, ey0),
                 oy1 = std::min(y1, ey1);
    if (ox1 <= ox0 || oy1 <= oy0) continue;
    // 3×3 Gauss over the overlap rectangle; local coordinates by the element's affine map.
    const auto conn = mesh_.element_nodes(e);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        const double x = 0.5 * (ox0 + ox1) + 0.5 * (ox1 - ox0) * gauss3.points[i];
        const double y = 0.5 * (oy0 + oy1) + 0.5 * (oy1 - oy0) * gauss3.points[j];
        const double w = gauss3.weights[i] * gauss3.weights[j] * 0.25 * (ox1 - ox0) * (oy1 - oy0);
        const Q9Shape sh = q9_shape(2 * (x - ex0) / (ex1 - ex0) - 1, 2 * (y - ey0) / (ey1 - ey0) - 1);
        for (int a = 0; a < 9; ++a)
          if (const int eq = dofs_.equation(conn[static_cast<std::size_t>(a)], 2); eq >= 0)
            f(eq) += w * q * sh.N(a);
      }
  }
  return f;
}

Eigen::VectorXd PlateModel::to_nodal(const Eigen::VectorXd& u) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(dofs_.total_count());
  for (int i = 0; i < dofs_.total_count(); ++i)
    if (const int eq = dofs_.equation(i / dofs_per_node, i % dofs_per_node); eq >= 0) full(i) = u(eq);
  return full;
}

ElementVector PlateModel::element_dofs(const Eigen::VectorXd& u, int e) const {
  ElementVector ue;
  const auto eq = dofs_.element_equations(mesh_, e);
  for (int i = 0; i < q9_dofs; ++i)
    ue(i) = eq[static_cast<std::size_t>(i)] >= 0 ? u(eq[static_cast<std::size_t>(i)]) : 0.0;
  return ue;
}

std::vector<std::string> unrestrained_rigid_motions(const PlateModel& model) {
  // The six rigid motions of a Mindlin plate, as nodal fields (u, v, w, θx, θy), and the rank of their
  // values on the restrained DOFs: a combination that vanishes on every restrained DOF is free.
  static const char* names[6] = {"translation along x (u)",  "translation along y (v)",
                                 "rotation about z (u, v)",  "translation along z (w)",
                                 "rotation about y (w, θx)", "rotation about x (w, θy)"};
  const PlateMesh& mesh = model.mesh();
  const double xc = mesh.plate().a / 2, yc = mesh.plate().b / 2;
  Eigen::Matrix<double, 6, 6> G = Eigen::Matrix<double, 6, 6>::Zero();
  for (int n = 0; n < mesh.node_count(); ++n) {
    const double x = (mesh.node(n).x() - xc) / mesh.plate().a, y = (mesh.node(n).y() - yc) / mesh.plate().b;
    Eigen::Matrix<double, 5, 6> R = Eigen::Matrix<double, 5, 6>::Zero();
    R(0, 0) = 1;                                  // u = 1
    R(1, 1) = 1;                                  // v = 1
    R(0, 2) = -y, R(1, 2) = x;                    // u = −y, v = x
    R(2, 3) = 1;                                  // w = 1
    R(2, 4) = x, R(3, 4) = -1.0 / mesh.plate().a; // w = x, θx = −w,x (γxz = 0)
    R(2, 5) = y, R(4, 5) = -1.0 / mesh.plate().b; // w = y, θy = −w,y
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

} // namespace plyimpact
