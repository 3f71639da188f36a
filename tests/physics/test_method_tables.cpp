// Method tables: every table's order conditions, checked numerically on linear flows
// (host only, suite "methods").
//
// For H = A + eps B a splitting method is one step Phi(h, eps) = product of exp(a_i h A)
// and exp(b_i h eps B). Its modified generator log(Phi)/h - (A + eps B) is a power series
// in eps whose eps^k coefficient c_k(h) is O(h^{p_k}), (p_1, p_2, p_3) the method's orders
// in eps (Method::eps_orders; a composition of order p has p_k = p). The test takes
// random non-commuting 4x4 matrices A and B, computes Phi exactly (Taylor series in
// 113-bit __float128, far below every error measured), takes c_1, c_2, c_3 from a discrete
// Fourier transform over 16 complex eps on a circle, and measures the slope of log c_k
// against log h between h = 0.1 and 0.05 (0.4 and 0.2 for the methods with an eps h^10
// term, whose size at h = 0.05 is below the rounding of the double coefficients). It must
// be the nominal p_k (within 0.3) for every power of eps that Method::eps_orders names,
// and at least the last entry for the powers beyond. RKN methods (Method::rkn: the orders need {B,{B,{B,A}}} = 0) take a B
// with B^2 = 0, which makes [B,[B,[B,A]]] vanish as it does for B = V(X). A force-gradient kick
// (Method::gradient) is exp(eps b h B + eps^2 g h^3 C) with C = [B,[A,B]], the linear-flow image of
// the gradient of |grad V|^2 (it commutes with B when B^2 = 0, as the gradient kick commutes with
// the kick). The stability limits in the tables are checked against the harmonic oscillator.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "arnoldweb/methods.hpp"

using namespace arnoldweb;

namespace {

#ifdef __SIZEOF_FLOAT128__
using q = __float128;  // GCC and Clang on x86-64
#else
using q = long double;  // IEEE quad on AArch64; elsewhere the eps h^10 slopes may blur
#endif
struct C {
  q re = 0, im = 0;
};
C operator+(C a, C b) { return {a.re + b.re, a.im + b.im}; }
C operator-(C a, C b) { return {a.re - b.re, a.im - b.im}; }
C operator*(C a, C b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

constexpr int kN = 4;
struct Mat {
  C v[kN][kN];
};
Mat identity() {
  Mat m;
  for (int i = 0; i < kN; ++i) m.v[i][i].re = 1;
  return m;
}
Mat operator*(const Mat& a, const Mat& b) {
  Mat r;
  for (int i = 0; i < kN; ++i)
    for (int k = 0; k < kN; ++k)
      for (int j = 0; j < kN; ++j) r.v[i][j] = r.v[i][j] + a.v[i][k] * b.v[k][j];
  return r;
}
Mat operator+(const Mat& a, const Mat& b) {
  Mat r;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) r.v[i][j] = a.v[i][j] + b.v[i][j];
  return r;
}
Mat scaled(const Mat& a, C s) {
  Mat r;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) r.v[i][j] = a.v[i][j] * s;
  return r;
}
double norm(const Mat& a) {  // max-abs entry, as a double
  double n = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) n = std::max(n, std::hypot(double(a.v[i][j].re), double(a.v[i][j].im)));
  return n;
}

// exp of a matrix of norm below ~1: Taylor series to 1e-34
Mat expm(const Mat& x) {
  Mat sum = identity(), term = identity();
  for (int k = 1; k < 60; ++k) {
    term = scaled(term * x, C{q(1) / q(k), 0});
    sum = sum + term;
    if (norm(term) < 1e-36) break;
  }
  return sum;
}

// log of a matrix near the identity: log(I + X) = X - X^2/2 + X^3/3 - ...
Mat logm(const Mat& m) {
  Mat x = m + scaled(identity(), C{-1, 0});
  Mat sum, power = identity();
  for (int k = 1; k < 400; ++k) {
    power = power * x;
    const Mat term = scaled(power, C{(k % 2 ? q(1) : q(-1)) / q(k), 0});
    sum = sum + term;
    if (norm(term) < 1e-36) break;
  }
  return sum;
}

// deterministic uniform numbers in [-1, 1) (a 64-bit LCG: the same matrices everywhere)
struct Lcg {
  std::uint64_t s = 20261123;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) / 4503599627370496.0 - 1.0;
  }
};

struct Pair {
  Mat a, b;
};

