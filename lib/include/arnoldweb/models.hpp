// arnoldweb: the built-in models (Hamiltonians H = T(P) + V(X) on the 3-torus),
// as `arnoldweb models` lists them (docs/models.md). A scene picks one with
// model.kind.
#pragma once

#include <string>
#include <vector>

namespace arnoldweb {

struct ModelInfo {
  std::string name;        // model.kind
  std::string title;       // human name and source
  std::string formula;     // H, as text
  std::string parameters;  // its parameters and their keys, as text
  std::vector<std::string> keys;  // its scene keys besides model.energy
};

std::vector<ModelInfo> model_list();

}  // namespace arnoldweb
