// Modal (Navier / Ritz) reference for the impact of a sphere on a simply supported Mindlin plate;
// see navier_impact.hpp for the derivation and conventions.
#include "support/navier_impact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace plyimpact::test::navier_impact {

namespace {

constexpr double pi = std::numbers::pi;

// Below this |S_m(x0) S_n(y0)| a w-term is not loaded (and does not load the contact point).
constexpr double unloaded = 1e-12;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("navier_impact: " + what);
}

// ---------------------------------------------------------------------------------------------------
// Separable strains and their integrals
// ---------------------------------------------------------------------------------------------------
enum class Trig { sine, cosine };

// coef · X(x) · Y(y), X = sin or cos (mπx/a), Y = sin or cos (nπy/b).
struct Separable {
  double coef = 0.0;
  Trig x = Trig::sine;
  Trig y = Trig::sine;
};

// ∫₀^L f1(m1 π s/L) f2(m2 π s/L) ds for f = sin or cos, m ≥ 0.
double integral_1d(Trig f1, int m1, Trig f2, int m2, double L) {
  if (f1 == Trig::sine && f2 == Trig::sine) return (m1 == m2 && m1 > 0) ? L / 2.0 : 0.0;
  if (f1 == Trig::cosine && f2 == Trig::cosine) return m1 == m2 ? (m1 == 0 ? L : L / 2.0) : 0.0;
  if (f1 == Trig::cosine) return integral_1d(f2, m2, f1, m1, L); // ∫ cos sin = ∫ sin cos
  // ∫₀^π sin(m1 t) cos(m2 t) dt = m1 (1 − (−1)^(m1+m2)) / (m1² − m2²), 0 if m1 + m2 is even.
  if ((m1 + m2) % 2 == 0) return 0.0;
  const double p = m1, r = m2;
  return L / pi * 2.0 * p / (p * p - r * r);
}

// Generalized strains of one basis function in the order (κx, κy, κxy, γyz, γxz), paired with the
// 5×5 constitutive matrix blockdiag(D, F) (F in the order yz, xz).
using StrainTerms = std::array<std::optional<Separable>, 5>;

StrainTerms strains(const BendingPlate& p, const BasisFunction& f) {
  const double al = f.m * pi / p.a, be = f.n * pi / p.b;
  StrainTerms e;
  switch (f.unknown) {
  case Unknown::w: // w = S S: γyz = w,y = β S C, γxz = w,x = α C S
    e[3] = Separable{be, Trig::sine, Trig::cosine};
    e[4] = Separable{al, Trig::cosine, Trig::sine};
    break;
  case Unknown::theta_x:
    if (f.edge) { // θx = S S: κx = α C S, κxy ∋ θx,y = β S C, γxz ∋ θx
      e[0] = Separable{al, Trig::cosine, Trig::sine};
      e[2] = Separable{be, Trig::sine, Trig::cosine};
      e[4] = Separable{1.0, Trig::sine, Trig::sine};
    } else { // θx = C S: κx = −α S S, κxy ∋ θx,y = β C C, γxz ∋ θx
      e[0] = Separable{-al, Trig::sine, Trig::sine};
      e[2] = Separable{be, Trig::cosine, Trig::cosine};
      e[4] = Separable{1.0, Trig::cosine, Trig::sine};
    }
    break;
  case Unknown::theta_y:
    if (f.edge) { // θy = S S: κy = β S C, κxy ∋ θy,x = α C S, γyz ∋ θy
      e[1] = Separable{be, Trig::sine, Trig::cosine};
      e[2] = Separable{al, Trig::cosine, Trig::sine};
      e[3] = Separable{1.0, Trig::sine, Trig::sine};
    } else { // θy = S C: κy = −β S S, κxy ∋ θy,x = α C C, γyz ∋ θy
      e[1] = Separable{-be, Trig::sine, Trig::sine};
      e[2] = Separable{al, Trig::cosine, Trig::cosine};
      e[3] = Separable{1.0, Trig::sine, Trig::cosine};
    }
    break;
  }
  return e;
}

Separable shape(const BasisFunction& f) {
  switch (f.unknown) {
  case Unknown::w:
    return {1.0, Trig::sine, Trig::sine};
  case Unknown::theta_x:
    return {1.0, f.edge ? Trig::sine : Trig::cosine, Trig::sine};
  case Unknown::theta_y:
    return {1.0, Trig::sine, f.edge ? Trig::sine : Trig::cosine};
  }
  return {};
}

double integral_2d(const BendingPlate& p, const Separable& s1, const BasisFunction& f1, const Separable& s2,
                   const BasisFunction& f2) {
  return s1.coef * s2.coef * integral_1d(s1.x, f1.m, s2.x, f2.m, p.a) *
         integral_1d(s1.y, f1.n, s2.y, f2.n, p.b);
}

