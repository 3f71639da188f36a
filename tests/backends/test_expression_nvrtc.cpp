// Expression models compile with NVRTC (no GPU needed): the emitted header
// takes the built-in's place, in double and float, and the kernel image
// cache tells two potentials apart.
#ifdef ARNOLDWEB_HAVE_CUDA

#include <doctest/doctest.h>

#include "../physics/expression_cases.hpp"
#include "arnoldweb/arnoldweb.hpp"
#include "aw_params.h"
#include "backends/cuda/kernel_cache.hpp"
#include "backends/cuda/nvrtc_compiler.hpp"
#include "physics/expression/expression_model.hpp"

namespace ex = arnoldweb::detail::expression;
namespace detail = arnoldweb::detail;

TEST_SUITE("nvrtc") {
  TEST_CASE("an expression model compiles with NVRTC in double and float") {
    const detail::CudaTarget sm90{90, true};
    const ex::ExpressionModel paper = ex::make_expression_model(awtest::paper_potential(), {});
    const ex::ExpressionModel mixed = ex::make_expression_model(awtest::mixed_potential(), {{"a", 0.3}, {"b", -1.7}});
    for (auto precision : {arnoldweb::Precision::Double, arnoldweb::Precision::Float}) {
      arnoldweb::KernelConfig k;
      k.precision = precision;
      k.features = AW_F_VELOCITY_MAP | AW_F_ENERGY;
      k.stages = 7;
      k.model = ex::kExpressionModelId;
      for (const auto* m : {&paper, &mixed}) {
        detail::CudaImage img;
        try {
          img = detail::nvrtc_compile_ensemble(k.defines(), sm90, "nvrtc test", m->device_header);
        } catch (const arnoldweb::BuildError& e) {
          FAIL_CHECK(e.what());
          continue;
        }
        CHECK(img.data.find("aw_ensemble") != std::string::npos);
      }
      // without the header, AW_MODEL 1000 does not compile: the header is what is used
      CHECK_THROWS_AS(detail::nvrtc_compile_ensemble(k.defines(), sm90, "nvrtc test"), arnoldweb::BuildError);
    }
    // two potentials, two cache entries
    arnoldweb::KernelConfig k;
    k.model = ex::kExpressionModelId;
    k.stages = 1;
    const auto a = detail::cuda_ensemble_image(k.defines(), sm90, "test", paper.device_header);
    const auto b = detail::cuda_ensemble_image(k.defines(), sm90, "test", mixed.device_header);
    CHECK(a.image->data != b.image->data);
    CHECK_FALSE(a.image.get() == b.image.get());
  }
}

#endif  // ARNOLDWEB_HAVE_CUDA
