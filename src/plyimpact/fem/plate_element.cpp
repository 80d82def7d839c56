#include "plyimpact/fem/plate_element.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

PointKinematics point_kinematics(const ElementCoordinates& xy, double xi, double eta) {
  PointKinematics k;
  k.shape = q9_shape(xi, eta);
  Eigen::Matrix2d J; // (2.78): rows ∂/∂ξ, ∂/∂η; columns x, y
  J.row(0) = k.shape.dN_dxi.transpose() * xy;
  J.row(1) = k.shape.dN_deta.transpose() * xy;
  k.detJ = J.determinant();
  if (!(k.detJ > 0.0)) throw std::domain_error("plate element is inverted or degenerate (det J <= 0)");
  const Eigen::Matrix2d Jinv = J.inverse(); // (2.80)–(2.82)
  k.dN_dx = Jinv(0, 0) * k.shape.dN_dxi + Jinv(0, 1) * k.shape.dN_deta;
  k.dN_dy = Jinv(1, 0) * k.shape.dN_dxi + Jinv(1, 1) * k.shape.dN_deta;
  return k;
}

MembraneBendingB membrane_bending_B(const PointKinematics& k) {
  MembraneBendingB B = MembraneBendingB::Zero();
  for (int a = 0; a < 9; ++a) {
    const int c = 5 * a;
    const double Nx = k.dN_dx(a), Ny = k.dN_dy(a);
    B(0, c + 0) = Nx; // εx = u,x
    B(1, c + 1) = Ny; // εy = v,y
    B(2, c + 0) = Ny; // γxy = u,y + v,x
    B(2, c + 1) = Nx;
    B(3, c + 3) = Nx; // κx = θx,x
    B(4, c + 4) = Ny; // κy = θy,y   ((2.74) prints N,x: misprint, SPEC §3)
    B(5, c + 3) = Ny; // κxy = θx,y + θy,x
    B(5, c + 4) = Nx;
  }
  return B;
}

ShearB shear_B(const PointKinematics& k) {
  ShearB B = ShearB::Zero();
  for (int a = 0; a < 9; ++a) {
    const int c = 5 * a;
    B(0, c + 2) = k.dN_dy(a); // γyz = θy + w,y
    B(0, c + 4) = k.shape.N(a);
    B(1, c + 2) = k.dN_dx(a); // γxz = θx + w,x
    B(1, c + 3) = k.shape.N(a);
  }
  return B;
}

// --- common to the formulations -------------------------------------------------------------------

StrainOperator PlateElement::strain_operator(const ElementCoordinates& xy, double xi, double eta) const {
  StrainOperator S;
  S.topRows<6>() = membrane_bending_B(point_kinematics(xy, xi, eta));
  S.bottomRows<2>() = shear_operator(xy, xi, eta);
  return S;
}

GeneralizedStrains PlateElement::strains(const ElementCoordinates& xy, const ElementVector& ue, double xi,
                                         double eta) const {
  const PointKinematics k = point_kinematics(xy, xi, eta);
  const Eigen::Matrix<double, 6, 1> mb = membrane_bending_B(k) * ue;
  const Eigen::Vector2d g = shear_operator(xy, xi, eta) * ue;
  return {mb.head<3>(), mb.tail<3>(), g};
}

namespace {

/// m̄ of (2.108) on (u, v, w, θx, θy).
Eigen::Matrix<double, 5, 5> inertia_matrix(const std::array<double, 3>& I) {
  Eigen::Matrix<double, 5, 5> m = Eigen::Matrix<double, 5, 5>::Zero();
  m(0, 0) = m(1, 1) = m(2, 2) = I[0];
  m(0, 3) = m(3, 0) = m(1, 4) = m(4, 1) = I[1];
  m(3, 3) = m(4, 4) = I[2];
  return m;
}

/// K += ∫ B_mbᵀ C B_mb dA (membrane, coupling, bending; 3×3 Gauss), point p's section C.
void add_membrane_bending(ElementMatrix& K, const PointKinematics& k, double w,
                          const Eigen::Matrix<double, 6, 6>& C) {
  const MembraneBendingB B = membrane_bending_B(k);
  K.noalias() += w * B.transpose() * C * B; // (2.98)
}

} // namespace

