// arnoldweb_parity: runs the same ensembles on every device and compares them.
//   portable math: map and final-state digests must be identical (exit 1 if not);
//   native math:   how far each device drifts from the portable reference
//                  (ulps of final momenta, fraction diverged, map chi-square).
// Usage: arnoldweb_parity [--trajectories N] [--steps S] [--devices a,b,...]
//                         [--native] [--csv FILE]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "arnoldweb/arnoldweb.hpp"

using namespace arnoldweb;

namespace {

struct Config {
  std::string name;
  double energy, step;
  Precision precision;
};

Scene make_scene(const Config& c, std::uint64_t n, std::int64_t steps, MathMode math) {
  Scene s;
  s.file = "<parity:" + c.name + ">";
  s.energy = c.energy;
  s.trajectories = n;
  s.seed = 20261121;
  s.step = c.step;
  s.average = c.step * static_cast<double>(steps);
  s.duration = s.average;
  s.energy_every = s.average / 10;
  s.nside = 64;
  s.final_states = true;
  s.precision = c.precision;
  s.math = math;
  return s;
}

double ulp_of(double x, bool fl) {
  if (fl) {
    float f = static_cast<float>(std::fabs(x));
    return std::nextafter(f, INFINITY) - f;
  }
  double a = std::fabs(x);
  return std::nextafter(a, INFINITY) - a;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t n = 100000;
  std::int64_t steps = 10000;
  bool native = false;
  std::string csv_path;
  std::vector<std::string> device_ids;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--trajectories") n = std::stoull(value());
    else if (a == "--steps") steps = std::stoll(value());
    else if (a == "--devices") device_ids = split(value());
    else if (a == "--native") native = true;
    else if (a == "--csv") csv_path = value();
    else {
      std::fprintf(stderr, "usage: %s [--trajectories N] [--steps S] [--devices a,b] [--native] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  if (device_ids.empty())
    for (const auto& d : list_devices()) device_ids.push_back(d.id);

  const std::vector<Config> configs = {
      {"E15-double", 15.0, 0.01, Precision::Double},
      {"E15-float", 15.0, 0.01, Precision::Float},
      {"E400-double", 400.0, 0.002, Precision::Double},
      {"E400-float", 400.0, 0.002, Precision::Float},
  };
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "config,math,device,name,seconds,map_digest,states_digest,identical,median_ulp,p99_ulp,diverged_fraction,chi2_per_dof\n";
  }
  int failures = 0;
  std::printf("parity: %llu trajectories x %lld steps, %s math\n", static_cast<unsigned long long>(n),
              static_cast<long long>(steps), native ? "portable and native" : "portable");
  std::printf("| config | math | device | s | map digest | states digest | same bits as %s | median ulp | p99 ulp | diverged | chi2/dof |\n",
              device_ids.front().c_str());
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Config& c : configs) {
    const bool fl = c.precision == Precision::Float;
    Result reference;
    bool have_ref = false;
    for (MathMode math : native ? std::vector<MathMode>{MathMode::Portable, MathMode::Native}
                                : std::vector<MathMode>{MathMode::Portable}) {
      const Plan plan = make_plan(make_scene(c, n, steps, math));
      for (const auto& id : device_ids) {
        std::unique_ptr<Backend> backend;
        Result r;
        try {
          backend = open_backend(id);
          r = run(plan, *backend);
        } catch (const Error& e) {
          std::printf("| %s | %s | %s | - | error: %s |\n", c.name.c_str(), to_string(math), id.c_str(), e.what());
          ++failures;
          continue;
        }
        if (!have_ref) {
          reference = r;  // the first device in portable math
          have_ref = true;
        }
        const bool same = digest_map(r) == digest_map(reference) &&
                          digest_records(r, "final_states") == digest_records(reference, "final_states");
        // drift from the reference, in ulps of the final momenta
        std::vector<double> ulps;
        std::uint64_t diverged = 0;
        for (std::size_t t = 0; t < n; ++t) {
          double worst = 0;
          for (int k = 3; k < 6; ++k) {
            const double a = r.reals("final_states")[t * 6 + k], b = reference.reals("final_states")[t * 6 + k];
            worst = std::max(worst, std::fabs(a - b) / ulp_of(b, fl));
          }
          const double dp = std::fabs(r.reals("final_states")[t * 6 + 3] - reference.reals("final_states")[t * 6 + 3]);
          if (dp > 1e-2) ++diverged;
          ulps.push_back(worst);
        }
        std::sort(ulps.begin(), ulps.end());
        const double median = ulps[ulps.size() / 2], p99 = ulps[ulps.size() * 99 / 100];
        double chi2 = 0;
        std::size_t dof = 0;
        for (std::size_t p = 0; p < r.map.size(); ++p) {
          const double a = static_cast<double>(r.map[p]), b = static_cast<double>(reference.map[p]);
          if (a + b > 0) {
            chi2 += (a - b) * (a - b) / (a + b);
            ++dof;
          }
        }
        const double chi2dof = dof ? chi2 / static_cast<double>(dof) : 0;
        if (math == MathMode::Portable && !same) ++failures;
        std::printf("| %s | %s | %s | %.2f | %.12s | %.12s | %s | %.3g | %.3g | %.4f | %.3f |\n", c.name.c_str(),
                    to_string(math), id.c_str(), r.wall_seconds, digest_map(r).c_str(),
                    digest_records(r, "final_states").c_str(), same ? "yes" : "NO", median, p99,
                    static_cast<double>(diverged) / static_cast<double>(n), chi2dof);
        std::fflush(stdout);
        if (csv)
          csv << c.name << ',' << to_string(math) << ',' << id << ",\"" << r.device.name << "\"," << r.wall_seconds << ','
              << digest_map(r) << ',' << digest_records(r, "final_states") << ',' << (same ? 1 : 0) << ',' << median << ','
              << p99 << ',' << static_cast<double>(diverged) / static_cast<double>(n) << ',' << chi2dof << '\n';
      }
    }
  }
  std::printf("parity: %s\n", failures ? "FAILED (portable math differs or a device failed)" : "all portable runs bitwise identical");
  return failures ? 1 : 0;
}
