// arnoldweb._arnoldweb: the compiled part of the Python package. The package
// (python/arnoldweb/__init__.py) is the documented API; this module is its
// engine and mirrors the C++ library one concern per file.
#include "bindings.hpp"

#include "arnoldweb/version.hpp"

namespace awpy {

nb::object json_loads(const std::string& text) {
  return nb::module_::import_("json").attr("loads")(nb::str(text.data(), text.size()));
}

}  // namespace awpy

NB_MODULE(_arnoldweb, m) {
  m.doc() = "The compiled core of the arnoldweb package (use the names in arnoldweb instead).";
  m.attr("__version__") = ARNOLDWEB_VERSION;
  awpy::bind_errors(m);
  awpy::bind_catalogue(m);
  awpy::bind_scene(m);
  awpy::bind_result(m);
  awpy::bind_run(m);
  awpy::bind_accuracy(m);
  awpy::bind_sphere(m);
  awpy::bind_saved(m);
  awpy::bind_states(m);
  awpy::bind_model(m);
}
