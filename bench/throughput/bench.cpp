// arnoldweb bench: see bench.hpp.
#include "arnoldweb/bench.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "arnoldweb/arnoldweb.hpp"
#include "naive.hpp"
#include "naive_cuda_loader.hpp"

namespace arnoldweb::bench {
namespace {

namespace fs = std::filesystem;
using clock = std::chrono::steady_clock;

constexpr double kTwoPi = 6.283185307179586476925;
constexpr int kBinsTheta = 64, kBinsPhi = 128;  // baselines' velocity histogram

std::uint64_t parse_count(const std::string& s) {
  std::size_t pos = 0;
  const double v = std::stod(s, &pos);
  if (pos != s.size() || !(v >= 1) || v > 1e13) throw CLI::ValidationError("size", "not a count: " + s);
  return static_cast<std::uint64_t>(std::llround(v));
}

std::string fmt(double v, const char* f = "%.3g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string today_utc() {
  std::time_t t = std::time(nullptr);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return b;
}

std::string hostname() {
  char b[256] = {0};
  gethostname(b, sizeof b - 1);
  return b;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

// The energy sample interval of the default scene (2 T), or the whole run when
// it does not divide it.
double energy_every(double average) {
  const double r = average / 2.0;
  return std::fabs(r - std::round(r)) < 1e-9 && r >= 1 ? 2.0 : average;
}

Scene scene_for(const Options& o, const std::string& variant, const std::string& precision,
                const std::string& math, std::uint64_t n, std::int64_t steps) {
  Scene s;
  s.file = "<bench:" + variant + ">";
  s.energy = o.energy;
  s.trajectories = n;
  s.seed = 1;
  s.step = o.step;
  s.average = o.step * static_cast<double>(steps);
  s.duration = s.average;
  s.nside = 64;
  s.velocity_map = true;
  s.energy_error = variant != "bare";
  s.energy_every = energy_every(s.average);
  if (variant == "energy_limit") s.max_energy_error = 1e-3;
  s.final_states = variant == "final_states";
  s.initial_states = variant == "initial_states";
  if (variant == "confine") {  // a square so large that nobody leaves it: the cost of the test alone
    s.confine = true;
    s.confine_center = {45.0, 0.0};
    s.confine_width = 119.0;
    s.initial = "cap";
    s.cap_center = {45.0, 0.0};
    s.cap_radius = 10.0;
  }
  if (variant == "zoom") {
    s.zoom = true;
    s.zoom_center = {45.0, 0.0};
    s.zoom_width = 60.0;
  }
  if (variant == "frames") {  // 10 windows, 4 frames
    s.average = s.average / 10;
    s.energy_every = energy_every(s.average);
    s.frame_times = {0.0, s.average, 3 * s.average, 6 * s.average, 10 * s.average};
  }
  s.precision = precision == "float" ? Precision::Float : Precision::Double;
  s.math = math == "native" ? MathMode::Native : MathMode::Portable;
  s.output_dir = "";
  s.images = false;
  return s;
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// ---------------------------------------------------------------- library runs

Row measure_library(Backend& b, const Options& o, const std::string& kind, const std::string& variant,
                    const std::string& precision, const std::string& math, std::uint64_t n,
                    std::int64_t steps) {
  const DeviceInfo& d = b.info();
  Row r;
  r.kind = kind;
  r.device = d.id;
  r.name = d.name;
  r.backend = d.backend;
  r.driver = d.version;
  r.cpu = d.is_cpu;
  r.precision = precision;
  r.math = math;
  r.variant = variant;
  r.n = n;
  r.steps = steps;
  try {
    const Plan plan = make_plan(scene_for(o, variant, precision, math, n, steps));
    r.effects = join(plan.effects(), "+");
    b.prepare(plan, n);  // compiles (cached): not timed
    ChunkOutput out;
    b.run_chunk(0, std::min<std::uint64_t>(n, d.is_cpu ? 64 : 4096), out);  // warm-up
    std::vector<double> t;
    for (int i = 0; i < std::max(1, o.repeat); ++i) {
      const auto t0 = clock::now();
      b.run_chunk(0, n, out);
      t.push_back(std::chrono::duration<double>(clock::now() - t0).count());
    }
    for (std::size_t g = 0; g + 1 < out.group_stats.size(); g += 2) r.emax = std::max(r.emax, out.group_stats[g]);
    r.seconds = median(t);
    r.seconds_min = *std::min_element(t.begin(), t.end());
    r.repeats = static_cast<int>(t.size());
    r.rate = static_cast<double>(n) * static_cast<double>(steps) / r.seconds;
  } catch (const std::exception& e) {
    r.note = e.what();
  }
  return r;
}

// ---------------------------------------------------------------- baselines

// Initial states of trajectories [0, n) from the library (cpu backend; the
// same (seed, index) streams as every library run), 6 per trajectory.
std::vector<double> initial_states(const Options& o, std::uint64_t n) {
  Scene s = scene_for(o, "bare", "double", "portable", n, 1);
  s.initial_states = true;
  const Plan plan = make_plan(s);
  auto cpu = open_backend("cpu");
  const Result r = arnoldweb::run(plan, *cpu);
  return r.reals("initial_states");
}

AwNaiveArgs naive_args(const Options& o, const std::vector<double>& init, std::uint64_t n, std::int64_t steps,
                       bool fl) {
  const Method& m = find_method("yoshida6a");
  AwNaiveArgs a{};
  a.use_float = fl ? 1 : 0;
  a.n = n;
  a.steps = steps;
  const double average = o.step * static_cast<double>(steps);
  a.energy_every = std::llround(energy_every(average) / o.step);
  a.init = init.data();
  a.stages = m.stages;
  const double h = o.step * kTwoPi;
  for (int i = 0; i < m.stages && i < 17; ++i) a.drift[i] = m.drift[i] * h;
  for (int i = 0; i <= m.stages && i < 18; ++i) a.kick[i] = m.kick[i] * h;
  a.step_time = h;
  a.bins_theta = kBinsTheta;
  a.bins_phi = kBinsPhi;
  return a;
}

Row measure_baseline(const Options& o, const std::string& which, int ordinal, const std::vector<double>& init,
                     const std::string& precision, std::uint64_t n, std::int64_t steps) {
  Row r;
  r.kind = "baseline";
  r.backend = which;
  r.device = which == "naive-cuda" ? "naive-cuda:" + std::to_string(ordinal) : which;
  r.cpu = which == "naive-openmp";
  r.precision = precision;
  r.math = "vendor";
  r.variant = "default";
  r.effects = "velocity_histogram+energy_error";
  r.n = n;
  r.steps = steps;
  AwNaiveArgs a = naive_args(o, init, n, steps, precision == "float");
  a.device = ordinal;
  std::vector<double> t;
  for (int i = 0; i < std::max(1, o.repeat); ++i) {
    AwNaiveOut out{};
    int rc = 1;
    if (which == "naive-openmp") {
      rc = aw_naive_openmp_run(&a, &out);
    } else {
      const NaiveCuda& nc = naive_cuda();
      if (!nc) {
        r.note = nc.problem;
        return r;
      }
      rc = nc.run(&a, &out);
    }
    if (rc != 0) {
      r.note = out.error;
      return r;
    }
    r.name = out.device_name;
    r.emax = out.emax;
    t.push_back(out.seconds);
  }
  r.seconds = median(t);
  r.seconds_min = *std::min_element(t.begin(), t.end());
  r.repeats = static_cast<int>(t.size());
  r.rate = static_cast<double>(n) * static_cast<double>(steps) / r.seconds;
  return r;
}

// ---------------------------------------------------------------- memory

double computed_device_bytes(const Plan& plan, std::uint64_t max_chunk, unsigned group) {
  // The buffers of every backend (backends/ensemble_backend.cpp):
  // parameters, 32- and 64-bit maps, counters, (max, sum) per group.
  const double rs = plan.kernel.precision == Precision::Float ? 4 : 8;
  const double groups = static_cast<double>(max_chunk / group + 2);
  const double npix = static_cast<double>(std::max<std::uint64_t>(plan.npix, 1));
  const double params = 8192;  // the two parameter blocks (lib/device/aw_param_blocks.h), a few kB
  return params + npix * 12 + 4.0 * 512 + 2 * groups * rs;
}

MemoryRow measure_memory(Backend& b, const Options& o, std::uint64_t n) {
  MemoryRow m;
  m.device = b.info().id;
  m.name = b.info().name;
  m.n = n;
  m.measured_bytes = -1;
  Scene s = scene_for(o, "default", "double", "portable", n, 5000);  // Figure 3: 50 T at 0.01 T
  const Plan plan = make_plan(s);
  // the chunk bound of run(): 2^30, and 32-bit counts per window
  const std::uint64_t max_chunk =
      std::min<std::uint64_t>({1ull << 30, 4000000000ull / static_cast<std::uint64_t>(plan.windows), n});
  m.computed_bytes = computed_device_bytes(plan, max_chunk, 128);
  const NaiveCuda& nc = naive_cuda();
  const bool cuda = b.info().backend == "cuda" && nc.mem_info;
  const int ordinal = cuda ? std::stoi(b.info().id.substr(5)) : 0;
  unsigned long long f0 = 0, f1 = 0, total = 0;
  if (cuda) nc.mem_info(ordinal, &f0, &total);
  b.prepare(plan, max_chunk);
  if (cuda && nc.mem_info(ordinal, &f1, &total) == 0) m.measured_bytes = static_cast<double>(f0) - static_cast<double>(f1);
  return m;
}

// ---------------------------------------------------------------- output

const char* kCsvHeader =
    "kind,device,name,backend,cpu,precision,math,variant,effects,trajectories,steps,seconds,seconds_min,"
    "repeats,rate,baseline,ratio,emax,driver,note";

std::string csv_quote(const std::string& s) {
  std::string o = "\"";
  for (char c : s) o += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return o + "\"";
}

void write_csv(const fs::path& p, const std::vector<Row>& rows) {
  std::ofstream f(p.string() + ".tmp");
  f << kCsvHeader << "\n";
  for (const Row& r : rows)
    f << r.kind << ',' << r.device << ',' << csv_quote(r.name) << ',' << r.backend << ',' << (r.cpu ? 1 : 0) << ','
      << r.precision << ',' << r.math << ',' << r.variant << ',' << r.effects << ',' << r.n << ',' << r.steps << ','
      << fmt(r.seconds, "%.6g") << ',' << fmt(r.seconds_min, "%.6g") << ',' << r.repeats << ','
      << fmt(r.rate, "%.5g") << ',' << r.baseline << ',' << fmt(r.ratio, "%.4g") << ',' << fmt(r.emax, "%.3g")
      << ',' << csv_quote(r.driver) << ',' << csv_quote(r.note) << "\n";
  f.close();
  fs::rename(p.string() + ".tmp", p);
}

void write_json(const fs::path& p, const Report& rep, const Options& o) {
  nlohmann::json j;
  j["date"] = rep.date;
  j["host"] = rep.host;
  j["command"] = rep.command;
  j["energy"] = o.energy;
  j["step_T"] = o.step;
  j["method"] = "yoshida6a";
  nlohmann::json devs = nlohmann::json::array();
  for (const auto& d : list_devices())
    devs.push_back({{"id", d.id}, {"name", d.name}, {"vendor", d.vendor}, {"version", d.version},
                    {"compute_units", d.compute_units}, {"memory", d.memory}, {"cpu", d.is_cpu}});
  j["devices"] = devs;
  nlohmann::json rows = nlohmann::json::array();
  for (const Row& r : rep.rows)
    rows.push_back({{"kind", r.kind}, {"device", r.device}, {"name", r.name}, {"backend", r.backend},
                    {"cpu", r.cpu}, {"precision", r.precision}, {"math", r.math}, {"variant", r.variant},
                    {"effects", r.effects}, {"trajectories", r.n}, {"steps", r.steps}, {"seconds", r.seconds},
                    {"seconds_min", r.seconds_min}, {"repeats", r.repeats}, {"rate", r.rate},
                    {"baseline", r.baseline}, {"ratio", r.ratio}, {"emax", r.emax}, {"driver", r.driver},
                    {"note", r.note}});
  j["rows"] = rows;
  nlohmann::json mem = nlohmann::json::array();
  for (const auto& m : rep.memory)
    mem.push_back({{"device", m.device}, {"name", m.name}, {"trajectories", m.n},
                   {"computed_bytes", m.computed_bytes}, {"measured_bytes", m.measured_bytes}});
  j["memory"] = mem;
  std::ofstream f(p.string() + ".tmp");
  f << j.dump(1) << "\n";
  f.close();
  fs::rename(p.string() + ".tmp", p);
}

void print_rows(std::ostream& log, const std::vector<Row>& rows, bool with_ratio) {
  char b[512];
  std::snprintf(b, sizeof b, "| %-14s | %-28.28s | %-6s | %-8s | %-14s | %10s | %5s | %9s | %10s | %s |\n", "device",
                "name", "prec", "math", "variant", "N", "steps", "s", "traj-steps/s",
                with_ratio ? "x baseline" : "note");
  log << b << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    std::string last = r.note.empty() ? (with_ratio && r.ratio > 0 ? fmt(r.ratio, "%.2f") + " (" + r.baseline + ")"
                                                                 : std::string(r.kind == "baseline" ? "baseline" : "-"))
                                      : "ERROR: " + r.note.substr(0, 120);
    std::snprintf(b, sizeof b, "| %-14s | %-28.28s | %-6s | %-8s | %-14s | %10llu | %5lld | %9.3f | %10.3e | %s |\n",
                  r.device.c_str(), r.name.c_str(), r.precision.c_str(), r.math.c_str(), r.variant.c_str(),
                  static_cast<unsigned long long>(r.n), static_cast<long long>(r.steps), r.seconds, r.rate,
                  last.c_str());
    log << b;
  }
  log.flush();
}

void apply_preset(Options& o) {
  if (o.preset.empty()) return;
  if (o.preset == "ci") {
    if (o.cpu_sizes.empty()) o.cpu_sizes = {1024, 4096};
    if (o.sizes.empty()) o.sizes = {16384, 65536};
    o.cpu_steps = 200;
    o.steps = 400;
    o.repeat = 1;
    o.effects_cpu_size = 2048;
    o.effects_size = 65536;
  } else if (o.preset == "dev") {
    if (o.cpu_sizes.empty()) o.cpu_sizes = {2048, 8192, 32768};
    if (o.sizes.empty()) o.sizes = {65536, 1048576, 4194304};
    o.cpu_steps = 400;
  } else if (o.preset == "gpu") {
    if (o.sizes.empty()) o.sizes = {16384, 65536, 262144, 1048576, 4194304, 8388608};
    if (o.cpu_sizes.empty()) o.cpu_sizes = {16384, 65536, 262144};
    o.steps = 2000;
    o.cpu_steps = 200;
    o.effects_size = 4194304;
    o.effects_cpu_size = 65536;
    if (o.memory_sizes.empty()) o.memory_sizes = {1000000000ull};
  } else {
    throw CLI::ValidationError("--preset", "unknown preset " + o.preset + " (ci, dev, gpu)");
  }
}


}  // namespace

void add_options(CLI::App* c, Options& o) {
  auto counts = [](std::vector<std::uint64_t>& dst) {
    return [&dst](const std::vector<std::string>& v) {
      dst.clear();
      for (const auto& s : v) dst.push_back(parse_count(s));
    };
  };
  c->add_option("--devices,-d", o.devices, "Device ids (comma-separated; default: every device present)")
      ->delimiter(',');
  c->add_option_function<std::vector<std::string>>("--sizes", counts(o.sizes),
                                                   "Ensemble sizes N on GPUs, e.g. 65536,1e6,4e6")
      ->delimiter(',');
  c->add_option_function<std::vector<std::string>>("--cpu-sizes", counts(o.cpu_sizes),
                                                   "Ensemble sizes N on CPU devices (cpu, PoCL)")
      ->delimiter(',');
  c->add_option("--steps", o.steps, "Steps per trajectory on GPUs (h = 0.01 T)")->capture_default_str();
  c->add_option("--cpu-steps", o.cpu_steps, "Steps per trajectory on CPU devices")->capture_default_str();
  c->add_option("--precision", o.precisions, "double,float")->delimiter(',')->capture_default_str();
  c->add_option("--variants", o.variants,
                "Figure-1 variants: default (map + energy tracking), bare (map only), energy_limit, "
                "final_states, initial_states")
      ->delimiter(',')
      ->capture_default_str();
  c->add_option("--math", o.math, "portable or native (Figure-1 sweep)")->capture_default_str();
  c->add_flag("!--no-baselines", o.baselines, "Skip the naive OpenMP / CUDA baselines");
  c->add_flag("!--no-figure", o.figure, "Skip the throughput-vs-N sweep");
  c->add_flag("--effects", o.effects, "Measure the cost of each effect, float vs double, portable vs native");
  c->add_option_function<std::string>("--effects-size", [&o](const std::string& s) { o.effects_size = parse_count(s); },
                                      "N of the effects table on GPUs");
  c->add_option_function<std::string>("--effects-cpu-size",
                                      [&o](const std::string& s) { o.effects_cpu_size = parse_count(s); },
                                      "N of the effects table on CPU devices");
  c->add_option_function<std::vector<std::string>>("--memory", counts(o.memory_sizes),
                                                   "Report GPU memory of a map run of these N (e.g. 1e9)")
      ->delimiter(',');
  c->add_option("--repeat", o.repeat, "Timed runs per point (median reported)")->capture_default_str();
  c->add_option("--out,-o", o.out_dir, "Output directory (bench.csv, bench.json, effects.csv, memory.csv, PNG)")
      ->capture_default_str();
  c->add_flag("!--no-plot", o.plot, "Do not print the command that draws the PNG");
  c->add_option("--scene", o.scene,
                "Also time this scene end to end (device open, compile, every chunk) on each device");
  c->add_option("--scene-set", o.scene_sets, "key=value overrides for --scene (repeatable)");
  c->add_option("--preset", o.preset, "ci (seconds), dev (a few minutes on 2 cores), gpu (GPU machine)");
}

namespace {

// What the stages of one bench run share.
struct Session {
  Options& o;
  std::ostream& log;
  Report rep;
  int failures = 0;
  std::vector<DeviceInfo> devices;
  std::vector<std::string> cuda_ids;
  bool any_cpu = false, any_gpu = false;
};

// The devices asked for, described in the log.
void open_session(Session& s, const std::string& command) {
  Options& o = s.o;
  std::ostream& log = s.log;
  s.rep.date = today_utc();
  s.rep.host = hostname();
  s.rep.command = command;
  for (const auto& d : list_devices())
    if (o.devices.empty() || std::find(o.devices.begin(), o.devices.end(), d.id) != o.devices.end())
      s.devices.push_back(d);
  log << "arnoldweb bench: Yoshida-6, E = " << o.energy << ", h = " << o.step << " T, " << s.rep.date << " on "
      << s.rep.host << "\n";
  for (const auto& d : s.devices) log << "  " << d.id << ": " << d.name << " (" << d.version << ")\n";
  for (const auto& p : backend_problems()) log << "  note: " << p << "\n";
  const NaiveCuda& nc = naive_cuda();
  log << "  naive CUDA baseline: " << (nc ? nc.path : nc.problem) << "\n";
  log.flush();
  s.any_cpu = std::any_of(s.devices.begin(), s.devices.end(), [](const DeviceInfo& d) { return d.is_cpu; });
  s.any_gpu = std::any_of(s.devices.begin(), s.devices.end(), [](const DeviceInfo& d) { return !d.is_cpu; });
  for (const auto& d : s.devices)
    if (d.backend == "cuda") s.cuda_ids.push_back(d.id);
}

// The library's throughput against N on every device.
void library_rows(Session& s, std::vector<Row>& fig) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  int& failures = s.failures;
  const auto& devices = s.devices;
  for (const auto& d : devices) {
    std::unique_ptr<Backend> b;
    try {
      b = open_backend(d.id);
    } catch (const std::exception& e) {
      Row r;
      r.kind = "library";
      r.device = d.id;
      r.name = d.name;
      r.note = e.what();
      fig.push_back(r);
      ++failures;
      continue;
    }
    const auto& sizes = d.is_cpu ? o.cpu_sizes : o.sizes;
    const std::int64_t steps = d.is_cpu ? o.cpu_steps : o.steps;
    for (const auto& prec : o.precisions)
      for (const auto& var : o.variants)
        for (std::uint64_t n : sizes) {
          Row r = measure_library(*b, o, "library", var, prec, o.math, n, steps);
          if (!r.note.empty()) ++failures;
          print_rows(log, {r}, false);
          fig.push_back(r);
        }
  }
}

// The baselines at the same N, steps and initial states, and the ratios.
void baseline_rows(Session& s, std::vector<Row>& fig) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  int& failures = s.failures;
  const bool any_cpu = s.any_cpu, any_gpu = s.any_gpu;
  const auto& cuda_ids = s.cuda_ids;
  const NaiveCuda& nc = naive_cuda();
  if (!o.baselines) return;
  std::uint64_t nmax = 0;
  if (any_cpu) nmax = std::max(nmax, *std::max_element(o.cpu_sizes.begin(), o.cpu_sizes.end()));
  if (!cuda_ids.empty()) nmax = std::max(nmax, *std::max_element(o.sizes.begin(), o.sizes.end()));
  std::vector<double> init;
  if (nmax) {
    const auto t0 = clock::now();
    init = initial_states(o, nmax);
    log << "baselines: initial states of " << nmax << " trajectories from the library in "
        << fmt(std::chrono::duration<double>(clock::now() - t0).count()) << " s\n";
  }
  for (const auto& prec : o.precisions) {
    if (any_cpu)
      for (std::uint64_t n : o.cpu_sizes) {
        Row r = measure_baseline(o, "naive-openmp", 0, init, prec, n, o.cpu_steps);
        print_rows(log, {r}, false);
        fig.push_back(r);
      }
    if (any_gpu && nc)
      for (const auto& id : cuda_ids)
        for (std::uint64_t n : o.sizes) {
          Row r = measure_baseline(o, "naive-cuda", std::stoi(id.substr(5)), init, prec, n, o.steps);
          if (!r.note.empty()) ++failures;
          print_rows(log, {r}, false);
          fig.push_back(r);
        }
  }
  // ratios: CPU devices to the OpenMP baseline, GPUs to the first CUDA baseline
  for (Row& r : fig) {
    if (r.kind != "library" || r.rate <= 0) continue;
    const std::string want = r.cpu ? "naive-openmp" : (cuda_ids.empty() ? "" : "naive-" + cuda_ids.front());
    for (const Row& b : fig)
      if (b.kind == "baseline" && b.device == want && b.precision == r.precision && b.n == r.n &&
          b.steps == r.steps && b.rate > 0) {
        r.baseline = b.device;
        r.ratio = r.rate / b.rate;
      }
  }
}

// Figure 1: throughput against N, with the baselines.
void figure_table(Session& s) {
  if (!s.o.figure) return;
  std::vector<Row> fig;
  library_rows(s, fig);
  baseline_rows(s, fig);
  s.log << "\nFigure 1: throughput against N (Yoshida-6, E = " << s.o.energy << ", h = " << s.o.step
        << " T; ratio to the baseline at the same N, steps and precision)\n";
  print_rows(s.log, fig, true);
  s.rep.rows = fig;
}

// The cost of every effect against the bare map.
void effects_table(Session& s) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  int& failures = s.failures;
  const auto& devices = s.devices;
  Report& rep = s.rep;
  std::vector<Row> eff;
  if (o.effects) {
    const std::vector<std::string> vars = {"bare", "default", "energy_limit", "final_states", "confine", "zoom", "frames"};
    for (const auto& d : devices) {
      std::unique_ptr<Backend> b;
      try {
        b = open_backend(d.id);
      } catch (const std::exception& e) {
        continue;
      }
      const std::uint64_t n = d.is_cpu ? o.effects_cpu_size : o.effects_size;
      const std::int64_t steps = d.is_cpu ? o.cpu_steps : o.steps;
      for (const auto& prec : o.precisions)
        for (const char* math : {"portable", "native"})
          for (const auto& var : vars) {
            Row r = measure_library(*b, o, "effects", var, prec, math, n, steps);
            if (!r.note.empty()) ++failures;
            eff.push_back(r);
          }
    }
    // relative to the bare map of the same device, precision and math
    for (Row& r : eff)
      for (const Row& b : eff)
        if (b.variant == "bare" && b.device == r.device && b.precision == r.precision && b.math == r.math &&
            b.rate > 0)
          r.ratio = r.rate / b.rate, r.baseline = "bare";
    log << "\nCost of effects (ratio: throughput relative to the bare map, same device, precision, math)\n";
    print_rows(log, eff, true);
    write_csv(fs::path(o.out_dir) / "effects.csv", eff);
    rep.rows.insert(rep.rows.end(), eff.begin(), eff.end());
  }

}

