// arnoldweb: the symplectic methods, as coefficient tables for the one stepper.
// Values and sources: ../shared/reference/integrators.md (docs/methods.md).
#include "arnoldweb/methods.hpp"

#include <cmath>
#include <stdexcept>

namespace arnoldweb {
namespace {

// A symmetric composition of leapfrog S2(w h) = K(w h/2) D(w h) K(w h/2) with
// weights w_1 .. w_s, kicks merged between neighbouring stages.
Method composition(std::string name, std::string title, std::string source, int order,
                   std::vector<double> w, double stability) {
  Method m;
  m.name = std::move(name);
  m.title = std::move(title);
  m.source = std::move(source);
  m.order = order;
  m.stages = static_cast<int>(w.size());
  m.kick_first = true;
  m.drift = w;
  m.kick.push_back(w.front() / 2);
  for (std::size_t i = 0; i + 1 < w.size(); ++i) m.kick.push_back((w[i] + w[i + 1]) / 2);
  m.kick.push_back(w.back() / 2);
  m.stability = stability;
  return m;
}

// first half, centre, mirrored
std::vector<double> palindrome(std::vector<double> half, double centre) {
  std::vector<double> w = half;
  w.push_back(centre);
  for (auto it = half.rbegin(); it != half.rend(); ++it) w.push_back(*it);
  return w;
}

// Blanes-Moan SRKN: kicks b1..bn, then mirrored (b_n appears once or twice as
// given), drifts a1..; given directly as the full sequences.
Method srkn(std::string name, std::string title, int order, std::vector<double> b,
            std::vector<double> a, double stability) {
  Method m;
  m.name = std::move(name);
  m.title = std::move(title);
  m.source = "Blanes & Moan, J. Comput. Appl. Math. 142 (2002) 313";
  m.order = order;
  m.stages = static_cast<int>(a.size());
  m.kick_first = true;
  m.kick = std::move(b);
  m.drift = std::move(a);
  m.stability = stability;
  return m;
}

std::vector<Method> build() {
  std::vector<Method> all;
  all.push_back(composition("leapfrog", "Stoermer-Verlet leapfrog", "-", 2, {1.0}, 2.0));

  const double fr1 = 1.351207191959657634047688, fr0 = -1.702414383919315268095376;
  all.push_back(composition("forest-ruth", "Forest-Ruth / Yoshida-4 triple jump",
                            "Forest & Ruth, Physica D 43 (1990) 105; Yoshida 1990", 4,
                            {fr1, fr0, fr1}, 1.573));

  {  // Omelyan, Mryglod, Folk 2002: drift first
    const double xi = 0.1786178958448091, lambda = -0.2123418310626054,
                 chi = -0.06626458266981849;
    Method m;
    m.name = "pefrl";
    m.title = "Omelyan PEFRL (position-extended Forest-Ruth-like)";
    m.source = "Omelyan, Mryglod & Folk, Comput. Phys. Commun. 146 (2002) 188";
    m.order = 4;
    m.stages = 4;
    m.kick_first = false;
    m.drift = {xi, chi, 1 - 2 * (chi + xi), chi, xi};
    m.kick = {0.0, (1 - 2 * lambda) / 2, lambda, lambda, (1 - 2 * lambda) / 2};
    m.stability = 2.989;
    all.push_back(m);
  }

  {
    const double b1 = 0.0829844064174052, b2 = 0.396309801498368, b3 = -0.0390563049223486;
    const double b4 = 1 - 2 * (b1 + b2 + b3);
    const double a1 = 0.245298957184271, a2 = 0.604872665711080, a3 = 0.5 - (a1 + a2);
    all.push_back(srkn("srkn6b", "Blanes-Moan SRKN6b", 4, {b1, b2, b3, b4, b3, b2, b1},
                       {a1, a2, a3, a3, a2, a1}, 3.164));
  }

  all.push_back(composition(
      "yoshida6a", "Yoshida-6 solution A (the paper's method)",
      "Yoshida, Phys. Lett. A 150 (1990) 262", 6,
      palindrome({0.78451361047755726382, 0.23557321335935813369, -1.17767998417887100695},
                 1.31518632068391121889),
      2.269));

  all.push_back(composition(
      "kahan-li-s9", "Kahan-Li s9odr6a", "Kahan & Li, Math. Comp. 66 (1997) 1089", 6,
      palindrome({0.39216144400731413928, 0.33259913678935943860, -0.70624617255763935981,
                  0.082213596293550800230},
                 0.79854399093482996340),
      2.533));

  {
    const double b[5] = {0.0414649985182624, 0.198128671918067, -0.0400061921041533,
                         0.0752539843015807, -0.0115113874206879};
    const double a[5] = {0.123229775946271, 0.290553797799558, -0.127049212625417,
                         -0.246331761062075, 0.357208872795928};
    double b6 = 0.5, a6 = 1;
    for (int i = 0; i < 5; ++i) {
      b6 -= b[i];
      a6 -= 2 * a[i];
    }
    std::vector<double> kicks(b, b + 5), drifts(a, a + 5);
    kicks.push_back(b6);
    kicks.push_back(b6);
    for (int i = 4; i >= 0; --i) kicks.push_back(b[i]);
    drifts.push_back(a6);
    for (int i = 4; i >= 0; --i) drifts.push_back(a[i]);
    all.push_back(srkn("srkn11b", "Blanes-Moan SRKN11b", 6, kicks, drifts, 3.141));
  }

  all.push_back(composition(
      "kahan-li-s15", "Kahan-Li s15odr8 (McLachlan SS15)",
      "Kahan & Li, Math. Comp. 66 (1997) 1089; McLachlan, SIAM J. Sci. Comput. 16 (1995) 151", 8,
      palindrome({0.74167036435061295345, -0.40910082580003159400, 0.19075471029623837995,
                  -0.57386247111608226666, 0.29906418130365592384, 0.33462491824529818378,
                  0.31529309239676659663},
                 -0.79688793935291635402),
      3.393));

  all.push_back(composition(
      "yoshida8d", "Yoshida-8 solution D (re-solved to 80 digits)",
      "Yoshida, Phys. Lett. A 150 (1990) 262", 8,
      palindrome({0.914844246229791566749, 0.253693336566211354146, -1.444852236860605157695,
                  -0.158240635368050175204, 1.938139137622525986579, -1.960610232975310807608,
                  0.102799849391796440698},
                 1.708453070787281584668),
      2.357));
  return all;
}

}  // namespace

const std::vector<Method>& methods() {
  static const std::vector<Method> all = build();
  return all;
}

const Method& find_method(const std::string& name) {
  for (const Method& m : methods())
    if (m.name == name) return m;
  throw std::out_of_range("unknown method '" + name + "' (known: " + method_names() + ")");
}

std::string method_names() {
  std::string s;
  for (const Method& m : methods()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

}  // namespace arnoldweb
