#include "plyimpact/fem/nonlinear_plate_element.hpp"

#include "plyimpact/fem/quadrature.hpp"

#include <span>
#include <stdexcept>
#include <utility>

namespace plyimpact {

std::string to_string(StrainMeasure m) {
  return m == StrainMeasure::von_karman ? "von-karman" : "green-lagrange";
}

namespace {

constexpr int n_gradients = 12; // g, see the header
constexpr int n_strains = 8;    // e = (εx, εy, γxy, κx, κy, κxy, γyz, γxz)
using Gradients = Eigen::Matrix<double, n_gradients, 1>;
using Strains = Eigen::Matrix<double, n_strains, 1>;
using StrainJacobian = Eigen::Matrix<double, n_strains, n_gradients>; // E = ∂e/∂g
using GradientOperator = Eigen::Matrix<double, n_gradients, q9_dofs>; // G

// Gradient indices.
enum : int { ux, uy, vx, vy, wx, wy, tx_x, tx_y, ty_x, ty_y, tx, ty };
// Strain indices.
enum : int { ex, ey, gxy, kx, ky, kxy, gyz, gxz };

/// One term c·g_a·g_b of a non-linear strain component (c = ½ on squares).
struct QuadraticTerm {
  int strain, a, b;
  double c;
};

// von Kármán: only the slopes of w enter the membrane strains.
constexpr std::array<QuadraticTerm, 3> von_karman_terms{
    {{ex, wx, wx, 0.5}, {ey, wy, wy, 0.5}, {gxy, wx, wy, 1.0}}};

// Green–Lagrange (2.53)–(2.55).
constexpr std::array<QuadraticTerm, 21> green_lagrange_terms{{
    {ex, ux, ux, 0.5},    {ex, vx, vx, 0.5},    {ex, wx, wx, 0.5},    // (2.53)
    {ey, uy, uy, 0.5},    {ey, vy, vy, 0.5},    {ey, wy, wy, 0.5},    //
    {gxy, ux, uy, 1.0},   {gxy, vx, vy, 1.0},   {gxy, wx, wy, 1.0},   //
    {kx, tx_x, ux, 1.0},  {kx, ty_x, vx, 1.0},                        // (2.54)
    {ky, tx_y, uy, 1.0},  {ky, ty_y, vy, 1.0},                        //
    {kxy, tx_y, ux, 1.0}, {kxy, tx_x, uy, 1.0}, {kxy, ty_y, vx, 1.0}, //
    {kxy, ty_x, vy, 1.0},                                             //
    {gyz, tx, uy, 1.0},   {gyz, ty, vy, 1.0},                         // (2.55)
    {gxz, tx, ux, 1.0},   {gxz, ty, vx, 1.0},                         //
}};

std::span<const QuadraticTerm> terms_of(StrainMeasure m) {
  if (m == StrainMeasure::von_karman) return von_karman_terms;
  return green_lagrange_terms;
}

/// Element DOFs as a 5×9 matrix: column a holds node a's (u, v, w, θx, θy).
using NodalMatrix = Eigen::Matrix<double, dofs_per_node, 9>;

/// g = G uₑ at a point, as three small matrix–vector products over the nodes.
Gradients gradients(const IntegrationPoint& p, const ElementVector& ue) {
  const Eigen::Map<const NodalMatrix> U(ue.data());
  const Eigen::Matrix<double, 5, 1> dx = U * p.dN_dx, dy = U * p.dN_dy, at = U * p.N;
  Gradients g;
  g << dx(0), dy(0), dx(1), dy(1), dx(2), dy(2), dx(3), dy(3), dx(4), dy(4), at(3), at(4);
  return g;
}

/// G as a dense matrix (tangent assembly).
GradientOperator gradient_operator(const IntegrationPoint& p) {
  GradientOperator G = GradientOperator::Zero();
  for (int a = 0; a < 9; ++a) {
    const int c = 5 * a;
    G(ux, c) = p.dN_dx(a), G(uy, c) = p.dN_dy(a);
    G(vx, c + 1) = p.dN_dx(a), G(vy, c + 1) = p.dN_dy(a);
    G(wx, c + 2) = p.dN_dx(a), G(wy, c + 2) = p.dN_dy(a);
    G(tx_x, c + 3) = p.dN_dx(a), G(tx_y, c + 3) = p.dN_dy(a), G(tx, c + 3) = p.N(a);
    G(ty_x, c + 4) = p.dN_dx(a), G(ty_y, c + 4) = p.dN_dy(a), G(ty, c + 4) = p.N(a);
  }
  return G;
}

/// e(g) and E = ∂e/∂g: linear part L (2.49)–(2.51) plus the quadratic terms.
struct StrainState {
  Strains e;
  StrainJacobian E;
};

StrainState strain_state(const Gradients& g, std::span<const QuadraticTerm> terms) {
  StrainState s;
  s.e << g(ux), g(vy), g(uy) + g(vx), g(tx_x), g(ty_y), g(tx_y) + g(ty_x), g(ty) + g(wy), g(tx) + g(wx);
  s.E.setZero();
  s.E(ex, ux) = 1, s.E(ey, vy) = 1, s.E(gxy, uy) = 1, s.E(gxy, vx) = 1;
  s.E(kx, tx_x) = 1, s.E(ky, ty_y) = 1, s.E(kxy, tx_y) = 1, s.E(kxy, ty_x) = 1;
  s.E(gyz, ty) = 1, s.E(gyz, wy) = 1, s.E(gxz, tx) = 1, s.E(gxz, wx) = 1;
  for (const QuadraticTerm& t : terms) {
    s.e(t.strain) += t.c * g(t.a) * g(t.b);
    s.E(t.strain, t.a) += t.c * g(t.b);
    s.E(t.strain, t.b) += t.c * g(t.a);
  }
  return s;
}

// The force path runs once per element and Gauss point in every Newton iteration, so its quadratic
// terms are expanded at compile time (a fold over the constant term table: no loop, constant
// indices) and restricted to the strain rows [First, Last) integrated at the point.

/// e(g) (the force path): L g plus the quadratic terms of rows [First, Last).
template <const auto& Terms, int First, int Last>
Strains strains_of(const Gradients& g) {
  Strains e;
  e << g(ux), g(vy), g(uy) + g(vx), g(tx_x), g(ty_y), g(tx_y) + g(ty_x), g(ty) + g(wy), g(tx) + g(wx);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((Terms[I].strain >= First && Terms[I].strain < Last
          ? void(e(Terms[I].strain) += Terms[I].c * g(Terms[I].a) * g(Terms[I].b))
          : void()),
     ...);
  }
  (std::make_index_sequence<Terms.size()>{});
  return e;
}

/// r = Eᵀ S without forming E (S holds the resultants of the strain rows [First, Last), zero
/// elsewhere): the linear map Lᵀ S plus, per quadratic term of those rows, S_i ∂e_i/∂g.
template <const auto& Terms, int First, int Last>
Gradients conjugate_stress(const Gradients& g, const Strains& S) {
  Gradients r;
  r(ux) = S(ex), r(vy) = S(ey), r(uy) = S(gxy), r(vx) = S(gxy);
  r(tx_x) = S(kx), r(ty_y) = S(ky), r(tx_y) = S(kxy), r(ty_x) = S(kxy);
  r(ty) = S(gyz), r(wy) = S(gyz), r(tx) = S(gxz), r(wx) = S(gxz);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((Terms[I].strain >= First && Terms[I].strain < Last
          ? void((r(Terms[I].a) += Terms[I].c * S(Terms[I].strain) * g(Terms[I].b),
                  r(Terms[I].b) += Terms[I].c * S(Terms[I].strain) * g(Terms[I].a)))
          : void()),
     ...);
  }
  (std::make_index_sequence<Terms.size()>{});
  return r;
}

