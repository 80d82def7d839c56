// Navier series reference solutions; see navier.hpp for the derivation and conventions.
#include "support/navier.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace plyimpact::test::navier {

namespace {

constexpr double pi = std::numbers::pi;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("navier: " + what);
}

// Scope checks shared by every entry point.
void check_bending(const Plate& p) {
  require(p.a > 0.0 && p.b > 0.0, "plate dimensions a, b must be positive");
  require(p.D(0, 0) > 0.0 && p.D(1, 1) > 0.0 && p.D(2, 2) > 0.0, "D11, D22, D66 must be positive");
  require(p.F44 > 0.0 && p.F55 > 0.0 && std::isfinite(p.F44) && std::isfinite(p.F55),
          "F44, F55 must be positive and finite");
  const double scale = std::max(p.D(0, 0), p.D(1, 1));
  require(std::abs(p.D(0, 2)) <= 1e-10 * scale && std::abs(p.D(1, 2)) <= 1e-10 * scale &&
              std::abs(p.D(2, 0)) <= 1e-10 * scale && std::abs(p.D(2, 1)) <= 1e-10 * scale,
          "D16, D26 must be zero (specially orthotropic / cross-ply laminate)");
}

void check_inertia(const Plate& p) {
  require(p.I0 > 0.0, "I0 must be positive");
  require(p.I2 >= 0.0, "I2 must be non-negative");
}

void check_membrane(const Plate& p) {
  require(p.a > 0.0 && p.b > 0.0, "plate dimensions a, b must be positive");
  require(p.A(0, 0) > 0.0 && p.A(1, 1) > 0.0 && p.A(2, 2) > 0.0, "A11, A22, A66 must be positive");
  const double scale = std::max(p.A(0, 0), p.A(1, 1));
  require(std::abs(p.A(0, 2)) <= 1e-10 * scale && std::abs(p.A(1, 2)) <= 1e-10 * scale &&
              std::abs(p.A(2, 0)) <= 1e-10 * scale && std::abs(p.A(2, 1)) <= 1e-10 * scale,
          "A16, A26 must be zero");
}

struct Wavenumbers {
  double alpha;
  double beta;
};
Wavenumbers wavenumbers(const Plate& p, int m, int n) {
  return {static_cast<double>(m) * pi / p.a, static_cast<double>(n) * pi / p.b};
}

// Bending-part 2×2 of the rotations: Db = [[D11α²+D66β², (D12+D66)αβ], [., D66α²+D22β²]].
Eigen::Matrix2d bending_block(const Plate& p, double al, double be) {
  Eigen::Matrix2d Db;
  Db(0, 0) = p.D(0, 0) * al * al + p.D(2, 2) * be * be;
  Db(1, 1) = p.D(2, 2) * al * al + p.D(1, 1) * be * be;
  Db(0, 1) = Db(1, 0) = (p.D(0, 1) + p.D(2, 2)) * al * be;
  return Db;
}

// Solves the symmetric 2×2 system S y = r (S positive definite here).
Eigen::Vector2d solve2(const Eigen::Matrix2d& S, const Eigen::Vector2d& r) {
  const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  return {(S(1, 1) * r(0) - S(0, 1) * r(1)) / det, (S(0, 0) * r(1) - S(1, 0) * r(0)) / det};
}

// γ per unit W for the shifted problem: γ = (Db + Fd − s I2)⁻¹ (Db − s I2) g.
// The Schur complement of the θ block is then T(s) − s I0 with T(s) = gᵀ Fd γ.
Eigen::Vector2d shear_per_unit_w(const Plate& p, double al, double be, double s) {
  const Eigen::Matrix2d Db = bending_block(p, al, be);
  Eigen::Matrix2d E = Db;
  E(0, 0) -= s * p.I2;
  E(1, 1) -= s * p.I2;
  Eigen::Matrix2d Kt = E;
  Kt(0, 0) += p.F55;
  Kt(1, 1) += p.F44;
  const Eigen::Vector2d g(al, be);
  return solve2(Kt, E * g);
}