// A and B generic (every entry random), or B = U V^T with V^T U = 0, so B^2 = 0.
Pair matrices(bool nilpotent) {
  Lcg r;
  Pair p;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) p.a.v[i][j].re = r.next();
  if (!nilpotent) {
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) p.b.v[i][j].re = r.next();
    return p;
  }
  // U = (u1 u2); V = (v1 v2) with v_i orthogonal to u1 and u2 (Gram-Schmidt)
  double u[2][kN], v[2][kN];
  for (auto& w : u)
    for (double& x : w) x = r.next();
  for (auto& w : v)
    for (double& x : w) x = r.next();
  double e[2][kN];  // orthonormal basis of span(u1, u2)
  for (int a = 0; a < 2; ++a) {
    for (int i = 0; i < kN; ++i) e[a][i] = u[a][i];
    for (int c = 0; c < a; ++c) {
      double d = 0;
      for (int i = 0; i < kN; ++i) d += e[c][i] * u[a][i];
      for (int i = 0; i < kN; ++i) e[a][i] -= d * e[c][i];
    }
    double n = 0;
    for (int i = 0; i < kN; ++i) n += e[a][i] * e[a][i];
    for (int i = 0; i < kN; ++i) e[a][i] /= std::sqrt(n);
  }
  for (auto& w : v)
    for (int c = 0; c < 2; ++c) {
      double d = 0;
      for (int i = 0; i < kN; ++i) d += e[c][i] * w[i];
      for (int i = 0; i < kN; ++i) w[i] -= d * e[c][i];
    }
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) p.b.v[i][j].re = q(u[0][i]) * q(v[0][j]) + q(u[1][i]) * q(v[1][j]);
  return p;
}

// One step of the table at step h and perturbation eps.
Mat step(const Method& m, const Pair& p, q h, C eps) {
  Mat phi = identity();
  auto drift = [&](double a) { phi = expm(scaled(p.a, C{q(a) * h, 0})) * phi; };
  // C = [B,[A,B]] = 2 BAB - BBA - ABB
  const Mat bab = p.b * p.a * p.b, bba = p.b * p.b * p.a, abb = p.a * p.b * p.b;
  const Mat c = bab + bab + scaled(bba, C{-1, 0}) + scaled(abb, C{-1, 0});
  auto kick = [&](double b) { phi = expm(scaled(p.b, eps * C{q(b) * h, 0})) * phi; };
  auto gradient_kick = [&](double b, double g) {
    phi = expm(scaled(p.b, eps * C{q(b) * h, 0}) + scaled(c, eps * eps * C{q(g) * h * h * h, 0})) * phi;
  };
  if (!m.gradient.empty()) {  // kick-first
    gradient_kick(m.kick[0], m.gradient[0]);
    for (int i = 0; i < m.stages; ++i) {
      drift(m.drift[i]);
      gradient_kick(m.kick[i + 1], m.gradient[i + 1]);
    }
  } else if (m.kick_first) {
    kick(m.kick[0]);
    for (int i = 0; i < m.stages; ++i) {
      drift(m.drift[i]);
      kick(m.kick[i + 1]);
    }
  } else {
    drift(m.drift[0]);
    for (int i = 1; i <= m.stages; ++i) {
      kick(m.kick[i]);
      drift(m.drift[i]);
    }
  }
  return phi;
}

// |c_k(h)| for k = 1, 2, 3: eps^k coefficients of log(Phi)/h - (A + eps B)
// against (sum a) A + eps (sum b) B: the sums of the double coefficients differ from 1 by
// ~1e-17, a constant term that would hide the high orders
std::vector<double> eps_coefficients(const Method& m, const Pair& p, double h) {
  q sa = 0, sb = 0;
  for (double a : m.drift) sa += a;
  for (double b : m.kick) sb += b;
  constexpr int kPoints = 16;
  const long double rho = 0.5L;
  std::vector<Mat> c(4);
  for (int j = 0; j < kPoints; ++j) {
    const long double t = 2 * 3.14159265358979323846264338327950288L * j / kPoints;
    const C eps{q(rho * std::cos(t)), q(rho * std::sin(t))};
    Mat g = scaled(logm(step(m, p, q(h), eps)), C{q(1) / q(h), 0});
    g = g + scaled(p.a, C{-sa, 0}) + scaled(p.b, C{0, 0} - eps * C{sb, 0});
    C inv{1, 0};  // eps^-k
    const C eps_inv{q(std::cos(t) / rho), q(-std::sin(t) / rho)};
    for (int k = 1; k <= 3; ++k) {
      inv = inv * eps_inv;
      c[k] = c[k] + scaled(g, inv * C{q(1) / q(kPoints), 0});
    }
  }
  return {norm(c[1]), norm(c[2]), norm(c[3])};
}