/// Σ_i S_i H_i over the strain rows [first, first + count) (H_i = ∂²e_i/∂g²).
Eigen::Matrix<double, n_gradients, n_gradients>
stress_hessian(std::span<const QuadraticTerm> terms, int first, int count, const Eigen::VectorXd& S) {
  Eigen::Matrix<double, n_gradients, n_gradients> H = Eigen::Matrix<double, n_gradients, n_gradients>::Zero();
  for (const QuadraticTerm& t : terms) {
    if (t.strain < first || t.strain >= first + count) continue;
    const double s = S(t.strain - first) * t.c;
    H(t.a, t.b) += s;
    H(t.b, t.a) += s;
  }
  return H;
}

/// K_s without its rows and columns of u and v, which must be zero.
Eigen::Matrix<double, 27, 27, Eigen::RowMajor> compact_shear(const ElementMatrix& Ks) {
  Eigen::Matrix<double, 27, 27, Eigen::RowMajor> K;
  for (Eigen::Index i = 0; i < 27; ++i)
    for (Eigen::Index j = 0; j < 27; ++j)
      K(i, j) = Ks(transverse_dof(i), transverse_dof(j));
  for (Eigen::Index i = 0; i < Ks.rows(); ++i)
    for (Eigen::Index j = 0; j < Ks.cols(); ++j)
      if ((i % 5 < 2 || j % 5 < 2) && Ks(i, j) != 0.0)
        throw std::logic_error("MITC9 shear stiffness with terms on the in-plane displacements");
  return K;
}

