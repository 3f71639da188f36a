// arnoldweb tests: the kernel sources flattened for OpenCL (every #include of
// an embedded file replaced by its text): headers that include each other
// (aw_params.h and the effect headers, through the generated
// effects/aw_effect_declarations.h) end, and the text keeps its line numbers.
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "backends/kernel_sources.hpp"

namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("backends") {
  TEST_CASE("flattening: an include of a file being expanded is left out, and the lines go on") {
    const std::vector<std::pair<std::string, std::string>> files = {
        {"cycle_a.h", "#ifndef A\n#define A\nint a_first;\n#include \"cycle_b.h\"\nint a_last;\n#endif\n"},
        {"cycle_b.h", "#ifndef B\n#define B\n#include \"cycle_a.h\"\nint b;\n#endif\n"},
    };
    const std::string text = arnoldweb::detail::flatten_source("cycle_a.h", files);
    CAPTURE(text);
    CHECK(count_of(text, "int a_first;") == 1);
    CHECK(count_of(text, "int b;") == 1);
    CHECK(count_of(text, "int a_last;") == 1);
    // b's "int b;" is its line 4: the left-out include kept its line
    CHECK(text.find("#line 1 \"cycle_b.h\"\n#ifndef B\n#define B\n\nint b;") != std::string::npos);
    // and a goes on at its line 5 after b
    CHECK(text.find("#line 5 \"cycle_a.h\"\nint a_last;") != std::string::npos);
  }

  TEST_CASE("flattening: the real kernel's sources, whose headers include each other, end") {
    const std::string text = arnoldweb::detail::flatten_source("ensemble.cl");
    // (a header included from two places is there twice: its guard keeps one)
    CHECK(count_of(text, "#define AW_EFFECT_DECLARATIONS_H") >= 1);
    CHECK(count_of(text, "#define AW_FX_ENERGY_DECLARATIONS") >= 1);
    CHECK(count_of(text, "aw_ensemble_item(") >= 1);
  }
}
