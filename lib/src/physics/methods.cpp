// arnoldweb: the symplectic methods, as coefficient tables for the one stepper.
// Values and sources: ../shared/reference/integrators.md (docs/methods.md).
#include "arnoldweb/methods.hpp"

#include <algorithm>
#include <cctype>
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
  m.eps_orders = {order};
  m.family = "composition";
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
  m.eps_orders = {order};
  m.rkn = true;
  m.family = "rkn";
  return m;
}

// A method for near-integrable H = A + eps B given as its whole sequence: drift-first
// (ABA: D a0 K b1 D a1 ... K b_s D a_s; `kicks` b1..b_s) or kick-first (BAB: K b0 D a0
// ... D a_{s-1} K b_s; `drifts` a0..a_{s-1}). eps_orders as in Method.
Method near_integrable(std::string name, std::string title, std::string source,
                       std::vector<int> eps_orders, bool kick_first, std::vector<double> drifts,
                       std::vector<double> kicks, double stability) {
  Method m;
  m.name = std::move(name);
  m.title = std::move(title);
  m.source = std::move(source);
  m.order = *std::min_element(eps_orders.begin(), eps_orders.end());
  m.eps_orders = std::move(eps_orders);
  m.kick_first = kick_first;
  m.drift = std::move(drifts);
  if (kick_first) {
    m.stages = static_cast<int>(m.drift.size());
    m.kick = std::move(kicks);
  } else {
    m.stages = static_cast<int>(kicks.size());
    m.kick.push_back(0.0);  // drift-first tables have no b_0
    m.kick.insert(m.kick.end(), kicks.begin(), kicks.end());
  }
  m.stability = stability;
  m.family = "near-integrable";
  return m;
}

// The method named `name` in `all`, or null.
const Method* lookup(const std::vector<Method>& all, const std::string& name) {
  for (const Method& m : all)
    if (m.name == name) return &m;
  return nullptr;
}

const Method& find_in(const std::vector<Method>& all, const std::string& name) {
  if (const Method* m = lookup(all, name)) return *m;
  throw std::logic_error("method table: no " + name);
}