// ---------------------------------------------------------------------------------------------------
// Contact law (SPEC §4, thesis (2.5)–(2.7)), written again for the reference
// ---------------------------------------------------------------------------------------------------
class IndentationLaw {
public:
  explicit IndentationLaw(const ContactLaw& law)
      : k_(law.k), q_(law.elastic ? 1.5 : law.q), beta_(law.elastic ? 0.0 : law.beta),
        alpha_cr_(law.alpha_cr) {}

  // F(α) with the current history: loading k α^1.5 beyond αm; below αm the unloading curve
  // Fm ((α − α0)/(αm − α0))^q, or after a full unload the reloading curve with exponent 1.5.
  [[nodiscard]] double force(double alpha) const {
    if (alpha <= alpha0_) return 0.0;
    if (alpha >= alpha_m_) return k_ * std::pow(alpha, 1.5);
    return force_m_ * std::pow((alpha - alpha0_) / (alpha_m_ - alpha0_), exponent());
  }
  [[nodiscard]] double stiffness(double alpha) const {
    if (alpha <= alpha0_) return 0.0;
    if (alpha >= alpha_m_) return 1.5 * k_ * std::sqrt(alpha);
    const double span = alpha_m_ - alpha0_;
    return force_m_ * exponent() * std::pow((alpha - alpha0_) / span, exponent() - 1.0) / span;
  }
  void commit(double alpha) {
    if (alpha > alpha_m_) {
      alpha_m_ = alpha;
      force_m_ = k_ * std::pow(alpha, 1.5);
      alpha0_ = alpha_m_ > alpha_cr_ ? beta_ * (alpha_m_ - alpha_cr_) : 0.0; // Tan & Sun
      reloading_ = false;
    } else if (alpha <= alpha0_ && alpha_m_ > 0.0) {
      reloading_ = true; // separated: the next contact follows Yang & Sun's reloading curve
    }
  }
  [[nodiscard]] double permanent_indentation() const { return alpha0_; }

private:
  [[nodiscard]] double exponent() const { return reloading_ ? 1.5 : q_; }

  double k_, q_, beta_, alpha_cr_;
  double alpha_m_ = 0.0, force_m_ = 0.0, alpha0_ = 0.0;
  bool reloading_ = false;
};