// Device memory of large map runs.
void memory_table(Session& s) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  int& failures = s.failures;
  const auto& devices = s.devices;
  Report& rep = s.rep;
  if (!o.memory_sizes.empty()) {
    std::ofstream mf(fs::path(o.out_dir) / "memory.csv");
    mf << "device,name,trajectories,computed_bytes,measured_bytes\n";
    log << "\nDevice memory of a map run (Figure-3 schedule; measured: cudaMemGetInfo around prepare())\n";
    for (const auto& d : devices) {
      if (d.is_cpu) continue;
      for (std::uint64_t n : o.memory_sizes) {
        try {
          auto b = open_backend(d.id);
          MemoryRow m = measure_memory(*b, o, n);
          rep.memory.push_back(m);
          mf << m.device << ',' << csv_quote(m.name) << ',' << m.n << ',' << fmt(m.computed_bytes, "%.0f") << ','
             << fmt(m.measured_bytes, "%.0f") << "\n";
          log << "  " << m.device << " N = " << fmt(static_cast<double>(n)) << ": computed "
              << fmt(m.computed_bytes / 1048576.0, "%.1f") << " MiB, measured "
              << (m.measured_bytes >= 0 ? fmt(m.measured_bytes / 1048576.0, "%.1f") + " MiB" : std::string("-"))
              << "\n";
        } catch (const std::exception& e) {
          log << "  " << d.id << ": " << e.what() << "\n";
          ++failures;
        }
      }
    }
  }

}