/// f += K_s uₑ from the compact K_s: per row the same products, added in the same (ascending column)
/// order as the full 45 × 45 product, so the result is the same to the last bit.
void add_shear_force(const Eigen::Matrix<double, 27, 27, Eigen::RowMajor>& K, const ElementVector& ue,
                     ElementVector& f) {
  Eigen::Matrix<double, 27, 1> x;
  for (Eigen::Index j = 0; j < 27; ++j)
    x(j) = ue(transverse_dof(j));
  for (Eigen::Index i = 0; i < 27; ++i) {
    double sum = 0.0;
    for (Eigen::Index j = 0; j < 27; ++j)
      sum += K(i, j) * x(j);
    f(transverse_dof(i)) += sum;
  }
}

IntegrationPoint integration_point(const ElementCoordinates& xy, double xi, double eta, double w) {
  const PointKinematics k = point_kinematics(xy, xi, eta);
  return {k.shape.N, k.dN_dx, k.dN_dy, w * k.detJ};
}

} // namespace

NonlinearMindlinQ9::NonlinearMindlinQ9(const PlateElement& linear, StrainMeasure measure)
    : linear_(linear), measure_(measure) {
  if (measure_ == StrainMeasure::green_lagrange && formulation() == ElementFormulation::mitc9)
    throw std::invalid_argument(
        "the Green-Lagrange strain measure is available with the q9 element only (its transverse-shear terms "
        "(2.55) have no MITC9 interpolation): set [mesh] element = \"q9\" or use strain_measure = "
        "\"von-karman\"");
}

ElementGeometry NonlinearMindlinQ9::geometry(const ElementCoordinates& xy,
                                             const SectionStiffness& section) const {
  ElementGeometry geo;
  for (std::size_t p = 0; p < gauss3x3.size(); ++p)
    geo.membrane_bending[p] = integration_point(xy, gauss3x3[p].xi, gauss3x3[p].eta, gauss3x3[p].weight);
  for (std::size_t p = 0; p < gauss2x2.size(); ++p)
    geo.shear[p] = integration_point(xy, gauss2x2[p].xi, gauss2x2[p].eta, gauss2x2[p].weight);
  geo.shear_stiffness = formulation() == ElementFormulation::mitc9 ? linear_.shear_stiffness(xy, section.F)
                                                                   : ElementMatrix(ElementMatrix::Zero());
  geo.shear_stiffness_wt = compact_shear(geo.shear_stiffness);
  for (int q = 0; q < 9; ++q) {
    geo.mb_dN_dx.col(q) = geo.membrane_bending[static_cast<std::size_t>(q)].dN_dx;
    geo.mb_dN_dy.col(q) = geo.membrane_bending[static_cast<std::size_t>(q)].dN_dy;
  }
  for (int q = 0; q < 4; ++q) {
    geo.s_dN_dx.col(q) = geo.shear[static_cast<std::size_t>(q)].dN_dx;
    geo.s_dN_dy.col(q) = geo.shear[static_cast<std::size_t>(q)].dN_dy;
    geo.s_N.col(q) = geo.shear[static_cast<std::size_t>(q)].N;
  }
  return geo;
}