double schur_T(const Plate& p, double al, double be, double s) {
  const Eigen::Vector2d gam = shear_per_unit_w(p, al, be, s);
  return al * p.F55 * gam(0) + be * p.F44 * gam(1);
}

// Smallest eigenvalue of the θ block divided by I2 (rad²/s²), +inf when I2 = 0.
double theta_block_limit(const Plate& p, double al, double be) {
  if (p.I2 <= 0.0) return std::numeric_limits<double>::infinity();
  Eigen::Matrix2d K = bending_block(p, al, be);
  K(0, 0) += p.F55;
  K(1, 1) += p.F44;
  const double tr = K(0, 0) + K(1, 1);
  const double dif = K(0, 0) - K(1, 1);
  const double disc = std::sqrt(dif * dif + 4.0 * K(0, 1) * K(0, 1));
  // Smaller root computed as det / larger root (no cancellation).
  const double big = 0.5 * (tr + disc);
  const double det = K(0, 0) * K(1, 1) - K(0, 1) * K(0, 1);
  return det / big / p.I2;
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Plates
// ---------------------------------------------------------------------------------------------------
Plate isotropic_plate(double a, double b, double h, double E, double nu, double rho, double k_shear) {
  require(h > 0.0 && E > 0.0 && nu > -1.0 && nu < 0.5 && rho >= 0.0 && k_shear > 0.0,
          "invalid isotropic plate data");
  Plate p;
  p.a = a;
  p.b = b;
  const double c = E / (1.0 - nu * nu);
  const double G = E / (2.0 * (1.0 + nu));
  Eigen::Matrix3d Q;
  Q << c, nu * c, 0.0, nu * c, c, 0.0, 0.0, 0.0, G;
  p.A = Q * h;
  p.D = Q * (h * h * h / 12.0);
  p.F44 = p.F55 = k_shear * G * h;
  p.I0 = rho * h;
  p.I2 = rho * h * h * h / 12.0;
  return p;
}

Plate plate_from_plies(double a, double b, const std::vector<Ply>& plies, double k_shear) {
  require(!plies.empty(), "empty ply list");
  require(k_shear > 0.0, "shear correction factor must be positive");
  Plate p;
  p.a = a;
  p.b = b;
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  double I1 = 0.0;
  for (std::size_t k = 0; k < plies.size(); ++k) {
    const Ply& q = plies[k];
    require(q.z_bottom > q.z_top, "ply z_bottom must exceed z_top");
    if (k > 0) {
      require(std::abs(q.z_top - plies[k - 1].z_bottom) <= 1e-12 * (std::abs(q.z_top) + 1e-3),
              "plies must be contiguous");
    }
    Eigen::Matrix3d Q;
    Q << q.Q11, q.Q12, q.Q16, q.Q12, q.Q22, q.Q26, q.Q16, q.Q26, q.Q66;
    const double t1 = q.z_bottom - q.z_top;
    const double t2 = (q.z_bottom * q.z_bottom - q.z_top * q.z_top) / 2.0;
    const double t3 = (q.z_bottom * q.z_bottom * q.z_bottom - q.z_top * q.z_top * q.z_top) / 3.0;
    p.A += Q * t1;
    B += Q * t2;
    p.D += Q * t3;
    p.F44 += k_shear * q.Q44 * t1;
    p.F55 += k_shear * q.Q55 * t1;
    p.I0 += q.rho * t1;
    I1 += q.rho * t2;
    p.I2 += q.rho * t3;
  }
  const double h = plies.back().z_bottom - plies.front().z_top;
  require(B.cwiseAbs().maxCoeff() <= 1e-9 * p.A.cwiseAbs().maxCoeff() * h,
          "laminate is not symmetric (B != 0)");
  require(std::abs(I1) <= 1e-9 * std::max(p.I0, 1e-300) * h, "laminate is not symmetric (I1 != 0)");
  check_membrane(p);
  check_bending(p);
  return p;
}

// ---------------------------------------------------------------------------------------------------
// Loads
// ---------------------------------------------------------------------------------------------------
Load uniform_load(double q0) {
  return Load{LoadKind::Uniform, q0, 0.0, 0.0, 0.0, 0.0};
}
Load sinusoidal_load(double q0) {
  return Load{LoadKind::Sinusoidal, q0, 0.0, 0.0, 0.0, 0.0};
}
Load point_load(double P, double x0, double y0) {
  return Load{LoadKind::Point, P, x0, y0, 0.0, 0.0};
}
Load patch_load(double q0, double x0, double y0, double cx, double cy) {
  return Load{LoadKind::Patch, q0, x0, y0, cx, cy};
}

double load_coefficient(const Plate& p, const Load& load, int m, int n) {
  require(m >= 1 && n >= 1, "load_coefficient needs m, n >= 1");
  const auto [al, be] = wavenumbers(p, m, n);
  const double mn = static_cast<double>(m) * static_cast<double>(n);
  switch (load.kind) {
  case LoadKind::Uniform:
    if (m % 2 == 0 || n % 2 == 0) return 0.0;
    return 16.0 * load.value / (pi * pi * mn);
  case LoadKind::Sinusoidal:
    return (m == 1 && n == 1) ? load.value : 0.0;
  case LoadKind::Point:
    return 4.0 * load.value / (p.a * p.b) * std::sin(al * load.x0) * std::sin(be * load.y0);
  case LoadKind::Patch:
    return 16.0 * load.value / (pi * pi * mn) * std::sin(al * load.x0) * std::sin(be * load.y0) *
           std::sin(al * load.cx / 2.0) * std::sin(be * load.cy / 2.0);
  }
  return 0.0;
}

// ---------------------------------------------------------------------------------------------------
// Single-term matrices and amplitudes
// ---------------------------------------------------------------------------------------------------
Eigen::Matrix3d bending_stiffness(const Plate& p, int m, int n) {
  check_bending(p);
  const auto [al, be] = wavenumbers(p, m, n);
  const Eigen::Matrix2d Db = bending_block(p, al, be);
  Eigen::Matrix3d K;
  K(0, 0) = p.F55 * al * al + p.F44 * be * be;
  K(0, 1) = K(1, 0) = p.F55 * al;
  K(0, 2) = K(2, 0) = p.F44 * be;
  K(1, 1) = Db(0, 0) + p.F55;
  K(2, 2) = Db(1, 1) + p.F44;
  K(1, 2) = K(2, 1) = Db(0, 1);
  return K;
}

Eigen::Matrix3d bending_mass(const Plate& p) {
  return Eigen::Vector3d(p.I0, p.I2, p.I2).asDiagonal();
}

Eigen::Matrix2d inplane_stiffness(const Plate& p, int m, int n) {
  check_membrane(p);
  const auto [al, be] = wavenumbers(p, m, n);
  Eigen::Matrix2d K;
  K(0, 0) = p.A(0, 0) * al * al + p.A(2, 2) * be * be;
  K(1, 1) = p.A(2, 2) * al * al + p.A(1, 1) * be * be;
  K(0, 1) = K(1, 0) = (p.A(0, 1) + p.A(2, 2)) * al * be;
  return K;
}

BendingAmplitudes static_amplitudes(const Plate& p, int m, int n, double q_mn) {
  check_bending(p);
  require(m >= 1 && n >= 1, "static_amplitudes needs m, n >= 1");
  const auto [al, be] = wavenumbers(p, m, n);
  const Eigen::Vector2d gam = shear_per_unit_w(p, al, be, 0.0); // γ per unit W
  const double S0 = al * p.F55 * gam(0) + be * p.F44 * gam(1);
  BendingAmplitudes r;
  r.W = q_mn / S0;
  r.Gx = gam(0) * r.W;
  r.Gy = gam(1) * r.W;
  r.X = r.Gx - al * r.W; // θ = γ − ∇w: X is the large term, no cancellation
  r.Y = r.Gy - be * r.W;
  return r;
}

// ---------------------------------------------------------------------------------------------------
// Static series
// ---------------------------------------------------------------------------------------------------
StaticField static_field(const Plate& p, const Load& load, double x, double y, const SeriesOptions& opt) {
  check_bending(p);
  require(opt.max_index >= 1, "max_index must be >= 1");
  constexpr int nf = 14;
  // 0 w, 1 θx, 2 θy, 3–5 κ, 6–8 ∂κ/∂x, 9–11 ∂κ/∂y, 12 γxz, 13 γyz; the convergence test looks at the
  // first n_checked (w, θ, κ): the shear-type fields converge only like 1/N.
  constexpr int n_checked = 6;
  std::array<double, nf> sum{};
  std::array<double, nf> absum{};
  StaticField f;
  int quiet_shells = 0;
  for (int K = 1; K <= opt.max_index; ++K) {
    std::array<double, nf> shell{};
    bool nonempty = false;
    for (int j = 1; j <= 2 * K - 1; ++j) {
      const int m = j <= K ? K : j - K;
      const int n = j <= K ? j : K;
      const double q = load_coefficient(p, load, m, n);
      if (q == 0.0) continue;
      nonempty = true;
      const auto [al, be] = wavenumbers(p, m, n);
      const BendingAmplitudes A = static_amplitudes(p, m, n, q);
      const double sx = std::sin(al * x), cx = std::cos(al * x);
      const double sy = std::sin(be * y), cy = std::cos(be * y);
      const double twist = be * A.X + al * A.Y;
      const double ss = sx * sy, cs = cx * sy, sc = sx * cy, cc = cx * cy;
      // coefficient × trigonometric factor of each field
      const std::array<double, nf> coef{A.W,
                                        A.X,
                                        A.Y,
                                        -al * A.X,
                                        -be * A.Y,
                                        twist,
                                        -al * al * A.X,
                                        -al * be * A.Y,
                                        -al * twist,
                                        -al * be * A.X,
                                        -be * be * A.Y,
                                        -be * twist,
                                        A.Gx,
                                        A.Gy};
      const std::array<double, nf> trig{ss, cs, sc, ss, ss, cc, cs, cs, sc, sc, sc, cs, cs, sc};
      for (int i = 0; i < nf; ++i) {
        shell[i] += coef[i] * trig[i];
        absum[i] += std::abs(coef[i]);
      }
    }
    for (int i = 0; i < nf; ++i)
      sum[i] += shell[i];
    f.max_index_used = K;
    if (opt.rel_tol > 0.0 && nonempty) {
      bool small = true;
      for (int i = 0; i < n_checked; ++i)
        small = small && std::abs(shell[i]) <= opt.rel_tol * absum[i];
      quiet_shells = small ? quiet_shells + 1 : 0;
      if (quiet_shells >= 2) {
        f.converged = true;
        break;
      }
    }
  }
  f.w = sum[0];
  f.theta_x = sum[1];
  f.theta_y = sum[2];
  f.kappa = Eigen::Vector3d(sum[3], sum[4], sum[5]);
  f.dkappa_dx = Eigen::Vector3d(sum[6], sum[7], sum[8]);
  f.dkappa_dy = Eigen::Vector3d(sum[9], sum[10], sum[11]);
  f.gamma_xz = sum[12];
  f.gamma_yz = sum[13];
  const double D11 = p.D(0, 0), D12 = p.D(0, 1), D22 = p.D(1, 1), D66 = p.D(2, 2);
  f.Mx = D11 * f.kappa(0) + D12 * f.kappa(1);
  f.My = D12 * f.kappa(0) + D22 * f.kappa(1);
  f.Mxy = D66 * f.kappa(2);
  f.Qx = p.F55 * f.gamma_xz;
  f.Qy = p.F44 * f.gamma_yz;
  f.dMx_dx = D11 * f.dkappa_dx(0) + D12 * f.dkappa_dx(1);
  f.dMy_dy = D12 * f.dkappa_dy(0) + D22 * f.dkappa_dy(1);
  f.dMxy_dx = D66 * f.dkappa_dx(2);
  f.dMxy_dy = D66 * f.dkappa_dy(2);
  return f;
}

Eigen::Vector3d inplane_stress(const Ply& ply, double z, const StaticField& f) {
  Eigen::Matrix3d Q;
  Q << ply.Q11, ply.Q12, ply.Q16, ply.Q12, ply.Q22, ply.Q26, ply.Q16, ply.Q26, ply.Q66;
  return Q * (z * f.kappa);
}

TransverseShear equilibrium_transverse_shear(const std::vector<Ply>& plies, const StaticField& f, double z) {
  require(!plies.empty(), "empty ply list");
  const double ztop = plies.front().z_top;
  const double zbot = plies.back().z_bottom;
  const double tol = 1e-12 * (zbot - ztop);
  require(z >= ztop - tol && z <= zbot + tol, "z outside the laminate");
  const Eigen::Vector3d& kx = f.dkappa_dx; // (κx,x, κy,x, κxy,x)
  const Eigen::Vector3d& ky = f.dkappa_dy; // (κx,y, κy,y, κxy,y)
  TransverseShear t;
  for (const Ply& q : plies) {
    if (z <= q.z_top) break;
    const double zb = std::min(z, q.z_bottom);
    // ∂σx/∂x + ∂τxy/∂y = z·cx,  ∂τxy/∂x + ∂σy/∂y = z·cy
    const double cxv =
        q.Q11 * kx(0) + q.Q12 * kx(1) + q.Q16 * kx(2) + q.Q16 * ky(0) + q.Q26 * ky(1) + q.Q66 * ky(2);
    const double cyv =
        q.Q16 * kx(0) + q.Q26 * kx(1) + q.Q66 * kx(2) + q.Q12 * ky(0) + q.Q22 * ky(1) + q.Q26 * ky(2);
    const double zz = (zb * zb - q.z_top * q.z_top) / 2.0;
    t.tau_xz -= cxv * zz;
    t.tau_yz -= cyv * zz;
  }
  return t;
}

// ---------------------------------------------------------------------------------------------------
// Free vibration
// ---------------------------------------------------------------------------------------------------
double fundamental_bending_omega2(const Plate& p, int m, int n) {
  check_bending(p);
  check_inertia(p);
  require(m >= 1 && n >= 1, "fundamental_bending_omega2 needs m, n >= 1");
  const Wavenumbers k = wavenumbers(p, m, n);
  const double al = k.alpha, be = k.beta; // plain variables: lambdas may not capture bindings (C++17)
  // h(s) = T(s) − s I0 is strictly decreasing on [0, s_theta) and h(0) = S0 > 0; the lowest root of
  // the 3×3 pencil is its unique zero there (or s_theta itself in a degenerate case).
  const double s_theta = theta_block_limit(p, al, be);
  const auto h = [&](double s) { return schur_T(p, al, be, s) - s * p.I0; };
  double lo = 0.0;
  double hi = schur_T(p, al, be, 0.0) / p.I0; // rotary-inertia-free value: an upper bound
  if (hi >= s_theta) {
    hi = s_theta * (1.0 - 1e-15);
    if (h(hi) > 0.0) return s_theta;
  }
  if (h(hi) >= 0.0) return hi; // I2 = 0: exact
  for (int it = 0; it < 200 && hi - lo > 1e-16 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (h(mid) > 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

std::vector<double> bending_frequencies(const Plate& p, int m, int n) {
  check_bending(p);
  check_inertia(p);
  require(m >= 0 && n >= 0 && m + n >= 1, "bending_frequencies needs m, n >= 0, not both 0");
  const auto [al, be] = wavenumbers(p, m, n);
  if (m == 0 || n == 0) {
    if (p.I2 <= 0.0) return {};
    const double k = (m == 0) ? p.D(2, 2) * be * be + p.F55 : p.D(2, 2) * al * al + p.F44;
    return {std::sqrt(k / p.I2)};
  }
  std::vector<double> out{std::sqrt(fundamental_bending_omega2(p, m, n))};
  if (p.I2 > 0.0) {
    // The two thickness-shear roots are the large eigenvalues: well conditioned in the 3×3 form.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> es(
        bending_stiffness(p, m, n), bending_mass(p), Eigen::EigenvaluesOnly);
    require(es.info() == Eigen::Success, "eigen solver failed");
    out.push_back(std::sqrt(es.eigenvalues()(1)));
    out.push_back(std::sqrt(es.eigenvalues()(2)));
  }
  return out;
}

std::vector<double> inplane_frequencies(const Plate& p, int m, int n) {
  check_membrane(p);
  check_inertia(p);
  require(m >= 0 && n >= 0 && m + n >= 1, "inplane_frequencies needs m, n >= 0, not both 0");
  const auto [al, be] = wavenumbers(p, m, n);
  if (m == 0) return {be * std::sqrt(p.A(2, 2) / p.I0)};
  if (n == 0) return {al * std::sqrt(p.A(2, 2) / p.I0)};
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(inplane_stiffness(p, m, n) / p.I0,
                                                          Eigen::EigenvaluesOnly);
  require(es.info() == Eigen::Success, "eigen solver failed");
  return {std::sqrt(es.eigenvalues()(0)), std::sqrt(es.eigenvalues()(1))};
}

std::vector<NaturalFrequency> lowest_frequencies(const Plate& p, int k) {
  require(k >= 1, "k must be >= 1");
  check_bending(p);
  check_membrane(p);
  check_inertia(p);
  const auto collect = [&](int m, int n, std::vector<NaturalFrequency>& out) {
    const std::vector<double> wb = bending_frequencies(p, m, n);
    for (std::size_t r = 0; r < wb.size(); ++r) {
      out.push_back({wb[r], ModeFamily::Bending, m, n, static_cast<int>(r)});
    }
    const std::vector<double> wi = inplane_frequencies(p, m, n);
    for (std::size_t r = 0; r < wi.size(); ++r) {
      out.push_back({wi[r], ModeFamily::InPlane, m, n, static_cast<int>(r)});
    }
  };
  const auto by_omega = [](const NaturalFrequency& l, const NaturalFrequency& r) {
    return l.omega < r.omega;
  };
  for (int N = std::max(4, k);; N *= 2) {
    std::vector<NaturalFrequency> all;
    for (int m = 0; m <= N; ++m) {
      for (int n = 0; n <= N; ++n) {
        if (m + n > 0) collect(m, n, all);
      }
    }
    std::sort(all.begin(), all.end(), by_omega);
    if (static_cast<int>(all.size()) < k) continue;
    std::vector<NaturalFrequency> frontier;
    for (int j = 0; j <= N + 1; ++j) {
      collect(N + 1, j, frontier);
      if (j <= N) collect(j, N + 1, frontier);
    }
    double frontier_min = std::numeric_limits<double>::infinity();
    for (const NaturalFrequency& fr : frontier)
      frontier_min = std::min(frontier_min, fr.omega);
    if (all[static_cast<std::size_t>(k - 1)].omega <= frontier_min) {
      all.resize(static_cast<std::size_t>(k));
      return all;
    }
    require(N < 4096, "lowest_frequencies did not terminate");
  }
}

// ---------------------------------------------------------------------------------------------------
// Buckling
// ---------------------------------------------------------------------------------------------------
double buckling_factor(const Plate& p, double Nx, double Ny, int m, int n) {
  check_bending(p);
  require(m >= 1 && n >= 1, "buckling_factor needs m, n >= 1");
  const auto [al, be] = wavenumbers(p, m, n);
  const double g = -(Nx * al * al + Ny * be * be);
  if (!(g > 0.0)) return std::numeric_limits<double>::infinity();
  return schur_T(p, al, be, 0.0) / g;
}

BucklingMode lowest_buckling_factor(const Plate& p, double Nx, double Ny, int max_index) {
  require(max_index >= 1, "max_index must be >= 1");
  BucklingMode best{std::numeric_limits<double>::infinity(), 0, 0};
  for (int m = 1; m <= max_index; ++m) {
    for (int n = 1; n <= max_index; ++n) {
      const double l = buckling_factor(p, Nx, Ny, m, n);
      if (l < best.lambda) best = {l, m, n};
    }
  }
  return best;
}

} // namespace plyimpact::test::navier