// A whole scene, end to end (e.g. the paper's Figure 3).
void scene_rows(Session& s) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  int& failures = s.failures;
  const auto& devices = s.devices;
  Report& rep = s.rep;
  if (!o.scene.empty()) {
    std::vector<Row> sc;
    for (const auto& d : devices) {
      Row r;
      r.kind = "scene";
      r.device = d.id;
      r.name = d.name;
      r.backend = d.backend;
      r.driver = d.version;
      r.cpu = d.is_cpu;
      r.variant = fs::path(o.scene).filename().string();
      try {
        const auto t0 = clock::now();
        std::vector<std::string> sets = o.scene_sets;
        sets.push_back("run.device=" + d.id);
        const Plan plan = make_plan(load_scene(o.scene, sets));
        auto b = open_backend(d.id);
        const Result res = arnoldweb::run(plan, *b);
        r.seconds = std::chrono::duration<double>(clock::now() - t0).count();
        r.seconds_min = res.wall_seconds;
        r.repeats = 1;
        r.precision = to_string(plan.scene.precision);
        r.math = to_string(plan.scene.math);
        r.effects = join(plan.effects(), "+");
        r.n = res.completed;
        r.steps = plan.steps_per_trajectory;
        r.rate = res.trajectory_steps / r.seconds;
        r.emax = res.energy.max;
        r.note = "end to end incl. device open and compile; run() " + fmt(res.wall_seconds) + " s in " +
                 std::to_string(res.chunks.size()) + " chunks; binned " + std::to_string(res.binned);
      } catch (const std::exception& e) {
        r.note = std::string("ERROR ") + e.what();
        ++failures;
      }
      log << "scene " << o.scene << " on " << r.device << ": " << fmt(r.seconds, "%.2f") << " s, "
          << fmt(r.rate) << " trajectory-steps/s (" << r.note << ")\n";
      log.flush();
      sc.push_back(r);
    }
    rep.rows.insert(rep.rows.end(), sc.begin(), sc.end());
  }

}