namespace {

/// f = ∫ Gᵀ Eᵀ S dA for one strain measure's terms (see NonlinearMindlinQ9::internal_force).
template <const auto& Terms>
ElementVector internal_force_with(const ElementGeometry& geo, const ElementVector& ue,
                                  const Eigen::Matrix<double, 6, 6>& C_mb, const Eigen::Matrix2d& F_s,
                                  bool mitc9) {
  // f = Σ_points w Gᵀ Eᵀ S, with G uₑ and Gᵀ r taken for all points of a rule at once. At a
  // membrane–bending point the rotations themselves (θx, θy) enter no strain row integrated there (they
  // appear in γyz, γxz only), and at a transverse-shear point the rotation gradients enter no shear
  // row: the first needs the x and y derivatives of the five fields, the second the derivatives of u,
  // v, w and the values of θx, θy. The entries not computed are zero, and so are their conjugates.
  const Eigen::Map<const NodalMatrix> U(ue.data());
  ElementVector f = ElementVector::Zero();
  Eigen::Map<NodalMatrix> F(f.data());
  {
    const NodalMatrix dx = U.lazyProduct(geo.mb_dN_dx), dy = U.lazyProduct(geo.mb_dN_dy); // column q: point q
    NodalMatrix rx, ry;
    for (int q = 0; q < 9; ++q) {
      Gradients g;
      g << dx(0, q), dy(0, q), dx(1, q), dy(1, q), dx(2, q), dy(2, q), dx(3, q), dy(3, q), dx(4, q), dy(4, q),
          0.0, 0.0;
      const Strains e = strains_of<Terms, ex, gyz>(g);
      Strains S = Strains::Zero();
      S.head<6>() = C_mb * e.head<6>(); // (N, M) (1.24)
      const Gradients r =
          geo.membrane_bending[static_cast<std::size_t>(q)].weight * conjugate_stress<Terms, ex, gyz>(g, S);
      rx.col(q) << r(ux), r(vx), r(wx), r(tx_x), r(ty_x);
      ry.col(q) << r(uy), r(vy), r(wy), r(tx_y), r(ty_y);
    }
    F.noalias() += rx.lazyProduct(geo.mb_dN_dx.transpose()) + ry.lazyProduct(geo.mb_dN_dy.transpose());
  }
  if (mitc9) {
    add_shear_force(geo.shear_stiffness_wt, ue, f); // linear shear (von Kármán only)
    return f;
  }
  const Eigen::Matrix<double, 3, 4> dx = U.topRows<3>().lazyProduct(geo.s_dN_dx),
                                    dy = U.topRows<3>().lazyProduct(geo.s_dN_dy);
  const Eigen::Matrix<double, 2, 4> at = U.bottomRows<2>().lazyProduct(geo.s_N);
  Eigen::Matrix<double, 3, 4> rx, ry;
  Eigen::Matrix<double, 2, 4> rn;
  for (int q = 0; q < 4; ++q) {
    Gradients g;
    g << dx(0, q), dy(0, q), dx(1, q), dy(1, q), dx(2, q), dy(2, q), 0.0, 0.0, 0.0, 0.0, at(0, q), at(1, q);
    const Strains e = strains_of<Terms, gyz, n_strains>(g);
    Strains S = Strains::Zero();
    S.tail<2>() = F_s * e.tail<2>(); // (Qy, Qx)
    const Gradients r =
        geo.shear[static_cast<std::size_t>(q)].weight * conjugate_stress<Terms, gyz, n_strains>(g, S);
    rx.col(q) << r(ux), r(vx), r(wx);
    ry.col(q) << r(uy), r(vy), r(wy);
    rn.col(q) << r(tx), r(ty);
  }
  F.topRows<3>().noalias() +=
      rx.lazyProduct(geo.s_dN_dx.transpose()) + ry.lazyProduct(geo.s_dN_dy.transpose());
  F.bottomRows<2>().noalias() += rn.lazyProduct(geo.s_N.transpose());
  return f;
}

} // namespace

ElementVector NonlinearMindlinQ9::internal_force(const ElementGeometry& geo, const SectionStiffness& section,
                                                 const ElementVector& ue) const {
  const bool mitc9 = formulation() == ElementFormulation::mitc9;
  if (measure_ == StrainMeasure::von_karman)
    return internal_force_with<von_karman_terms>(geo, ue, section.C_mb, section.F, mitc9);
  return internal_force_with<green_lagrange_terms>(geo, ue, section.C_mb, section.F, mitc9);
}

ElementMatrix NonlinearMindlinQ9::tangent_stiffness(const ElementGeometry& geo,
                                                    const SectionStiffness& section,
                                                    const ElementVector& ue) const {
  const Eigen::Matrix<double, 6, 6>& C_mb = section.C_mb;
  const Eigen::Matrix2d& F = section.F;
  const auto terms = terms_of(measure_);
  ElementMatrix K = ElementMatrix::Zero();
  for (const IntegrationPoint& p : geo.membrane_bending) {
    const StrainState s = strain_state(gradients(p, ue), terms);
    const Eigen::Matrix<double, 6, n_gradients> E = s.E.topRows<6>();
    const Eigen::VectorXd S = C_mb * s.e.head<6>();
    // K_L + K_NL from Eᵀ C E, K_σ from the resultants times the strain curvature (2.100)–(2.103).
    const Eigen::Matrix<double, n_gradients, n_gradients> Kg =
        E.transpose() * C_mb * E + stress_hessian(terms, ex, 6, S);
    const GradientOperator G = gradient_operator(p);
    K.noalias() += p.weight * (G.transpose() * (Kg * G));
  }
  if (formulation() == ElementFormulation::mitc9) {
    K += geo.shear_stiffness;
    return K;
  }
  for (const IntegrationPoint& p : geo.shear) {
    const StrainState s = strain_state(gradients(p, ue), terms);
    const Eigen::Matrix<double, 2, n_gradients> E = s.E.bottomRows<2>();
    const Eigen::VectorXd Q = F * s.e.tail<2>();
    const Eigen::Matrix<double, n_gradients, n_gradients> Kg =
        E.transpose() * F * E + stress_hessian(terms, gyz, 2, Q);
    const GradientOperator G = gradient_operator(p);
    K.noalias() += p.weight * (G.transpose() * (Kg * G));
  }
  return K;
}

} // namespace plyimpact
