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
  double stability = 0;       // linear stability limit h*omega (harmonic oscillator)
};

// Every method the library knows, in order of increasing order and cost.
const std::vector<Method>& methods();

// The method named `name`; throws std::out_of_range listing the known names.
const Method& find_method(const std::string& name);

// Comma-separated list of method names (for messages).
std::string method_names();

}  // namespace arnoldweb