void write_report(Session& s) {
  const Options& o = s.o;
  std::ostream& log = s.log;
  Report& rep = s.rep;
  write_csv(fs::path(o.out_dir) / "bench.csv", rep.rows);
  write_json(fs::path(o.out_dir) / "bench.json", rep, o);
  log << "\nwrote " << (fs::path(o.out_dir) / "bench.csv").string() << ", bench.json\n";
  if (o.plot && o.figure) {
    // The picture is drawn by a Python script; arnoldweb starts no other
    // program (and never a shell), so it says how.
#ifdef ARNOLDWEB_BENCH_PLOT_SCRIPT
    const std::string script = ARNOLDWEB_BENCH_PLOT_SCRIPT;
#else
    const std::string script = "bench/throughput/plot_bench.py";
#endif
    log << "plot: python3 " << script << " " << (fs::path(o.out_dir) / "bench.csv").string() << " "
        << (fs::path(o.out_dir) / "bench_throughput.png").string() << "\n";
  }
}

}  // namespace

int run(Options o, const std::string& command, std::ostream& log) {
  apply_preset(o);
  if (o.sizes.empty()) o.sizes = {65536, 1048576, 4194304};
  if (o.cpu_sizes.empty()) o.cpu_sizes = {4096, 16384};
  fs::create_directories(o.out_dir);
  Session s{o, log, {}, 0, {}, {}, false, false};
  open_session(s, command);
  figure_table(s);
  if (o.effects) effects_table(s);
  if (!o.memory_sizes.empty()) memory_table(s);
  if (!o.scene.empty()) scene_rows(s);
  write_report(s);
  return s.failures ? 1 : 0;
}

}  // namespace arnoldweb::bench