// Vertex (t, value) of the parabola through (−1, y0), (0, y1), (1, y2) in units of the step.
std::pair<double, double> parabola_vertex(double y0, double y1, double y2) {
  const double curvature = y0 - 2.0 * y1 + y2;
  if (!(curvature < 0.0)) return {0.0, y1};
  const double s = 0.5 * (y0 - y2) / curvature;
  return {s, y1 - 0.125 * (y0 - y2) * (y0 - y2) / curvature};
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Plate
// ---------------------------------------------------------------------------------------------------
BendingPlate bending_plate(const Laminate& laminate, double a, double b) {
  require(a > 0.0 && b > 0.0, "plate dimensions must be positive");
  const double h = laminate.thickness();
  require(laminate.B().cwiseAbs().maxCoeff() <= 1e-10 * laminate.A().cwiseAbs().maxCoeff() * h,
          "laminate is not symmetric (B != 0)");
  const auto& I = laminate.inertia();
  require(std::abs(I[1]) <= 1e-10 * I[0] * h, "laminate is not symmetric (I1 != 0)");
  BendingPlate p;
  p.a = a;
  p.b = b;
  p.D = laminate.D();
  p.F = laminate.F();
  p.I0 = I[0];
  p.I2 = I[2];
  return p;
}

bool is_specially_orthotropic(const BendingPlate& p) {
  const double d = p.D.cwiseAbs().maxCoeff(), f = p.F.cwiseAbs().maxCoeff();
  return std::abs(p.D(0, 2)) <= 1e-12 * d && std::abs(p.D(1, 2)) <= 1e-12 * d &&
         std::abs(p.F(0, 1)) <= 1e-12 * f;
}

RitzMatrices ritz_matrices(const BendingPlate& p, const std::vector<BasisFunction>& basis) {
  const auto n = static_cast<Eigen::Index>(basis.size());
  Eigen::Matrix<double, 5, 5> C = Eigen::Matrix<double, 5, 5>::Zero();
  C.topLeftCorner<3, 3>() = p.D;
  C.bottomRightCorner<2, 2>() = p.F;
  std::vector<StrainTerms> e;
  e.reserve(basis.size());
  for (const BasisFunction& f : basis) {
    require(f.m >= 0 && f.n >= 0, "negative wave index");
    e.push_back(strains(p, f));
  }
  RitzMatrices r{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    for (Eigen::Index j = i; j < n; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      double k = 0.0;
      for (int s = 0; s < 5; ++s) {
        if (!e[ui][static_cast<std::size_t>(s)]) continue;
        for (int t = 0; t < 5; ++t) {
          if (!e[uj][static_cast<std::size_t>(t)] || C(s, t) == 0.0) continue;
          k += C(s, t) * integral_2d(p, *e[ui][static_cast<std::size_t>(s)], basis[ui],
                                     *e[uj][static_cast<std::size_t>(t)], basis[uj]);
        }
      }
      r.K(i, j) = r.K(j, i) = k;
    }
    // Mass: I0 on w, I2 on θx, θy; different unknowns do not couple.
    const double inertia = basis[ui].unknown == Unknown::w ? p.I0 : p.I2;
    for (Eigen::Index j = i; j < n; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      if (basis[uj].unknown != basis[ui].unknown) continue;
      r.M(i, j) = r.M(j, i) =
          inertia * integral_2d(p, shape(basis[ui]), basis[ui], shape(basis[uj]), basis[uj]);
    }
  }
  return r;
}

// ---------------------------------------------------------------------------------------------------
// Hertz pressure in wavenumber space
// ---------------------------------------------------------------------------------------------------
double hertz_transform(double q) {
  q = std::abs(q);
  if (q < 0.1) { // 3 j1(q)/q = 1 − q²/10 + q⁴/280 − q⁶/15120 + q⁸/1330560 − …  (no cancellation)
    const double q2 = q * q;
    return 1.0 - q2 / 10.0 * (1.0 - q2 / 28.0 * (1.0 - q2 / 54.0 * (1.0 - q2 / 88.0)));
  }
  return 3.0 * (std::sin(q) - q * std::cos(q)) / (q * q * q);
}

// P(q) and P'(q) with one sine and one cosine (the time loop evaluates both for every term).
std::pair<double, double> hertz_transform_and_derivative(double q) {
  if (std::abs(q) < 0.1) return {hertz_transform(q), hertz_transform_derivative(q)};
  const double s = std::sin(q), c = std::cos(q), q2 = q * q, q3 = q2 * q;
  const double j1 = s / q2 - c / q, j2 = (3.0 / q3 - 1.0 / q) * s - 3.0 * c / q2;
  return {3.0 * j1 / q, -3.0 * j2 / q};
}

double hertz_transform_derivative(double q) {
  const double sign = q < 0.0 ? -1.0 : 1.0;
  q = std::abs(q);
  if (q < 0.1) { // −3 j2(q)/q = −q/5 + q³/70 − q⁵/2520 + q⁷/166320 − …
    const double q2 = q * q;
    return sign * (-q / 5.0) * (1.0 - q2 / 14.0 * (1.0 - q2 / 36.0 * (1.0 - q2 / 66.0)));
  }
  const double j2 = (3.0 / (q * q * q) - 1.0 / q) * std::sin(q) - 3.0 * std::cos(q) / (q * q);
  return sign * (-3.0 * j2 / q);
}

double hertz_modal_load(const BendingPlate& p, int m, int n, double x0, double y0, double c) {
  require(c >= 0.0 && x0 - c >= 0.0 && x0 + c <= p.a && y0 - c >= 0.0 && y0 + c <= p.b,
          "the contact circle must lie inside the plate");
  const double al = m * pi / p.a, be = n * pi / p.b;
  return std::sin(al * x0) * std::sin(be * y0) * hertz_transform(std::hypot(al, be) * c);
}

// ---------------------------------------------------------------------------------------------------
// Modes
// ---------------------------------------------------------------------------------------------------
ModalPlate::ModalPlate(const BendingPlate& plate, Truncation truncation, double x0, double y0,
                       Expansion expansion, std::optional<Truncation> coupled)
    : plate_(plate), truncation_(truncation), coupled_(coupled), x0_(x0), y0_(y0) {
  require(plate.a > 0.0 && plate.b > 0.0 && plate.I0 > 0.0 && plate.I2 > 0.0, "invalid plate");
  require(truncation.M >= 1 && truncation.N >= 1, "truncation M, N must be at least 1");
  require(x0 > 0.0 && x0 < plate.a && y0 > 0.0 && y0 < plate.b, "impact point outside the plate");
  const bool orthotropic = is_specially_orthotropic(plate);
  require(expansion != Expansion::navier || orthotropic,
          "Navier blocks need a specially orthotropic plate (D16 = D26 = F45 = 0)");
  ritz_ = expansion == Expansion::ritz || expansion == Expansion::ritz_trigonometric ||
          (expansion == Expansion::automatic && !orthotropic);
  const int M = truncation.M, N = truncation.N;
  if (!ritz_) {
    for (int m = 1; m <= M; ++m)
      for (int n = 1; n <= N; ++n)
        add_block(plate_, {{Unknown::w, m, n}, {Unknown::theta_x, m, n}, {Unknown::theta_y, m, n}});
    return;
  }
  // Ritz: the coupled blocks hold m ≤ M1, n ≤ N1; the remaining terms up to (M, N) are Navier blocks
  // of the plate without D16, D26, F45 (the hybrid: exact as M1, N1 grow, see the header).
  const Truncation dense = coupled_ ? *coupled_ : truncation;
  require(dense.M >= 1 && dense.N >= 1 && dense.M <= M && dense.N <= N,
          "the coupled truncation must lie within the total one");
  const bool edge_functions = expansion != Expansion::ritz_trigonometric;
  for (int parity = 0; parity < 2; ++parity) { // symmetric, then antisymmetric under the 180° rotation
    std::vector<BasisFunction> basis;
    for (int m = 1; m <= dense.M; ++m)
      for (int n = 1; n <= dense.N; ++n)
        if ((m + n) % 2 == parity) basis.push_back({Unknown::w, m, n});
    for (int m = 0; m <= dense.M; ++m)
      for (int n = 1; n <= dense.N; ++n)
        if ((m + n) % 2 == parity) basis.push_back({Unknown::theta_x, m, n});
    for (int m = 1; m <= dense.M; ++m)
      for (int n = 0; n <= dense.N; ++n)
        if ((m + n) % 2 == parity) basis.push_back({Unknown::theta_y, m, n});
    if (edge_functions) // sin(πs/L), sin(2πs/L) along the free direction: θx,x ≠ 0 on x = 0, a (κy on
                        // y-edges)
      for (int k = 1; k <= 2; ++k) {
        for (int n = 1; n <= dense.N; ++n)
          if ((k + n + 1) % 2 == parity) basis.push_back({Unknown::theta_x, k, n, true});
        for (int m = 1; m <= dense.M; ++m)
          if ((m + k + 1) % 2 == parity) basis.push_back({Unknown::theta_y, m, k, true});
      }
    add_block(plate_, basis);
  }
  BendingPlate uncoupled = plate_;
  uncoupled.D(0, 2) = uncoupled.D(2, 0) = uncoupled.D(1, 2) = uncoupled.D(2, 1) = 0.0;
  uncoupled.F(0, 1) = uncoupled.F(1, 0) = 0.0;
  for (int m = 1; m <= M; ++m)
    for (int n = 1; n <= N; ++n)
      if (m > dense.M || n > dense.N)
        add_block(uncoupled, {{Unknown::w, m, n}, {Unknown::theta_x, m, n}, {Unknown::theta_y, m, n}});
}

void ModalPlate::add_block(const BendingPlate& plate, const std::vector<BasisFunction>& basis) {
  // w-functions come first in every block: their values at the impact point decide whether the block
  // is excited at all.
  std::vector<double> kappa, a;
  for (const BasisFunction& f : basis) {
    if (f.unknown != Unknown::w) break;
    const double al = f.m * pi / plate_.a, be = f.n * pi / plate_.b;
    kappa.push_back(std::hypot(al, be));
    a.push_back(std::sin(al * x0_) * std::sin(be * y0_));
  }
  if (std::none_of(a.begin(), a.end(), [](double v) { return std::abs(v) > unloaded; })) return;

  const RitzMatrices km = ritz_matrices(plate, basis);
  // K φ = ω² M φ, φᵀ M φ = 1 (M is diagonal except between the edge functions and the cosines).
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(km.K, km.M);
  require(eig.info() == Eigen::Success, "eigen solver failed");
  const auto terms = static_cast<Eigen::Index>(kappa.size());
  const Eigen::MatrixXd phi_w = eig.eigenvectors().topRows(terms);

  Block blk;
  blk.first_term = static_cast<int>(kappa_.size());
  blk.term_count = static_cast<int>(terms);
  blk.first_mode = static_cast<int>(omega2_.size());
  blk.mode_count = static_cast<int>(phi_w.cols());
  blk.phi_offset = phi_.size();
  blocks_.push_back(blk);
  kappa_.insert(kappa_.end(), kappa.begin(), kappa.end());
  a_.insert(a_.end(), a.begin(), a.end());
  const Eigen::Map<const Eigen::VectorXd> a_vec(a.data(), terms);
  for (Eigen::Index j = 0; j < phi_w.cols(); ++j) {
    require(eig.eigenvalues()(j) > 0.0, "non-positive stiffness eigenvalue");
    omega2_.push_back(eig.eigenvalues()(j));
    e_.push_back(phi_w.col(j).dot(a_vec));
  }
  phi_.insert(phi_.end(), phi_w.data(), phi_w.data() + phi_w.size());
}

std::vector<double> ModalPlate::frequencies_hz() const {
  std::vector<double> f;
  f.reserve(omega2_.size());
  for (const double w2 : omega2_)
    f.push_back(std::sqrt(w2) / (2.0 * pi));
  std::sort(f.begin(), f.end());
  return f;
}

double ModalPlate::static_compliance(double c) const {
  // w(x0, y0) = Σ_j e_j s_j / ω_j²,  s_j = Σ_t φ_tj a_t P(κ_t c).
  double w = 0.0;
  for (const Block& blk : blocks_) {
    for (int j = 0; j < blk.mode_count; ++j) {
      double s = 0.0;
      for (int t = 0; t < blk.term_count; ++t) {
        const auto ti = static_cast<std::size_t>(blk.first_term + t);
        s += phi_[blk.phi_offset + static_cast<std::size_t>(j * blk.term_count + t)] * a_[ti] *
             hertz_transform(kappa_[ti] * c);
      }
      const auto jj = static_cast<std::size_t>(blk.first_mode + j);
      w += e_[jj] * s / omega2_[jj];
    }
  }
  return w;
}

// ---------------------------------------------------------------------------------------------------
// Impact
// ---------------------------------------------------------------------------------------------------
namespace {

// One time step of every mode q̈ + ω² q = f(t) (unit modal mass), written as
//     q_{n+1} = q̂ + g f_{n+1},     q̂ = cq q_n + cv q̇_n + ca q̈_n + cf f_n,
//     q̇_{n+1} = dq q_n + dv q̇_n + da q̈_n + df f_n + dg f_{n+1}.
// Exact stepping: the force is linear over the step and each mode is integrated exactly
// (x = ωΔt): q_{n+1} = cos x q + (sin x/ω) q̇ + (sin x/(ω x) − cos x)/ω² f_n + (1 − sin x/x)/ω² f_{n+1}.
// Newmark average acceleration: g = 1/(ω² + 4/Δt²) and the usual predictor (acceleration kept).
struct ModeStep {
  double g = 0.0;
  double cq = 0.0, cv = 0.0, ca = 0.0, cf = 0.0;
  double dq = 0.0, dv = 0.0, da = 0.0, df = 0.0, dg = 0.0;
};

ModeStep mode_step(double omega2, double dt, Integrator integrator) {
  ModeStep m;
  if (integrator == Integrator::newmark) {
    const double c0 = 4.0 / (dt * dt), c2 = 4.0 / dt; // β = 1/4, γ = 1/2, c3 = 1/(2β) − 1 = 1
    m.g = 1.0 / (omega2 + c0);
    m.cq = c0 * m.g;
    m.cv = c2 * m.g;
    m.ca = m.g;
    // q̈_{n+1} = c0 (q_{n+1} − q_n) − c2 q̇_n − q̈_n;  q̇_{n+1} = q̇_n + Δt/2 (q̈_n + q̈_{n+1}).
    return m;
  }
  const double w = std::sqrt(omega2), x = w * dt, cx = std::cos(x), sx = std::sin(x);
  double a = 0.0, b = 0.0, p = 0.0,
         r = 0.0; // (1 − sin x/x)/x², (sin x/x − cos x)/x², (1 − cos x)/x², (sin x/x − (1 − cos x)/x²)
  if (x < 0.05) { // series, no cancellation
    const double x2 = x * x;
    a = 1.0 / 6.0 - x2 / 120.0 + x2 * x2 / 5040.0;
    b = 1.0 / 3.0 - x2 / 30.0 + x2 * x2 / 840.0;
    p = 0.5 - x2 / 24.0 + x2 * x2 / 720.0;
    r = 0.5 - x2 / 8.0 + x2 * x2 / 144.0;
  } else {
    const double x2 = x * x;
    a = (1.0 - sx / x) / x2;
    b = (sx / x - cx) / x2;
    p = (1.0 - cx) / x2;
    r = sx / x - p;
  }
  m.g = a * dt * dt;
  m.cq = cx;
  m.cv = sx / w;
  m.cf = b * dt * dt;
  m.dq = -w * sx;
  m.dv = cx;
  m.df = r * dt;
  m.dg = p * dt;
  return m;
}

// The plate seen from the contact during one step: ws(F, c) = ŵs(c) + C(c) F for a contact radius c,
// given the modal predictors q̂.
class ContactPointResponse {
public:
  ContactPointResponse(const ModalPlate& plate, LoadModel load, const std::vector<ModeStep>& steps)
      : plate_(plate), load_(load), steps_(steps), z_(plate.kappa().size(), 0.0), u_(plate.kappa().size()),
        du_(plate.kappa().size()), s_(plate.omega2().size()), ds_(plate.omega2().size()) {
    // Centre measure: C(c) = Σ_j e_j g_j s_j(c) = Σ_t z_t a_t P(κ_t c), z_t = Σ_j φ_tj e_j g_j.
    for (const auto& blk : plate.blocks())
      for (int j = 0; j < blk.mode_count; ++j) {
        const auto jj = static_cast<std::size_t>(blk.first_mode + j);
        for (int t = 0; t < blk.term_count; ++t)
          z_[static_cast<std::size_t>(blk.first_term + t)] +=
              phi(blk, t, j) * plate.mode_value()[jj] * steps[jj].g;
      }
  }

  struct Value {
    double ws_hat = 0.0, C = 0.0;   // m, m/N
    double dws_hat = 0.0, dC = 0.0; // derivatives with respect to c
  };
  // ŵs, C and their c-derivatives for the predictor q_hat and contact radius c (0: point load).
  Value at(const std::vector<double>& q_hat, double c) {
    Value v;
    const auto& a = plate_.load_point_value();
    const auto& kappa = plate_.kappa();
    if (load_ != LoadModel::hertz_pressure_work_conjugate) {
      for (std::size_t j = 0; j < q_hat.size(); ++j)
        v.ws_hat += plate_.mode_value()[j] * q_hat[j];
      for (std::size_t t = 0; t < z_.size(); ++t) {
        const double za = z_[t] * a[t];
        if (za == 0.0) continue;
        const auto [P, dP] =
            load_ == LoadModel::point ? std::pair{1.0, 0.0} : hertz_transform_and_derivative(kappa[t] * c);
        v.C += za * P;
        v.dC += za * kappa[t] * dP;
      }
      return v;
    }
    // Work-conjugate measure ws = Σ_j s_j(c) q_j: ŵs = Σ s_j q̂_j, C = Σ s_j² g_j.
    load_vectors(c, true);
    for (std::size_t j = 0; j < q_hat.size(); ++j) {
      v.ws_hat += s_[j] * q_hat[j];
      v.dws_hat += ds_[j] * q_hat[j];
      v.C += s_[j] * s_[j] * steps_[j].g;
      v.dC += 2.0 * s_[j] * ds_[j] * steps_[j].g;
    }
    return v;
  }

  // Modal loads per unit force s_j(c) = Σ_t φ_tj a_t P(κ_t c) (and ds_j/dc when asked).
  const std::vector<double>& load_vectors(double c, bool derivative = false) {
    const auto& a = plate_.load_point_value();
    const auto& kappa = plate_.kappa();
    for (std::size_t t = 0; t < u_.size(); ++t) {
      if (load_ == LoadModel::point) {
        u_[t] = a[t];
        du_[t] = 0.0;
      } else {
        const auto [P, dP] = hertz_transform_and_derivative(kappa[t] * c);
        u_[t] = a[t] * P;
        du_[t] = a[t] * kappa[t] * dP;
      }
    }
    for (const auto& blk : plate_.blocks()) {
      if (blk.term_count == 1) { // Navier block: one w-term, three modes
        for (int j = 0; j < blk.mode_count; ++j) {
          const double phi_j = phi(blk, 0, j);
          const auto jj = static_cast<std::size_t>(blk.first_mode + j),
                     t = static_cast<std::size_t>(blk.first_term);
          s_[jj] = phi_j * u_[t];
          if (derivative) ds_[jj] = phi_j * du_[t];
        }
        continue;
      }
      const Eigen::Map<const Eigen::MatrixXd> phi_b(plate_.phi().data() + blk.phi_offset, blk.term_count,
                                                    blk.mode_count);
      Eigen::Map<Eigen::VectorXd>(s_.data() + blk.first_mode, blk.mode_count).noalias() =
          phi_b.transpose() * Eigen::Map<const Eigen::VectorXd>(u_.data() + blk.first_term, blk.term_count);
      if (derivative)
        Eigen::Map<Eigen::VectorXd>(ds_.data() + blk.first_mode, blk.mode_count).noalias() =
            phi_b.transpose() *
            Eigen::Map<const Eigen::VectorXd>(du_.data() + blk.first_term, blk.term_count);
    }
    return s_;
  }

private:
  [[nodiscard]] double phi(const ModalPlate::Block& blk, int t, int j) const {
    return plate_.phi()[blk.phi_offset + static_cast<std::size_t>(j * blk.term_count + t)];
  }

  const ModalPlate& plate_;
  LoadModel load_;
  const std::vector<ModeStep>& steps_;
  std::vector<double> z_, u_, du_, s_, ds_;
};

} // namespace

ImpactResult simulate_impact(const ModalPlate& plate, const Impactor& imp, const ContactLaw& law_in,
                             LoadModel load, const TimeStepping& time) {
  require(time.dt > 0.0 && imp.mass > 0.0 && imp.radius > 0.0 && imp.velocity > 0.0 && law_in.k > 0.0,
          "invalid impact data");
  const double dt = time.dt;
  const bool newmark = time.integrator == Integrator::newmark;
  const bool point = load == LoadModel::point;
  const bool conjugate = load == LoadModel::hertz_pressure_work_conjugate;
  const auto& omega2 = plate.omega2();
  const auto& e = plate.mode_value();
  const std::size_t modes = omega2.size();
  std::vector<ModeStep> steps;
  steps.reserve(modes);
  for (const double w2 : omega2)
    steps.push_back(mode_step(w2, dt, time.integrator));
  ContactPointResponse response(plate, load, steps);
  const auto contact_radius = [&](double alpha) {
    return point ? 0.0 : std::sqrt(imp.radius * std::max(alpha, 0.0));
  };
  const auto check_circle = [&](double c) {
    require(plate.x0() - c >= 0.0 && plate.x0() + c <= plate.plate().a && plate.y0() - c >= 0.0 &&
                plate.y0() + c <= plate.plate().b,
            "the contact circle left the plate");
  };

  IndentationLaw law(law_in);
  // Impactor m ẅ = −F: ŵi and λ such that wi_{n+1} = ŵi − λ F_{n+1}.
  const double lambda = (newmark ? 0.25 : 1.0 / 6.0) * dt * dt / imp.mass;
  std::vector<double> q(modes, 0.0), v(modes, 0.0), acc(modes, 0.0), f(modes, 0.0), q_hat(modes);
  double wi = 0.0, vi = imp.velocity, ai = 0.0; // impactor
  double force = 0.0, alpha = 0.0, alpha_previous = 0.0, ws = 0.0;

  ImpactResult r;
  std::vector<double> alpha_history{0.0};
  long peak_step = 0, last_contact_step = -1;
  bool in_contact = false;
  const auto record = [&](long step) {
    if (time.history_every <= 0 || step % time.history_every != 0) return;
    double energy = 0.0;
    for (std::size_t j = 0; j < modes; ++j)
      energy += 0.5 * (v[j] * v[j] + omega2[j] * q[j] * q[j]);
    r.history.push_back({static_cast<double>(step) * dt, force, alpha, ws, wi, vi, energy});
  };
  record(0);

  for (long step = 1;; ++step) {
    const double t = static_cast<double>(step) * dt;
    if (time.end && t > *time.end + 1e-9 * dt) break;
    require(step < 50'000'000, "too many steps");

    // 1. Predictors without the new contact force (f holds the modal forces at the start of the step).
    for (std::size_t j = 0; j < modes; ++j) {
      const ModeStep& m = steps[j];
      q_hat[j] = m.cq * q[j] + m.cv * v[j] + m.ca * acc[j] + m.cf * f[j];
    }
    const double wi_hat =
        newmark ? wi + dt * vi + 0.25 * dt * dt * ai : wi + dt * vi - dt * dt * force / (3.0 * imp.mass);

    // 2. Scalar contact problem g(α) = α − ŵi + ŵs(c) + (λ + C(c)) F(α) = 0 with c = √(Rα) at the new
    //    time, solved by Newton kept inside a bracket [α where F = 0, α where g ≥ 0].
    const double alpha_free = wi_hat - response.at(q_hat, contact_radius(alpha)).ws_hat; // c of the last step
    double force_new = 0.0, alpha_new = alpha_free;
    if (law.force(alpha_free) > 0.0 || conjugate) {
      double lo = law.permanent_indentation(), hi = std::max(alpha_free, lo);
      const auto g_of = [&](double x, double& dg) {
        const double c = contact_radius(x);
        const auto val = response.at(q_hat, c);
        const double F = law.force(x), dc = c > 0.0 ? imp.radius / (2.0 * c) : 0.0;
        dg = 1.0 + (val.dws_hat + val.dC * F) * dc + (lambda + val.C) * law.stiffness(x);
        return x - wi_hat + val.ws_hat + (lambda + val.C) * F;
      };
      double dg = 1.0;
      while (g_of(hi, dg) < 0.0) // only the work-conjugate measure can need a wider bracket
        hi += std::max(hi - lo, 1e-12);
      double x = std::clamp(2.0 * alpha - alpha_previous, lo, hi); // extrapolated from the last steps
      if (!(x > lo)) x = hi;
      for (int it = 1; it <= 200; ++it) {
        r.newton_iterations_max = std::max(r.newton_iterations_max, it);
        const double g = g_of(x, dg);
        const double step_newton = g / dg;
        if (std::abs(step_newton) <= 1e-13 * hi) { // round-off level of ŵi − ŵs
          x -= step_newton;
          break;
        }
        (g > 0.0 ? hi : lo) = x;
        x = (x - step_newton > lo && x - step_newton < hi) ? x - step_newton : 0.5 * (lo + hi);
        if (hi - lo <= 1e-13 * hi) break;
      }
      if (law.force(x) > 0.0) {
        alpha_new = x;
        force_new = law.force(x);
      }
    }
    const double radius = force_new > 0.0 ? contact_radius(alpha_new) : 0.0;
    check_circle(radius);

    // 3. Update of plate (modal loads at the new contact radius) and impactor.
    const std::vector<double>& s = response.load_vectors(radius);
    ws = 0.0;
    for (std::size_t j = 0; j < modes; ++j) {
      const ModeStep& m = steps[j];
      const double f_new = force_new * s[j];
      const double q_new = q_hat[j] + m.g * f_new;
      if (newmark) {
        const double acc_new = 4.0 / (dt * dt) * (q_new - q[j]) - 4.0 / dt * v[j] - acc[j];
        v[j] += 0.5 * dt * (acc[j] + acc_new);
        acc[j] = acc_new;
      } else {
        v[j] = m.dq * q[j] + m.dv * v[j] + m.df * f[j] + m.dg * f_new;
      }
      q[j] = q_new;
      f[j] = f_new;
      ws += (conjugate ? s[j] : e[j]) * q_new;
    }
    wi = wi_hat - lambda * force_new;
    if (newmark) {
      const double ai_new = -force_new / imp.mass;
      vi += 0.5 * dt * (ai + ai_new);
      ai = ai_new;
    } else {
      vi -= 0.5 * dt * (force + force_new) / imp.mass;
    }
    force = force_new;
    alpha_previous = alpha;
    alpha = wi - ws;
    law.commit(alpha);
    alpha_history.push_back(alpha);
    record(step);
    r.steps = step;

    // 4. Episodes and the first contact.
    if (force > 0.0) {
      if (!in_contact) ++r.contacts;
      in_contact = true;
      if (r.contacts == 1) {
        last_contact_step = step;
        if (force > r.sampled_peak_force) {
          r.sampled_peak_force = force;
          r.sampled_time_of_peak = t;
          peak_step = step;
        }
      }
    } else if (in_contact) {
      in_contact = false;
      if (r.contacts == 1) {
        r.separated = true;
        const double alpha0 = law.permanent_indentation();
        // α − α0 crosses zero between last_contact_step and step: linear interpolation.
        const double above = alpha_history[static_cast<std::size_t>(last_contact_step)] - alpha0;
        const double below = alpha - alpha0;
        r.contact_duration = (static_cast<double>(last_contact_step) + above / (above - below)) * dt;
        r.sampled_contact_duration = static_cast<double>(last_contact_step) * dt;
      }
      if (!time.end) break;
    }
  }

  // Continuous-time peak of the first contact from the indentation samples around its largest force.
  require(peak_step > 0, "no contact");
  const auto k = static_cast<std::size_t>(peak_step);
  const bool interior = k + 1 < alpha_history.size();
  const auto [shift, alpha_max] =
      interior ? parabola_vertex(alpha_history[k - 1], alpha_history[k], alpha_history[k + 1])
               : std::pair{0.0, alpha_history[k]};
  r.max_indentation = alpha_max;
  r.peak_force = law_in.k * std::pow(alpha_max, 1.5);
  r.time_of_peak = (static_cast<double>(peak_step) + shift) * dt;
  r.max_contact_radius = std::sqrt(imp.radius * alpha_max);
  r.permanent_indentation = law.permanent_indentation();
  r.rebound_velocity = -vi;
  return r;
}

double rigid_target_peak_force(double mass, double velocity, double k) {
  return std::pow(1.25 * mass * velocity * velocity, 0.6) * std::pow(k, 0.4);
}

double rigid_target_contact_time(double mass, double velocity, double k) {
  // αm = (5 m v0²/(4k))^(2/5); T = 2 αm/v0 ∫₀¹ (1 − x^(5/2))^(−½) dx, the integral = (2/5) B(2/5, 1/2).
  const double alpha_m = std::pow(1.25 * mass * velocity * velocity / k, 0.4);
  const double integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  return 2.0 * alpha_m / velocity * integral;
}

} // namespace plyimpact::test::navier_impact
