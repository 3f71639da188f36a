// arnoldweb: opening several devices at once (open_at_once.hpp).
#include "backends/open_at_once.hpp"

#include <exception>
#include <thread>

namespace arnoldweb::detail {

std::vector<std::unique_ptr<Backend>> open_at_once(const std::vector<std::string>& ids, const OpenDevice& open) {
  std::vector<std::unique_ptr<Backend>> backends(ids.size());
  std::vector<std::exception_ptr> errors(ids.size());
  auto open_one = [&](std::size_t i) {
    try {
      backends[i] = open(ids[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i < ids.size(); ++i) threads.emplace_back(open_one, i);
  if (!ids.empty()) open_one(0);
  for (auto& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);  // the backends opened close as `backends` goes
  return backends;
}

}  // namespace arnoldweb::detail
