// Runs a tiny ensemble through the installed library and checks the counts.
#include <arnoldweb/arnoldweb.hpp>

#include <cstdio>
#include <filesystem>

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
  if (r.binned != 64) return 1;
#ifdef EXPECT_PICTURES
  // the pictures' plugin is found beside the installed library
  const std::string png = (std::filesystem::temp_directory_path() / "arnoldweb-downstream-map.png").string();
  try {
    arnoldweb::render_sphere_png(png, r.map, 4, arnoldweb::RenderOptions{});
  } catch (const arnoldweb::Error& e) {
    std::printf("no picture: %s\n", e.what());
    return 1;
  }
  const bool drawn = std::filesystem::file_size(png) > 1000;
  std::filesystem::remove(png);
  std::printf("map picture drawn through the installed plugin\n");
  if (!drawn) return 1;
#endif
  return 0;
}
