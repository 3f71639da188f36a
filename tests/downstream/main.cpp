// Runs a tiny ensemble through the installed library and checks the counts.
#include <arnoldweb/arnoldweb.hpp>

#include <cstdio>

int main() {
  arnoldweb::Scene s = arnoldweb::parse_scene(
      "[ensemble]\ntrajectories = 64\n[run]\naverage = 0.5\nduration = 0.5\n[observe]\n"
      "velocity_map = { nside = 4 }\nenergy_error = { every = 0.25 }\n",
      "downstream.toml");
  const arnoldweb::Plan plan = arnoldweb::make_plan(s);
  auto backend = arnoldweb::open_backend("cpu");
  const arnoldweb::Result r = arnoldweb::run(plan, *backend);
  std::printf("arnoldweb %s: %llu binned, map %s\n", ARNOLDWEB_VERSION, static_cast<unsigned long long>(r.binned),
              arnoldweb::digest_map(r).c_str());
  return r.binned == 64 ? 0 : 1;
}
