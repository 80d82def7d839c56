#include "plyimpact/analysis/fields/stress_recovery.hpp"

#include "plyimpact/laminate/ply_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plyimpact {

PlateAxesStress ply_stress(const Laminate& lam, std::size_t k, const GeneralizedStrains& e, double z) {
  const double zc = std::clamp(z, lam.z_top(k), lam.z_bottom(k));
  return {lam.Qbar(k) * (e.membrane + zc * e.curvature), lam.Qbar_shear(k) * e.shear};
}

PlateAxesStress ply_average_stress(const Laminate& lam, std::size_t k, const GeneralizedStrains& e) {
  const double z_mid = 0.5 * (lam.z_top(k) + lam.z_bottom(k));
  return {lam.Qbar(k) * (e.membrane + z_mid * e.curvature), lam.Qbar_shear(k) * e.shear};
}

PlyStress to_material_axes(const PlateAxesStress& s, double angle_deg) {
  const auto [c, sn] = cos_sin_degrees(angle_deg);
  const double sx = s.in_plane(0), sy = s.in_plane(1), txy = s.in_plane(2);
  const double tyz = s.shear(0), txz = s.shear(1);
  PlyStress m;
  m.s11 = c * c * sx + sn * sn * sy + 2 * c * sn * txy;
  m.s22 = sn * sn * sx + c * c * sy - 2 * c * sn * txy;
  m.t12 = -c * sn * sx + c * sn * sy + (c * c - sn * sn) * txy;
  m.t13 = c * txz + sn * tyz;
  m.t23 = -sn * txz + c * tyz;
  return m;
}

InterfaceStress interface_stress(const Laminate& lam, std::size_t k, const GeneralizedStrains& e) {
  const double z = lam.z_bottom(k);
  return {to_material_axes(ply_stress(lam, k, e, z), lam.plies()[k].angle_deg),
          to_material_axes(ply_stress(lam, k + 1, e, z), lam.plies()[k + 1].angle_deg)};
}

namespace {

/// d/dx (σx) + d/dy (τxy) and d/dx (τxy) + d/dy (σy) at height z in ply k: a + b z.
struct DivergenceLine {
  Eigen::Vector2d a, b; ///< components (x, y)
};

DivergenceLine in_plane_divergence(const Laminate& lam, std::size_t k, const StrainGradients& g) {
  const Eigen::Matrix3d& Q = lam.Qbar(k);
  const Eigen::Vector3d sdx0 = Q * g.membrane_dx, sdy0 = Q * g.membrane_dy;
  const Eigen::Vector3d sdx1 = Q * g.curvature_dx, sdy1 = Q * g.curvature_dy;
  DivergenceLine d;
  d.a = Eigen::Vector2d(sdx0(0) + sdy0(2), sdx0(2) + sdy0(1));
  d.b = Eigen::Vector2d(sdx1(0) + sdy1(2), sdx1(2) + sdy1(1));
  return d;
}

/// τ(z) = −∫_{−h/2}^{z} (a + b ζ) dζ, ply by ply; returns (τxz, τyz) order (x, y).
Eigen::Vector2d integrate_from_top(const Laminate& lam, const StrainGradients& g, double z) {
  Eigen::Vector2d tau = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    const double z0 = lam.z_top(k);
    if (z <= z0) break;
    const double z1 = std::min(z, lam.z_bottom(k));
    const DivergenceLine d = in_plane_divergence(lam, k, g);
    tau -= d.a * (z1 - z0) + d.b * (z1 * z1 - z0 * z0) / 2.0;
  }
  return tau;
}

} // namespace