ElementMatrix PlateElement::mass(const ElementCoordinates& xy, const std::array<double, 3>& inertia,
                                 MassMatrix kind) {
  const Eigen::Matrix<double, 5, 5> mbar = inertia_matrix(inertia);
  ElementMatrix M = ElementMatrix::Zero();
  if (kind == MassMatrix::lumped) {
    // 3-point Lobatto in each direction: the quadrature points are the nodes, so Nᵀ m̄ N only
    // touches the node's own 5×5 block (diagonal when I1 = 0) (3.7)/(3.8).
    for (int a = 0; a < 9; ++a) {
      const auto& c = q9_node_coordinates[static_cast<std::size_t>(a)];
      const auto wi = lobatto3.weights[static_cast<std::size_t>(c[0] + 1.0)];
      const auto wj = lobatto3.weights[static_cast<std::size_t>(c[1] + 1.0)];
      const PointKinematics k = point_kinematics(xy, c[0], c[1]);
      M.block<5, 5>(5 * a, 5 * a) = wi * wj * k.detJ * mbar;
    }
    return M;
  }
  for (const QuadraturePoint& p : gauss3x3) {
    const PointKinematics k = point_kinematics(xy, p.xi, p.eta);
    const double w = p.weight * k.detJ;
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b)
        M.block<5, 5>(5 * a, 5 * b) += (w * k.shape.N(a) * k.shape.N(b)) * mbar;
  }
  return M;
}

ElementMatrix PlateElement::geometric_stiffness(const ElementCoordinates& xy, const Eigen::Matrix2d& N) {
  ElementMatrix Kg = ElementMatrix::Zero();
  for (const QuadraturePoint& p : gauss3x3) {
    const PointKinematics k = point_kinematics(xy, p.xi, p.eta);
    const double w = p.weight * k.detJ;
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b) {
        const Eigen::Vector2d ga(k.dN_dx(a), k.dN_dy(a));
        const Eigen::Vector2d gb(k.dN_dx(b), k.dN_dy(b));
        Kg(5 * a + 2, 5 * b + 2) += w * ga.dot(N * gb);
      }
  }
  return Kg;
}

ElementVector PlateElement::pressure_load(const ElementCoordinates& xy, double q) {
  ElementVector f = ElementVector::Zero();
  for (const QuadraturePoint& p : gauss3x3) {
    const PointKinematics k = point_kinematics(xy, p.xi, p.eta);
    const double w = p.weight * k.detJ;
    for (int a = 0; a < 9; ++a)
      f(5 * a + 2) += w * q * k.shape.N(a);
  }
  return f;
}

// --- q9: selective integration ----------------------------------------------------------------------

namespace {

/// K += ∫ B_sᵀ F B_s dA with the Lagrange shear strains, reduced 2×2 Gauss integration (thesis).
void add_reduced_shear(ElementMatrix& K, const ElementCoordinates& xy, const Eigen::Matrix2d& F) {
  for (const QuadraturePoint& p : gauss2x2) {
    const PointKinematics k = point_kinematics(xy, p.xi, p.eta);
    const ShearB Bs = shear_B(k);
    K.noalias() += (p.weight * k.detJ) * Bs.transpose() * F * Bs;
  }
}

} // namespace

ElementMatrix SelectiveQ9::stiffness(const ElementCoordinates& xy, const ElementSection& s) const {
  ElementMatrix K = ElementMatrix::Zero();
  for (std::size_t p = 0; p < gauss3x3.size(); ++p) {
    const PointKinematics k = point_kinematics(xy, gauss3x3[p].xi, gauss3x3[p].eta);
    add_membrane_bending(K, k, gauss3x3[p].weight * k.detJ, s.at(p).C_mb);
  }
  add_reduced_shear(K, xy, s.shear_for_other_rules());
  return K;
}

ElementMatrix SelectiveQ9::shear_stiffness(const ElementCoordinates& xy, const Eigen::Matrix2d& F) const {
  ElementMatrix K = ElementMatrix::Zero();
  add_reduced_shear(K, xy, F);
  return K;
}

ShearB SelectiveQ9::shear_operator(const ElementCoordinates& xy, double xi, double eta) const {
  return shear_B(point_kinematics(xy, xi, eta));
}

// --- MITC9 --------------------------------------------------------------------------------------------