// v followed by its mirror image; `repeat_centre`: the last element appears twice.
std::vector<double> mirrored(std::vector<double> v, bool repeat_centre) {
  const std::size_t n = v.size();
  for (std::size_t i = repeat_centre ? n : n - 1; i-- > 0;) v.push_back(v[i]);
  return v;
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
    m.eps_orders = {4};
    m.family = "composition";
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

  // ---- Methods for near-integrable H = A + eps B (A = |P|^2/2, the drift; B = V, the
  // kick; eps_eff = 2/E here). Orders (p, q, r): error O(eps h^p + eps^2 h^q + eps^3 h^r).
  // Coefficients to 20+ digits from the closed forms or the cited tables;
  // tests/physics/test_method_tables.cpp checks every order numerically (docs/methods.md).

  // Laskar & Robutel, Celest. Mech. Dyn. Astron. 80 (2001) 39, "High order symplectic
  // integrators for perturbed Hamiltonian systems": SABA_n (drift-first, drifts at the
  // Gauss-Legendre nodes, kicks the Gauss weights) and SBAB_n (kick-first, Gauss-Lobatto),
  // O(eps h^2n + eps^2 h^2). SBAB_1 is `leapfrog`.
  const char* lr2001 = "Laskar & Robutel, Celest. Mech. Dyn. Astron. 80 (2001) 39";
  all.push_back(near_integrable("saba1", "Laskar-Robutel SABA1 (drift-first leapfrog)", lr2001, {2}, false,
                                {0.5, 0.5}, {1.0}, 2.000));
  {  // c1 = 1/2 - sqrt(3)/6, c2 = sqrt(3)/3; d1 = 1/2
    const double c1 = 0.21132486540518711774542560974902127, c2 = 0.57735026918962576450914878050195746;
    all.push_back(near_integrable("saba2", "Laskar-Robutel SABA2", lr2001, {4, 2}, false, {c1, c2, c1},
                                  {0.5, 0.5}, 2.632));
  }
  {  // c1 = 1/2 - sqrt(15)/10, c2 = sqrt(15)/10; d1 = 5/18, d2 = 4/9
    const double c1 = 0.11270166537925831148207346002176004, c2 = 0.38729833462074168851792653997823996;
    all.push_back(near_integrable("saba3", "Laskar-Robutel SABA3", lr2001, {6, 2}, false,
                                  mirrored({c1, c2}, true), {5.0 / 18, 4.0 / 9, 5.0 / 18}, 2.887));
  }
  {  // c1 = 1/2 - sqrt(525 + 70 sqrt 30)/70, c2 = (sqrt(525 + 70 sqrt 30) - sqrt(525 - 70 sqrt 30))/70,
     // c3 = sqrt(525 - 70 sqrt 30)/35; d1 = 1/4 - sqrt(30)/72, d2 = 1/4 + sqrt(30)/72
    const double c1 = 0.069431844202973712388026755553595247, c2 = 0.26057763400459815521064036489478241,
                 c3 = 0.33998104358485626480266575910324469;
    const double d1 = 0.17392742256872692868653197461099970, d2 = 0.32607257743127307131346802538900030;
    all.push_back(near_integrable("saba4", "Laskar-Robutel SABA4", lr2001, {8, 2}, false,
                                  mirrored({c1, c2, c3}, false), mirrored({d1, d2}, true), 3.010));
  }
  // SBAB2: d1 = 1/6, d2 = 2/3; c = 1/2
  all.push_back(near_integrable("sbab2", "Laskar-Robutel SBAB2", lr2001, {4, 2}, true, {0.5, 0.5},
                                {1.0 / 6, 2.0 / 3, 1.0 / 6}, 2.449));
  {  // c2 = 1/2 - sqrt(5)/10, c3 = sqrt(5)/5; d1 = 1/12, d2 = 5/12
    const double c2 = 0.27639320225002103035908263312687237, c3 = 0.44721359549995793928183473374625525;
    all.push_back(near_integrable("sbab3", "Laskar-Robutel SBAB3", lr2001, {6, 2}, true, {c2, c3, c2},
                                  {1.0 / 12, 5.0 / 12, 5.0 / 12, 1.0 / 12}, 2.931));
  }
  {  // c2 = 1/2 - sqrt(21)/14, c3 = sqrt(21)/14; d1 = 1/20, d2 = 49/180, d3 = 16/45
    const double c2 = 0.17267316464601142810085377187657294, c3 = 0.32732683535398857189914622812342706;
    all.push_back(near_integrable("sbab4", "Laskar-Robutel SBAB4", lr2001, {8, 2}, true,
                                  mirrored({c2, c3}, true), mirrored({1.0 / 20, 49.0 / 180, 16.0 / 45}, false),
                                  2.997));
  }

  // McLachlan, BIT 35 (1995) 258, "Composition methods in the presence of small
  // parameters": the kick-first (8,4) method with 5 force evaluations (20 digits as
  // tabulated in the IMCCE integrator of Farres et al., Celest. Mech. Dyn. Astron. 116
  // (2013) 141).
  all.push_back(near_integrable(
      "bab84", "McLachlan BAB(8,4)", "McLachlan, BIT 35 (1995) 258", {8, 4}, true,
      mirrored({-0.00758691311877447385, 0.31721827797316981388, 0.38073727029120931994}, false),
      mirrored({0.81186273854451628884, -0.67748039953216912289, 0.36561766098765283405}, true), 2.974));

  // Blanes, Casas, Farres, Laskar, Makazaga & Murua, Appl. Numer. Math. 68 (2013) 58,
  // "New families of symplectic splitting methods for numerical integration in dynamical
  // astronomy": the drift-first ABA(10,4) (s = 7), ABA(8,6,4) (s = 7) and ABA(10,6,4)
  // (s = 8), 40 digits as printed there (also in REBOUND's SABA integrator).
  const char* bcflmm = "Blanes, Casas, Farres, Laskar, Makazaga & Murua, Appl. Numer. Math. 68 (2013) 58";
  all.push_back(near_integrable(
      "aba104", "Blanes et al. ABA(10,4)", bcflmm, {10, 4}, false,
      mirrored({0.04706710064597250612947887637243678556564, 0.1847569354170881069247376193702560968574,
                0.2827060056798362053243616565541452479160, -0.01453004174289681837857815229683813033908},
               true),
      mirrored({0.1188819173681970199453503950853885936957, 0.2410504605515015657441667865901651105675,
                -0.2732866667053238060543113981664559460630, 0.8267085775712504407295884329818044835997},
               false),
      3.090));
  all.push_back(near_integrable(
      "aba864", "Blanes et al. ABA(8,6,4)", bcflmm, {8, 6, 4}, false,
      mirrored({0.0711334264982231177779387300061549964174, 0.241153427956640098736487795326289649618,
                0.521411761772814789212136078067994229991, -0.333698616227678005726562603400438876027},
               true),
      mirrored({0.183083687472197221961703757166430291072, 0.310782859898574869507522291054262796375,
                -0.0265646185119588006972121379164987592663, 0.0653961422823734184559721793911134363710},
               false),
      3.142));
  all.push_back(near_integrable(
      "aba1064", "Blanes et al. ABA(10,6,4)", bcflmm, {10, 6, 4}, false,
      mirrored({0.03809449742241219545697532230863756534060, 0.1452987161169137492940200726606637497442,
                0.2076276957255412507162056113249882065158, 0.4359097036515261592231548624010651844006,
                -0.6538612258327867093807117373907094120024},
               false),
      mirrored({0.09585888083707521061077150377145884776921, 0.2044461531429987806805077839164344779763,
                0.2170703479789911017143385924306336714532, -0.01737538195906509300561788011852699719871},
               true),
      3.146));
  // ---- Force-gradient methods: kicks that carry h^3 grad|F|^2 (Method::gradient), from the
  // force's own sin/cos. They need {B,{B,{B,A}}} = 0 (B = V(X)), so rkn = true.

  // Laskar & Robutel (2001), the correctors: e^{-c h^3 eps^2 {{A,B},B}/2} SABA_n (or SBAB_n)
  // e^{-c h^3 eps^2 {{A,B},B}/2} removes the eps^2 h^2 term: O(eps h^2n + eps^2 h^4). c is the
  // coefficient of h^3 [B,[B,A]] in the method's modified generator, in closed form (checked
  // by tests/physics/test_method_tables.cpp; SABA's agree with REBOUND's to 34 digits):
  //   SABA: 1/12, (2 - sqrt 3)/24, (54 - 13 sqrt 15)/648, 0.0033967750...
  //   SBAB: -1/24, 1/72, (13 - 5 sqrt 5)/288, 143/2400 - 791 sqrt 21/64800.
  // SBAB_nC: the corrector merges into the first and last kick (same force evaluations as
  // SBAB_n). SABA_nC: the correctors of neighbouring steps merge into one pure gradient kick
  // between steps (b = 0), written kick-first: one evaluation more than SABA_n.
  {
    // `base`: the uncorrected method's name; `b`: its table
    auto corrected = [&](const std::string& base, const Method& b, double c, double stability) {
      Method m = b;
      m.name = base + "c";
      std::string upper = base;  // "SABA2"
      for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      m.title = "Laskar-Robutel " + upper + "C (" + upper + " with its corrector)";
      m.source = lr2001;
      m.family = "near-integrable";
      m.rkn = true;
      if (!b.kick_first) {  // D a0 K b1 ... K bs D as  ->  K(0) D a0 K b1 ... D as K(0)
        m.kick_first = true;
        m.stages = b.stages + 1;
        m.kick = b.kick;   // b.kick[0] == 0
        m.kick.push_back(0.0);
      }
      m.gradient.assign(m.kick.size(), 0.0);
      m.gradient.front() = c / 2;
      m.gradient.back() = c / 2;
      m.eps_orders = {b.eps_orders.front(), 4};
      m.order = std::min(m.eps_orders[0], 4);
      m.stability = stability;
      all.push_back(m);
    };
    auto corrected_of = [&](const std::string& base, double c, double stability) {
      corrected(base, find_in(all, base), c, stability);
    };
    corrected_of("saba1", 1.0 / 12, 2.000);
    corrected_of("saba2", 0.01116454968463011276968973577058865137738, 2.869);
    corrected_of("saba3", 0.005634593363122809402267823769797538671562, 2.887);
    corrected_of("saba4", 0.003396775048208601331532157783492143797021, 3.010);
    corrected("sbab1", find_in(all, "leapfrog"), -1.0 / 24, 1.779);  // SBAB_1 is the leapfrog
    corrected_of("sbab2", 1.0 / 72, 2.449);
    corrected_of("sbab3", 0.006318264279517539992896290473415343134712, 2.947);
    corrected_of("sbab4", 0.003644793600153249302297139965449772919958, 2.997);
  }

  // A force-gradient method given as its kick-first table (K b0 D a0 ... D a_{s-1} K b_s, a
  // gradient coefficient per kick).
  auto force_gradient = [&](std::string name, std::string title, std::string source, int order,
                            std::vector<double> drifts, std::vector<double> kicks, std::vector<double> gradient,
                            double stability) {
    Method m;
    m.name = std::move(name);
    m.title = std::move(title);
    m.source = std::move(source);
    m.order = order;
    m.stages = static_cast<int>(drifts.size());
    m.kick_first = true;
    m.drift = std::move(drifts);
    m.kick = std::move(kicks);
    m.gradient = std::move(gradient);
    m.stability = stability;
    m.eps_orders = {order};
    m.rkn = true;
    m.family = "force-gradient";
    all.push_back(m);
  };

  // Chin, Phys. Lett. A 226 (1997) 344, algorithm 4A ("C"): V/6, T/2, (2/3)(V + h^2/48
  // [V,[T,V]]), T/2, V/6: fourth order in h for any eps, two force evaluations a step, the
  // gradient on the middle one (g = 2/3 x 1/48 = 1/72).
  force_gradient("chin4a", "Chin 4A force-gradient", "Chin, Phys. Lett. A 226 (1997) 344", 4, {0.5, 0.5},
                 {1.0 / 6, 2.0 / 3, 1.0 / 6}, {0.0, 1.0 / 72, 0.0}, 3.464);

  // Omelyan, Mryglod & Folk, Comput. Phys. Commun. 151 (2003) 272: order 6, five force
  // evaluations. G carries h^3 [B,[A,B]] as in Chin 4A (whose 1/72 is OMF's order-4 chi).
  {  // velocity version, eqs. (63)-(64), four gradients, in closed form (s = sqrt 5,
     // t = sqrt(50 + 22 s)): V(vartheta) T(rho) V(lambda)+G(xi) T(theta) V(1/2-lambda-vartheta)+G(chi)
     // T(1-2(theta+rho)), mirrored; rho = (1 + 1/s)/2, theta = -1/s, vartheta = 1/12,
     // lambda = 5/12 - t/24, xi = (15 + 5s)/1152 - t (1/2880 + s/1152),
     // chi = -(11 + 5s)/1152 + t (1/2880 + s/1152). 40 digits (mpmath).
    const double rho = 0.7236067977499789696409173668731276235441;
    const double theta = -0.4472135954999579392818347337462552470881;
    const double centre = 0.4472135954999579392818347337462552470881;  // 1 - 2(theta + rho)
    const double vartheta = 1.0 / 12;
    const double lambda = 0.001683619186203287766402563100360490765158;
    const double mid = 0.4149830474804633789002641035663061759015;  // 1/2 - lambda - vartheta
    const double xi = -0.00006408390325141897507306236138814724749513;
    const double chi = 0.003536306125473641197295284583610369469717;
    force_gradient("omf6v", "Omelyan-Mryglod-Folk order 6, velocity version",
                   "Omelyan, Mryglod & Folk, Comput. Phys. Commun. 151 (2003) 272", 6,
                   {rho, theta, centre, theta, rho}, {vartheta, lambda, mid, mid, lambda, vartheta},
                   {0.0, xi, chi, chi, xi, 0.0}, 3.139);
  }

  return all;
}

}  // namespace