std::vector<Eigen::Vector2d> equilibrium_transverse_shear(const Laminate& lam, const StrainGradients& g,
                                                          const Eigen::Vector2d& Q,
                                                          const std::vector<double>& z) {
  const double h = lam.thickness(), top = -h / 2, bottom = h / 2;
  const Eigen::Vector2d at_bottom = integrate_from_top(lam, g, bottom);
  // Corrected profile τc(z) = τ(z) − τ(h/2) (z + h/2)/h vanishes on both faces. Its resultant, from
  // a 3-point Gauss rule per ply (τ is quadratic in z inside a ply, so exact).
  const auto corrected = [&](double zz) {
    return Eigen::Vector2d(integrate_from_top(lam, g, zz) - at_bottom * (zz - top) / h);
  };
  Eigen::Vector2d resultant = Eigen::Vector2d::Zero();
  constexpr double gp[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
  constexpr double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (std::size_t k = 0; k < lam.ply_count(); ++k) {
    const double zm = 0.5 * (lam.z_top(k) + lam.z_bottom(k)), hz = 0.5 * (lam.z_bottom(k) - lam.z_top(k));
    for (int i = 0; i < 3; ++i)
      resultant += gw[i] * hz * corrected(zm + gp[i] * hz);
  }
  // Scale each component to the constitutive resultant (Qx ↔ τxz, Qy ↔ τyz). Q = (Qy, Qx) in F's
  // order (yz, xz).
  const Eigen::Vector2d target(Q(1), Q(0));
  Eigen::Vector2d scale;
  for (int c = 0; c < 2; ++c)
    scale(c) = std::abs(resultant(c)) > 1e-300 ? target(c) / resultant(c) : 0.0;
  std::vector<Eigen::Vector2d> out;
  out.reserve(z.size());
  for (const double zz : z) {
    const Eigen::Vector2d t = corrected(zz).cwiseProduct(scale);
    out.emplace_back(t(1), t(0)); // (τyz, τxz)
  }
  return out;
}

StrainGradients strain_gradients(const ElementCoordinates& xy, const ElementVector& ue, double xi,
                                 double eta) {
  // Axis-aligned rectangle: x = x0 + (ξ + 1) dx/2, so ∂/∂x = (2/dx) ∂/∂ξ exactly.
  const double dx = xy(1, 0) - xy(0, 0), dy = xy(3, 1) - xy(0, 1);
  if (!(dx > 0.0) || !(dy > 0.0) || std::abs(xy(1, 1) - xy(0, 1)) > 1e-12 * dy)
    throw std::invalid_argument("strain gradients need axis-aligned rectangular elements");
  const double sx = 2.0 / dx, sy = 2.0 / dy;
  // Second derivatives of the 1-D quadratic Lagrange polynomials are constant: (1, −2, 1).
  const auto lagrange = [](double s, int i) {
    return i == 0 ? 0.5 * s * (s - 1.0) : (i == 1 ? 1.0 - s * s : 0.5 * s * (s + 1.0));
  };
  const auto dlagrange = [](double s, int i) { return i == 0 ? s - 0.5 : (i == 1 ? -2.0 * s : s + 0.5); };
  const auto d2lagrange = [](int i) { return i == 1 ? -2.0 : 1.0; };
  StrainGradients g{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                    Eigen::Vector3d::Zero()};
  for (int a = 0; a < 9; ++a) {
    const auto& c = q9_node_coordinates[static_cast<std::size_t>(a)];
    const int i = c[0] < -0.5 ? 0 : (c[0] > 0.5 ? 2 : 1);
    const int j = c[1] < -0.5 ? 0 : (c[1] > 0.5 ? 2 : 1);
    const double Nxx = d2lagrange(i) * lagrange(eta, j) * sx * sx;
    const double Nyy = lagrange(xi, i) * d2lagrange(j) * sy * sy;
    const double Nxy = dlagrange(xi, i) * dlagrange(eta, j) * sx * sy;
    const double u = ue(5 * a), v = ue(5 * a + 1), tx = ue(5 * a + 3), ty = ue(5 * a + 4);
    g.membrane_dx += Eigen::Vector3d(Nxx * u, Nxy * v, Nxy * u + Nxx * v); // ∂/∂x (u,x, v,y, u,y + v,x)
    g.membrane_dy += Eigen::Vector3d(Nxy * u, Nyy * v, Nyy * u + Nxy * v);
    g.curvature_dx += Eigen::Vector3d(Nxx * tx, Nxy * ty, Nxy * tx + Nxx * ty);
    g.curvature_dy += Eigen::Vector3d(Nxy * tx, Nyy * ty, Nyy * tx + Nxy * ty);
  }
  return g;
}

} // namespace plyimpact