// Measured slopes of log c_k against log h, k = 1..3.
std::vector<double> eps_slopes(const Method& m, double h, std::vector<double>* sizes = nullptr) {
  const Pair p = matrices(m.rkn);
  const std::vector<double> big = eps_coefficients(m, p, h), small = eps_coefficients(m, p, h / 2);
  std::vector<double> s;
  for (int k = 0; k < 3; ++k) s.push_back(std::log2(big[k] / small[k]));
  if (sizes) *sizes = small;
  return s;
}

// The order the table promises for eps^k (k = 1, 2, ...).
int promised(const Method& m, int k) {
  return m.eps_orders[std::min<std::size_t>(k, m.eps_orders.size()) - 1];
}

}  // namespace

TEST_SUITE("methods") {
  TEST_CASE("every table is a consistent palindrome: drifts and kicks each sum to 1") {
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      REQUIRE(m.stages >= 1);
      REQUIRE(m.stages <= 16);  // AW_MAX_STAGES
      REQUIRE(m.drift.size() == static_cast<std::size_t>(m.kick_first ? m.stages : m.stages + 1));
      REQUIRE(m.kick.size() == static_cast<std::size_t>(m.stages + 1));
      if (!m.kick_first) CHECK(m.kick[0] == 0.0);
      long double sa = 0, sb = 0;
      for (double a : m.drift) sa += a;
      for (double b : m.kick) sb += b;
      CHECK(std::fabs(static_cast<double>(sa - 1)) < 4e-15);
      CHECK(std::fabs(static_cast<double>(sb - 1)) < 4e-15);
      for (std::size_t i = 0; i < m.drift.size(); ++i)
        CHECK(std::fabs(m.drift[i] - m.drift[m.drift.size() - 1 - i]) < 1e-15);
      const std::size_t k0 = m.kick_first ? 0 : 1;
      for (std::size_t i = k0; i < m.kick.size(); ++i)
        CHECK(std::fabs(m.kick[i] - m.kick[m.kick.size() - 1 - (i - k0)]) < 1e-15);
      if (!m.gradient.empty()) {
        CHECK(m.kick_first);  // the gradient stepper is kick-first
        CHECK(m.rkn);         // the gradient kick commutes with the kick only when V depends on X alone
        REQUIRE(m.gradient.size() == m.kick.size());
        for (std::size_t i = 0; i < m.gradient.size(); ++i)
          CHECK(std::fabs(m.gradient[i] - m.gradient[m.gradient.size() - 1 - i]) < 1e-15);
        CHECK(m.force_gradient());
      }
      REQUIRE(!m.eps_orders.empty());
      int lowest = m.eps_orders[0];
      for (int p : m.eps_orders) lowest = std::min(lowest, p);
      CHECK(m.order == lowest);
      CHECK(!m.family.empty());
    }
  }

  TEST_CASE("every table meets its order conditions in h and in eps (linear flows, 113-bit arithmetic)") {
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      std::vector<double> sizes;
      // eps h^10 terms are below the round-off of the double coefficients (~1e-20 at
      // h = 0.05): measure them at h = 0.4 and 0.2, where they are still asymptotic
      const int highest = *std::max_element(m.eps_orders.begin(), m.eps_orders.end());
      const double h = highest >= 10 ? 0.4 : 0.1;
      const std::vector<double> s = eps_slopes(m, h, &sizes);
      std::printf("  %-13s %-10s %s  h = %.1f, %.2f  eps^1 %5.2f (%.1e)  eps^2 %5.2f (%.1e)  eps^3 %5.2f (%.1e)\n",
                  m.name.c_str(), eps_order_string(m).c_str(), m.rkn ? "B^2=0" : "     ", h, h / 2, s[0], sizes[0], s[1],
                  sizes[1], s[2], sizes[2]);
      for (int k = 1; k <= 3; ++k) {
        CAPTURE(k);
        CHECK(sizes[k - 1] > 1e-30);  // measured, not round-off
        if (k <= static_cast<int>(m.eps_orders.size()))
          CHECK(std::fabs(s[k - 1] - promised(m, k)) <= 0.3);
        else
          CHECK(s[k - 1] >= promised(m, k) - 0.3);
      }
    }
  }

  TEST_CASE("every table's stability limit is the harmonic oscillator's (|trace| of the step matrix reaches 2)") {
    // V = w^2 x^2 / 2, t = h w, y = w x: drift y += a t p; kick p += (-b t + 2 g t^3) y (the gradient
    // of |F|^2 = w^4 x^2 is 2 w^4 x). Stable while |trace| < 2 (the determinant is 1).
    auto trace = [](const Method& m, double t) {
      double a11 = 1, a12 = 0, a21 = 0, a22 = 1;  // the step matrix acting on (y, p)
      auto drift = [&](double a) {
        a11 += a * t * a21;
        a12 += a * t * a22;
      };
      auto kick = [&](std::size_t i) {
        const double g = m.gradient.empty() ? 0.0 : m.gradient[i];
        const double k = -m.kick[i] * t + 2 * g * t * t * t;
        a21 += k * a11;
        a22 += k * a12;
      };
      if (m.kick_first) {
        kick(0);
        for (int i = 0; i < m.stages; ++i) {
          drift(m.drift[i]);
          kick(static_cast<std::size_t>(i) + 1);
        }
      } else {
        drift(m.drift[0]);
        for (int i = 1; i <= m.stages; ++i) {
          kick(static_cast<std::size_t>(i));
          drift(m.drift[i]);
        }
      }
      return a11 + a22;
    };
    for (const Method& m : methods()) {
      CAPTURE(m.name);
      double t = 1e-3;  // first t with |trace| >= 2, then bisection
      while (t < 8 && std::fabs(trace(m, t)) < 2) t += 1e-3;
      double lo = t - 1e-3, hi = t;
      for (int i = 0; i < 50; ++i) {
        const double mid = (lo + hi) / 2;
        (std::fabs(trace(m, mid)) >= 2 ? hi : lo) = mid;
      }
      CHECK(std::fabs(lo - m.stability) < 1e-3);
    }
  }

  TEST_CASE("the check has teeth: a perturbed coefficient or a missing RKN property shows") {
    // ABA(8,6,4) with one drift pair moved by 1e-6 (sums kept): its eps h^8 term becomes eps h^2
    Method m = find_method("aba864");
    m.drift[1] += 1e-6;
    m.drift[2] -= 1e-6;
    m.drift[m.drift.size() - 2] += 1e-6;
    m.drift[m.drift.size() - 3] -= 1e-6;
    CHECK(eps_slopes(m, 0.1)[0] < 2.5);
    // SRKN11b relies on {B,{B,{B,A}}} = 0: with a generic B its eps^3 term is h^4, not h^6
    Method r = find_method("srkn11b");
    r.rkn = false;
    CHECK(eps_slopes(r, 0.1)[2] < 4.5);
    // SBAB3C with its corrector 1% off: the eps^2 h^2 term returns (order 2, not 4)
    Method c = find_method("sbab3c");
    c.gradient.front() *= 1.01;
    c.gradient.back() *= 1.01;
    CHECK(eps_slopes(c, 0.1)[1] < 2.5);
  }

  TEST_CASE("a step forms the Hessian only at the kicks with a gradient term, and costs what it forms") {
    // the stepper (aw_stepper.h) forms it where g != 0, the first and last kick merged across steps
    for (const char* name : {"leapfrog", "yoshida6a", "aba864", "srkn11b"}) {
      CAPTURE(name);
      CHECK(find_method(name).gradient_stages() == 0);
      CHECK(find_method(name).work() == find_method(name).stages);
    }
    // the correctors sit on the end kicks (SBAB_nC) or on the pure gradient kick between steps
    // (SABA_nC); Chin 4A's gradient is on its middle kick: one Hessian a step each
    for (const char* name : {"sbab1c", "sbab2c", "sbab3c", "sbab4c", "saba1c", "saba4c", "chin4a"}) {
      const Method& m = find_method(name);
      CAPTURE(name);
      CHECK(m.gradient_stages() == 1);
      CHECK(m.work() == doctest::Approx(m.stages + (kGradientWork - 1.0)));
    }
    CHECK(find_method("sbab3c").work() == doctest::Approx(3.2));
    CHECK(find_method("chin4a").work() == doctest::Approx(2.2));
    // Omelyan-Mryglod-Folk order 6: gradients on the four inner kicks, none on the merged end kick
    CHECK(find_method("omf6v").gradient_stages() == 4);
    CHECK(find_method("omf6v").work() == doctest::Approx(5.8));
    // a table with gradient terms on every kick pays on every evaluation
    Method every = find_method("chin4a");
    every.gradient = {0.01, 0.02, 0.01};
    CHECK(every.gradient_stages() == 2);
    CHECK(every.work() == doctest::Approx(2 * kGradientWork));
  }
}
