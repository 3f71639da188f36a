// arnoldweb compare DIR_A DIR_B: are two saved velocity maps (or zooms)
// statistically the same? The two-sample chi-square test of compare_maps
// (analysis.hpp). Exit codes as diff and cmp have them: 0 consistent,
// 1 different, 2 trouble (a missing or damaged directory or map, different
// shapes, a bad option; the read-side checks of saved_run.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "arnoldweb/analysis.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/output.hpp"
#include "command.hpp"

namespace arnoldweb::cli {
namespace {

struct CompareArgs {
  std::string dir_a, dir_b;
  double alpha = 1e-3;
  double min_count = 5;
  std::string what = "map";
};

// The histogram asked for from one directory, with its shape in words;
// OutputError naming the file when the run did not make it.
const std::vector<std::uint64_t>& pick(const SavedMaps& s, const std::string& what, std::string* shape) {
  if (what == "zoom") {
    if (s.zoom.empty())
      throw OutputError(s.map_file, "holds no zoom (the run had no observe.zoom); compare the maps with --what map");
    *shape = "zoom " + std::to_string(s.zoom_resolution) + " x " + std::to_string(s.zoom_resolution);
    return s.zoom;
  }
  if (s.map.empty())
    throw OutputError(s.map_file, "holds no velocity map (the run had observe.velocity_map off); "
                                  "compare the zooms with --what zoom");
  *shape = "map nside " + std::to_string(s.nside);
  return s.map;
}

int compare(const CompareArgs& args) {
  const SavedMaps a = read_saved_maps(args.dir_a), b = read_saved_maps(args.dir_b);
  for (const SavedMaps* s : {&a, &b})
    if (!s->note.empty()) std::cerr << "arnoldweb: note: " << s->note << "\n";
  std::string shape_a, shape_b;
  const auto& ma = pick(a, args.what, &shape_a);
  const auto& mb = pick(b, args.what, &shape_b);
  if (shape_a != shape_b)
    throw OutputError(b.map_file, shape_b + ", but " + a.map_file + " has " + shape_a +
                                      ": histograms of different shapes cannot be compared");
  const MapComparison c = compare_maps(ma, mb, args.min_count);
  const bool same = c.consistent(args.alpha);
  std::printf("A         %s: %s, %llu counts (%llu trajectories binned)\n", args.dir_a.c_str(), shape_a.c_str(),
              static_cast<unsigned long long>(c.total_a), static_cast<unsigned long long>(a.binned));
  std::printf("B         %s: %s, %llu counts (%llu trajectories binned)\n", args.dir_b.c_str(), shape_b.c_str(),
              static_cast<unsigned long long>(c.total_b), static_cast<unsigned long long>(b.binned));
  std::printf("bins      %zu: %zu used", c.bins, c.used_bins);
  if (c.pooled_bins)
    std::printf(", one of them the %zu bins with fewer than %g counts in A + B pooled", c.pooled_bins, args.min_count);
  std::printf("; %zu empty in both\n", c.empty_bins);
  std::printf("chi2      %.6g\n", c.chi2);
  std::printf("dof       %.0f\n", c.dof);
  std::printf("chi2/dof  %.4f\n", c.chi2_per_dof());
  if (c.p_value > 0)
    std::printf("p         %.4g\n", c.p_value);
  else
    std::printf("p         < 1e-307 (below the smallest double)\n");
  if (a.seed && a.seed == b.seed)
    std::printf("note      both runs have ensemble.seed = %llu: if their initial states agree, the maps are not\n"
                "          independent samples and the test is too lenient (give one run another seed)\n",
                static_cast<unsigned long long>(*a.seed));
  std::printf("%s at alpha = %g (p %s alpha)\n", same ? "statistically consistent" : "different", args.alpha,
              same ? ">=" : "<");
  return same ? 0 : 1;
}

// A number strictly between 0 and 1 (CLI::Range took 0, 1 and NaN; 1e-400
// reads as 0).
CLI::Validator significance_level() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !(v > 0 && v < 1))
          return "--alpha must be a number strictly between 0 and 1, got " + text;
        return "";
      },
      "in (0, 1)");
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<CompareArgs>();
  auto* c = app.add_subcommand(
      "compare",
      "Two-sample chi-square test of two saved maps: exit 0 statistically consistent, 1 different, 2 error");
  c->add_option("dir_a", args->dir_a, "Output directory of a run")->required();
  c->add_option("dir_b", args->dir_b, "Output directory of another run (an independent ensemble: another seed)")
      ->required();
  c->add_option("--alpha", args->alpha, "Significance level in (0, 1): different when p < alpha")
      ->capture_default_str()
      ->check(significance_level());
  c->add_option("--what", args->what, "Which histogram of map.h5")->capture_default_str()->check(
      CLI::IsMember({"map", "zoom"}));
  c->add_option("--min-count", args->min_count, "Bins with fewer counts in A + B are pooled into one bin")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  c->callback([&action, args] {
    action = [args] {
      // every failure is exit 2 here (as for diff and cmp): 1 means "different"
      try {
        return compare(*args);
      } catch (const std::exception& e) {
        std::cerr << "arnoldweb: error: " << e.what() << "\n";
        return 2;
      }
    };
  });
}

}  // namespace arnoldweb::cli