const std::vector<Method>& methods() {
  static const std::vector<Method> all = build();
  return all;
}

const Method& find_method(const std::string& name) {
  if (const Method* m = lookup(methods(), name)) return *m;
  throw std::out_of_range("unknown method '" + name + "' (known: " + method_names() + ")");
}

std::string eps_order_string(const Method& m) {
  std::string s = "(";
  for (std::size_t i = 0; i < m.eps_orders.size(); ++i) s += (i ? "," : "") + std::to_string(m.eps_orders[i]);
  return s + ")";
}

bool Method::force_gradient() const {
  return std::any_of(gradient.begin(), gradient.end(), [](double g) { return g != 0.0; });
}

int Method::gradient_stages() const {
  if (!force_gradient()) return 0;
  int n = (gradient.front() + gradient.back() != 0.0) ? 1 : 0;  // the merged kick between steps
  for (std::size_t i = 1; i + 1 < gradient.size(); ++i) n += (gradient[i] != 0.0) ? 1 : 0;
  return n;
}

double Method::work() const { return stages + gradient_stages() * (kGradientWork - 1.0); }

std::string method_names() {
  std::string s;
  for (const Method& m : methods()) s += (s.empty() ? "" : ", ") + m.name;
  return s;
}

}  // namespace arnoldweb
