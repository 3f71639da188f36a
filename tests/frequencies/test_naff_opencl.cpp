// The frequency analysis through OpenCL (PoCL here): naff_driver.h, compiled
// as an OpenCL C 1.2 kernel from the embedded device sources, gives the same
// bits as on the host, in double and in float, with one trajectory per
// work-item and inside a program built for eight lanes (the width PoCL's
// ensemble kernels use; the analysis itself is scalar).
#include <doctest/doctest.h>

#include <boost/compute/core.hpp>
#include <cmath>
#include <complex>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "backends/kernel_sources.hpp"
#include "naff_cases.hpp"
#include "support.hpp"

namespace compute = boost::compute;

namespace {

const char* kKernel = R"(
#include "aw_naff.h"
#include "naff_driver.h"
__kernel void naff_test(__global real* re, __global real* im, __global real* wre, __global real* wim,
                        __global real* out, int count, int n, int p, int terms, int log2m) {
  const int j = (int)get_global_id(0);
  if (j < count) naff_test_analyse(re, im, wre, wim, out, j, count, n, p, terms, log2m);
}
)";

std::string driver_text() {
  std::ifstream in(std::string(ARNOLDWEB_SOURCE_DIR) + "/tests/frequencies/naff_driver.h");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The OpenCL device of an arnoldweb id "opencl:N" (platforms in order, their devices in order).
compute::device device_of(const std::string& id) {
  const int index = std::stoi(id.substr(id.find(':') + 1));
  int i = 0;
  for (const auto& platform : compute::system::platforms())
    for (const auto& d : platform.devices())
      if (i++ == index) return d;
  throw std::runtime_error("no OpenCL device " + id);
}

// naff_driver.h over a chunk on `dev`, in Real (double or float).
template <class Real>
std::vector<Real> run_opencl(const compute::device& dev, const naff_test::Chunk& c, int p, int terms, int log2m,
                             int lanes) {
  const bool fl = sizeof(Real) == sizeof(float);
  compute::context context(dev);
  compute::command_queue queue(context, dev);
  const std::string source = arnoldweb::detail::flatten_source(
      "naff_test.cl", {{"naff_test.cl", kKernel}, {"naff_driver.h", driver_text()}});
  std::string options = "-DAW_LANES=" + std::to_string(lanes);
  if (fl) options += " -DAW_FLOAT=1 -cl-fp32-correctly-rounded-divide-sqrt";
  compute::program program = compute::program::create_with_source(source, context);
  try {
    program.build(options);
  } catch (const compute::opencl_error&) {
    FAIL("OpenCL build failed:\n" << program.build_log());
  }
  compute::kernel kernel = program.create_kernel("naff_test");
  std::vector<Real> re(c.re.begin(), c.re.end()), im(c.im.begin(), c.im.end());
  const std::size_t work = (std::size_t{1} << log2m) * c.count, results = std::size_t(c.count) * terms * 5;
  compute::buffer bre(context, re.size() * sizeof(Real)), bim(context, im.size() * sizeof(Real));
  compute::buffer bwre(context, work * sizeof(Real)), bwim(context, work * sizeof(Real));
  compute::buffer bout(context, results * sizeof(Real));
  queue.enqueue_write_buffer(bre, 0, re.size() * sizeof(Real), re.data());
  queue.enqueue_write_buffer(bim, 0, im.size() * sizeof(Real), im.data());
  kernel.set_args(bre, bim, bwre, bwim, bout, c.count, c.n, p, terms, log2m);
  queue.enqueue_1d_range_kernel(kernel, 0, static_cast<std::size_t>(c.count), 0);
  std::vector<Real> out(results);
  queue.enqueue_read_buffer(bout, 0, results * sizeof(Real), out.data());
  return out;
}

// Elements that differ in their bits (NaN payloads are not compared: a caller
// writes its own NaN where ok = 0), -1 if none.
template <class Real>
long first_difference_but_nan(const std::vector<Real>& a, const std::vector<Real>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(Real)) != 0 && !(std::isnan(a[i]) && std::isnan(b[i])))
      return static_cast<long>(i);
  return -1;
}

// 37 signals: quasi-periodic with frequencies and amplitudes varied per
// signal, one of them broken by a NaN.
naff_test::Chunk test_chunk(int n) {
  std::vector<std::vector<naff_test::Term>> signals;
  for (int j = 0; j < 37; ++j)
    signals.push_back({{0.05 + 0.013 * j, std::polar(1.0, 0.1 * j)},
                       {-0.31 + 0.007 * j, std::polar(0.3 + 0.01 * j, -0.2 * j)},
                       {0.41 - 0.005 * j, std::polar(0.1, 0.5)}});
  naff_test::Chunk c = naff_test::make_chunk(signals, n, 1.0);
  c.re[std::size_t(n / 2) * c.count + 11] = std::nan("");
  return c;
}

}  // namespace

TEST_SUITE("frequencies-opencl") {
  TEST_CASE("OpenCL gives the host's bits: double and float, one lane and eight") {
    std::vector<arnoldweb::DeviceInfo> devices;
    for (const auto& d : awtest::devices_under_test())
      if (d.backend == "opencl") devices.push_back(d);
    if (!awtest::require(!devices.empty(), "frequencies-opencl", "no OpenCL device on this machine")) return;
    const int n = 1000, terms = 2;
    const naff_test::Chunk c = test_chunk(n);
    const int log2m = naff_test::fft_log2(n);
    for (int p : {1, 2}) {
      const std::vector<double> host_d = naff_test::analyse_double(c, p, terms, log2m);
      const std::vector<float> host_f = naff_test::analyse_float(c, p, terms, log2m);
      CHECK(host_d[11 * terms * 5 + 4] == 0);  // the broken signal: not refined
      CHECK(host_d[12 * terms * 5 + 4] == 1);
      for (const auto& d : devices) {
        const compute::device dev = device_of(d.id);
        for (int lanes : {1, 8}) {
          CAPTURE(d.id);
          CAPTURE(p);
          CAPTURE(lanes);
          if (d.fp64) CHECK(first_difference_but_nan(run_opencl<double>(dev, c, p, terms, log2m, lanes), host_d) == -1);
          CHECK(first_difference_but_nan(run_opencl<float>(dev, c, p, terms, log2m, lanes), host_f) == -1);
        }
      }
    }
  }
}
