// arnoldweb bench: throughput in trajectory-steps per second against the
// ensemble size N, on every device present, for Yoshida-6 at E = 15,
// h = 0.01 T (the paper's Figure 1), with the plain baselines of
// bench/baselines timed in the same process; the cost of each effect; device
// memory of large map runs. Used by `arnoldweb bench` and `arnoldweb_bench`.
// Timings are reported, never asserted.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace arnoldweb::bench {

struct Options {
  std::vector<std::string> devices;          // empty: every device present
  std::vector<std::uint64_t> sizes;          // N on GPUs and other non-CPU devices
  std::vector<std::uint64_t> cpu_sizes;      // N on CPU devices (cpu backend, PoCL)
  std::int64_t steps = 2000;                 // steps per trajectory (GPUs)
  std::int64_t cpu_steps = 400;              // steps per trajectory (CPU devices)
  std::vector<std::string> precisions = {"double", "float"};
  std::vector<std::string> variants = {"default", "bare"};  // Figure 1 variants
  std::string math = "portable";
  bool baselines = true;
  bool figure = true;                        // the throughput-vs-N sweep
  bool effects = false;                      // the cost-of-effects table
  std::uint64_t effects_size = 4194304;      // N for the effects table (GPUs)
  std::uint64_t effects_cpu_size = 16384;    // N for the effects table (CPU devices)
  std::vector<std::uint64_t> memory_sizes;   // prepare() at these N on GPUs, report memory
  int repeat = 3;                            // timed runs per point (median reported)
  double energy = 15.0;
  double step = 0.01;                        // T
  std::string out_dir = "bench-out";
  bool plot = true;                          // print the command that draws the plot
  std::string preset;                        // "ci", "dev", "gpu" (sets the sizes)
  std::string scene;                         // time this scene end to end on each device
  std::vector<std::string> scene_sets;       // --set overrides for it
};

// One measured point.
struct Row {
  std::string kind;       // "library", "baseline", "effects"
  std::string device;     // "cpu", "opencl:0", "cuda:0", "naive-openmp", "naive-cuda:0"
  std::string name;       // device name
  std::string backend;    // cpu, opencl, cuda, naive-openmp, naive-cuda
  std::string driver;     // driver / platform version
  bool cpu = false;       // a CPU device (compared with the OpenMP baseline)
  std::string precision;  // double, float
  std::string math;       // portable, native (vendor functions for the baselines)
  std::string variant;    // default, bare, energy_limit, final_states, initial_states
  std::string effects;    // feature names, '+'-joined
  std::uint64_t n = 0;
  std::int64_t steps = 0;
  double seconds = 0;     // median of the timed runs
  double seconds_min = 0;
  int repeats = 0;
  double rate = 0;        // trajectory-steps per second (median)
  double ratio = 0;       // rate / baseline rate at the same N, steps, precision (0: none)
  std::string baseline;   // the baseline divided by
  double emax = 0;        // energy error seen (a sanity figure)
  std::string note;       // errors, skipped reasons
};

struct MemoryRow {
  std::string device, name;
  std::uint64_t n = 0;
  double computed_bytes = 0;  // buffers the backend allocates (formula)
  double measured_bytes = 0;  // cudaMemGetInfo before/after prepare() (-1: not measured)
};

struct Report {
  std::string date, host, command;
  std::vector<Row> rows;
  std::vector<MemoryRow> memory;
};

// Registers the options on a CLI11 command (shared by the CLI and the bench program).
void add_options(CLI::App* app, Options& o);

// Runs what the options ask for; prints progress and tables to `log`; writes
// bench.csv, bench.json (+ effects.csv, memory.csv, bench_throughput.png) to
// o.out_dir. Returns 0, or 1 if some point failed (the rest still ran).
int run(Options o, const std::string& command, std::ostream& log);

}  // namespace arnoldweb::bench
