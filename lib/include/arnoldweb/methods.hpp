// arnoldweb: symplectic composition methods as coefficient tables.
// One generic stepper (lib/device/aw_stepper.h) runs every method.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb {

struct Method {
  std::string name;       // scene value of integrator.method
  std::string title;      // human name
  std::string source;     // literature reference
  int order = 0;          // nominal order
  int stages = 0;         // force evaluations per step (merged kicks counted once)
  bool kick_first = true; // K D K ... D K (merged across steps) or D K D ... K D
  // kick_first: drifts a[0..stages-1], kicks b[0..stages]   (b[0] == b[stages] here)
  // drift first: drifts a[0..stages], kicks b[1..stages]    (b[0] unused, 0)
  std::vector<double> drift;  // a_i, fractions of the step
  std::vector<double> kick;   // b_i, fractions of the step
  // Force-gradient (modified-potential) terms, one per kick, or empty: kick i is
  //   P += b_i h F + g_i h^3 grad(sum_k a_k F_k^2)       (F = -grad V, a_k = d^2T/dP_k^2),
  // the flow of the potential b_i V - g_i h^2 |grad V|^2_T. In the notation of Laskar &
  // Robutel and Chin, g_i is the coefficient of h^3 [B,[B,A]] = h^3 {{A,B},B}: a corrector
  // e^{-c h^3 eps^2 {{A,B},B}/2} at both ends of a step is g = c/2 on the first and last kick.
  // These methods are kick-first; the gradient comes from the force's own sin/cos
  // (aw_model_force_hessian).
  std::vector<double> gradient;
  double stability = 0;       // linear stability limit h*omega (harmonic oscillator)
  // Order in h and in eps for H = A + eps B, A = |P|^2/2 (the drift), B = V (the kick):
  // the modified Hamiltonian differs from H by O(eps h^p1 + eps^2 h^p2 + eps^3 h^p3 ...),
  // eps_orders = {p1, p2, ...}; the last entry holds for every higher power of eps.
  // A composition method of order p: {p}. SABA_n: {2n, 2}. ABA(8,6,4): {8, 6, 4}.
  // `order` is the smallest entry (the order at eps = O(1)).
  std::vector<int> eps_orders;
  // The orders need {B,{B,{B,A}}} = 0 (B depends on X only, A quadratic in P: Runge-Kutta-
  // Nystrom problems such as this one); false: they hold for any A + eps B.
  bool rkn = false;
  std::string family;  // "composition", "rkn", "near-integrable" or "force-gradient"
  // Whether any kick carries a force-gradient term.
  bool force_gradient() const;
  // Force evaluations a step that also form the Hessian and the gradient: the kicks with a
  // gradient term (the first and last, merged across steps, count once). The others are plain.
  int gradient_stages() const;
  // The cost of one step in plain force evaluations: stages, plus kGradientWork - 1 for each
  // of its gradient_stages().
  double work() const;
};

// The cost of a force-gradient evaluation in plain ones (the paper's model, double): measured
// 1.19 on the cpu backend (2-core AMD EPYC, AVX2, 2026-11-23: sbab2 vs sbab2c, docs/methods.md).
constexpr double kGradientWork = 1.2;

// "(8,6,4)" for eps_orders {8, 6, 4}; "(6)" for a composition of order 6.
std::string eps_order_string(const Method& m);

// Every method the library knows, in order of increasing order and cost.
const std::vector<Method>& methods();

// The method named `name`; throws std::out_of_range listing the known names.
const Method& find_method(const std::string& name);

// Comma-separated list of method names (for messages).
std::string method_names();

}  // namespace arnoldweb
