// arnoldweb: opening several devices at once (open_backends). A GPU's context
// and its driver's start-up take a fraction of a second each; opened one after
// the other, a list of N devices paid N of them before its first launch.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "arnoldweb/device.hpp"

namespace arnoldweb::detail {

using OpenDevice = std::function<std::unique_ptr<Backend>(const std::string& id)>;

// open(id) for every id, each in a thread of its own (the first in the
// calling thread): the backends in the order of `ids`. When some fail, every
// thread is joined and the backends opened are closed, then the error of the
// first failing id in the order of `ids` is thrown (whichever failed first in
// time), as it was thrown.
std::vector<std::unique_ptr<Backend>> open_at_once(const std::vector<std::string>& ids, const OpenDevice& open);

}  // namespace arnoldweb::detail
