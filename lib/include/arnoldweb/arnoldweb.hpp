// arnoldweb: the whole public API.
#pragma once

#include "arnoldweb/accuracy.hpp"
#include "arnoldweb/analysis.hpp"
#include "arnoldweb/checkpoint.hpp"
#include "arnoldweb/device.hpp"
#include "arnoldweb/errors.hpp"
#include "arnoldweb/job.hpp"
#include "arnoldweb/methods.hpp"
#include "arnoldweb/output.hpp"
#include "arnoldweb/plan.hpp"
#include "arnoldweb/result.hpp"
#include "arnoldweb/run.hpp"
#include "arnoldweb/scene.hpp"
#include "arnoldweb/sphere.hpp"
#include "arnoldweb/states.hpp"
#include "arnoldweb/version.hpp"