namespace {

/// MITC9 tying points (Bucalem & Bathe 1993): a = 1/√3 (linear direction), b = √(3/5) (quadratic).
constexpr double tie_a = 0.57735026918962576451;
constexpr double tie_b = 0.77459666924148337704;

double linear_through_pm_a(int i, double s) {
  return 0.5 * (1.0 + (i == 0 ? -s : s) / tie_a);
}

double quadratic_through_b(int j, double s) {
  switch (j) {
  case 0:
    return s * (s - tie_b) / (2.0 * tie_b * tie_b);
  case 1:
    return 1.0 - s * s / (tie_b * tie_b);
  default:
    return s * (s + tie_b) / (2.0 * tie_b * tie_b);
  }
}

constexpr double linear_points[2] = {-tie_a, tie_a};
constexpr double quadratic_points[3] = {-tie_b, 0.0, tie_b};

Eigen::Matrix2d jacobian(const ElementCoordinates& xy, const Q9Shape& s) {
  Eigen::Matrix2d J;
  J.row(0) = s.dN_dxi.transpose() * xy;
  J.row(1) = s.dN_deta.transpose() * xy;
  return J;
}

} // namespace

ShearB Mitc9::shear_operator(const ElementCoordinates& xy, double xi, double eta) const {
  // Covariant shear strains e_ξ = x,ξ γxz + y,ξ γyz and e_η = x,η γxz + y,η γyz are sampled at the
  // tying points and interpolated; Cartesian strains follow from [γxz; γyz] = J⁻¹ [ẽ_ξ; ẽ_η].
  Eigen::Matrix<double, 1, q9_dofs> e_xi = Eigen::Matrix<double, 1, q9_dofs>::Zero();
  Eigen::Matrix<double, 1, q9_dofs> e_eta = Eigen::Matrix<double, 1, q9_dofs>::Zero();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) {
      // ẽ_ξ: linear in ξ through ±a, quadratic in η through −b, 0, b.
      const double r = linear_points[i], s = quadratic_points[j];
      const PointKinematics k = point_kinematics(xy, r, s);
      const Eigen::Matrix2d J = jacobian(xy, k.shape);
      const ShearB Bc = shear_B(k);
      e_xi += linear_through_pm_a(i, xi) * quadratic_through_b(j, eta) *
              (J(0, 0) * Bc.row(1) + J(0, 1) * Bc.row(0));
      // ẽ_η: quadratic in ξ through −b, 0, b, linear in η through ±a.
      const PointKinematics k2 = point_kinematics(xy, s, r);
      const Eigen::Matrix2d J2 = jacobian(xy, k2.shape);
      const ShearB Bc2 = shear_B(k2);
      e_eta += quadratic_through_b(j, xi) * linear_through_pm_a(i, eta) *
               (J2(1, 0) * Bc2.row(1) + J2(1, 1) * Bc2.row(0));
    }
  const Eigen::Matrix2d Jinv = jacobian(xy, q9_shape(xi, eta)).inverse();
  ShearB B;
  const Eigen::Matrix<double, 1, q9_dofs> gxz = Jinv(0, 0) * e_xi + Jinv(0, 1) * e_eta;
  const Eigen::Matrix<double, 1, q9_dofs> gyz = Jinv(1, 0) * e_xi + Jinv(1, 1) * e_eta;
  B.row(0) = gyz;
  B.row(1) = gxz;
  return B;
}

ElementMatrix Mitc9::stiffness(const ElementCoordinates& xy, const ElementSection& s) const {
  ElementMatrix K = ElementMatrix::Zero();
  for (std::size_t p = 0; p < gauss3x3.size(); ++p) {
    const QuadraturePoint& q = gauss3x3[p];
    const PointKinematics k = point_kinematics(xy, q.xi, q.eta);
    const double w = q.weight * k.detJ;
    add_membrane_bending(K, k, w, s.at(p).C_mb);
    const ShearB Bs = shear_operator(xy, q.xi, q.eta);
    K.noalias() += w * Bs.transpose() * s.at(p).F * Bs;
  }
  return K;
}

ElementMatrix Mitc9::shear_stiffness(const ElementCoordinates& xy, const Eigen::Matrix2d& F) const {
  ElementMatrix K = ElementMatrix::Zero();
  for (const QuadraturePoint& q : gauss3x3) {
    const PointKinematics k = point_kinematics(xy, q.xi, q.eta);
    const ShearB Bs = shear_operator(xy, q.xi, q.eta);
    K.noalias() += (q.weight * k.detJ) * Bs.transpose() * F * Bs;
  }
  return K;
}

std::unique_ptr<PlateElement> make_plate_element(ElementFormulation formulation) {
  if (formulation == ElementFormulation::mitc9) return std::make_unique<Mitc9>();
  return std::make_unique<SelectiveQ9>();
}

} // namespace plyimpact
