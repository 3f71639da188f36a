// arnoldweb devices: the devices present, and why a backend has none.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "arnoldweb/device.hpp"
#include "command.hpp"

namespace arnoldweb::cli {
namespace {

int list(bool json) {
  const auto devs = list_devices();
  if (json) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const auto& d : devs)
      j.push_back({{"id", d.id}, {"name", d.name}, {"vendor", d.vendor}, {"version", d.version}, {"fp64", d.fp64},
                   {"compute_units", d.compute_units}, {"memory", d.memory}, {"cpu", d.is_cpu}});
    std::cout << j.dump(1) << "\n";
    return 0;
  }
  std::printf("%-10s %-40s %-28s %-5s %6s %9s\n", "id", "name", "vendor", "fp64", "units", "memory");
  for (const auto& d : devs)
    std::printf("%-10s %-40.40s %-28.28s %-5s %6u %5.1f GiB\n", d.id.c_str(), d.name.c_str(),
                d.vendor.c_str(), d.fp64 ? "yes" : "no", d.compute_units,
                static_cast<double>(d.memory) / (1024.0 * 1024 * 1024));
  for (const auto& p : backend_problems()) std::printf("note: %s\n", p.c_str());
  std::printf("default (auto): %s\n", default_device_id().c_str());
  return 0;
}

}  // namespace

void add_devices_command(CLI::App& app, Action& action) {
  auto* c = app.add_subcommand("devices", "List the devices: id, name, vendor, fp64, compute units, memory");
  auto json = std::make_shared<bool>(false);
  c->add_flag("--json", *json, "Print JSON");
  c->callback([&action, json] { action = [json] { return list(*json); }; });
}

}  // namespace arnoldweb::cli
