// The library's error types (errors.hpp) raised in Python as the classes of
// arnoldweb._errors, with their fields as attributes: SceneError(file, line,
// column, key), DeviceError(device, call, status), BuildError(options, log),
// OutputError(path), StateError(source, dataset, row). The message is the library's, word for word (the CLI
// prints the same text).
#include "bindings.hpp"

#include <nanobind/stl/string.h>

namespace awpy {
namespace {

// Raises arnoldweb._errors.<name>(message, **fields) as the current Python error.
void raise_as(const char* name, const std::string& message, nb::dict fields) {
  nb::object type = nb::module_::import_("arnoldweb._errors").attr(name);
  nb::object error = type(nb::str(message.data(), message.size()), **fields);
  PyErr_SetObject(type.ptr(), error.ptr());
}

void translate(const std::exception_ptr& p, void*) {
  try {
    std::rethrow_exception(p);
  } catch (const arnoldweb::SceneError& e) {
    nb::dict f;
    f["file"] = e.file();
    f["line"] = e.line();
    f["column"] = e.column();
    f["key"] = e.key();
    f["reason"] = e.message();
    raise_as("SceneError", e.what(), f);
  } catch (const arnoldweb::DeviceError& e) {
    nb::dict f;
    f["device"] = e.device();
    f["call"] = e.call();
    f["status"] = e.status();
    raise_as("DeviceError", e.what(), f);
  } catch (const arnoldweb::BuildError& e) {
    nb::dict f;
    f["options"] = e.options();
    f["log"] = e.log();
    raise_as("BuildError", e.what(), f);
  } catch (const arnoldweb::OutputRefused& e) {
    nb::dict f;
    f["path"] = e.path();
    raise_as("OutputRefused", e.what(), f);
  } catch (const arnoldweb::OutputError& e) {
    nb::dict f;
    f["path"] = e.path();
    raise_as("OutputError", e.what(), f);
  } catch (const arnoldweb::StateError& e) {
    nb::dict f;
    f["source"] = e.source();
    f["dataset"] = e.dataset();
    f["row"] = e.row();
    f["reason"] = e.message();
    raise_as("StateError", e.what(), f);
  } catch (const arnoldweb::Error& e) {
    raise_as("Error", e.what(), nb::dict());
  }
}

}  // namespace

void bind_errors(nb::module_& m) { nb::register_exception_translator(translate); }

}  // namespace awpy
