// arnoldweb: the planner's part for the chaos indicators and grids (indicators.hpp).
#include "plan/indicators.hpp"

#include <cmath>

#include "aw_params.h"
#include "plan/checks.hpp"

namespace arnoldweb::detail {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;

bool written(const Scene& s, const std::string& key) {
  const SourcePos pos = s.pos(key);
  return pos.line > 0 || pos.set_index > 0;
}

std::array<double, 3> position_turns(const Scene& s) {
  return {s.grid_position[0] / kTwoPi, s.grid_position[1] / kTwoPi, s.grid_position[2] / kTwoPi};
}

}  // namespace

std::uint64_t grid_points(const Scene& s) {
  if (s.initial != "grid") return 0;
  if (s.grid_kind == "healpix") return 12ull * static_cast<std::uint64_t>(s.grid_nside) * s.grid_nside;
  return static_cast<std::uint64_t>(s.grid_resolution[0]) * static_cast<std::uint64_t>(s.grid_resolution[1]);
}

Scene with_grid_size(const Scene& scene) {
  const std::uint64_t n = grid_points(scene);
  if (!n || scene.trajectories == n) return scene;
  if (written(scene, "ensemble.trajectories"))
    fail_at(scene, "ensemble.trajectories",
            "ensemble.initial = \"grid\" integrates one trajectory per grid point: the grid has " + show_count(n) +
                " points, ensemble.trajectories says " + show_count(scene.trajectories) +
                "; leave ensemble.trajectories out or set it to " + show_count(n));
  Scene s = scene;
  s.trajectories = n;
  return s;
}

void plan_grid(const Scene& scene, const ModelDescriptor& model, const RealParams& rp, Plan& p) {
  p.accessible_fraction = 1;
  if (scene.grid_kind == "plane") return;
  const auto u = position_turns(scene);
  const double v = model.potential(u[0], u[1], u[2], rp);
  if (!(scene.energy > v))
    fail_at(scene, "ensemble.grid.position",
            "the grid's position has V = " + show_number(v) + " >= E = " + show_number(scene.energy) +
                ": no momentum has that energy there; choose a position with V < E or a larger model.energy");
}

void fill_indicator_reals(const Scene& scene, const Plan& p, RealParams& rp) {
  rp.tangent_step = p.step;  // (the initial tangent vector: its direction key in the output table)
  if (scene.initial != "grid") return;
  const auto u = position_turns(scene);
  for (int i = 0; i < 3; ++i) rp.grid_position[i] = u[static_cast<std::size_t>(i)];
  if (scene.grid_kind == "lonlat") {
    rp.grid_lo[0] = scene.box_lon[0] / 360.0;
    rp.grid_width[0] = (scene.box_lon[1] - scene.box_lon[0]) / 360.0;
    rp.grid_lo[1] = scene.box_lat[0] / 360.0;
    rp.grid_width[1] = (scene.box_lat[1] - scene.box_lat[0]) / 360.0;
  } else if (scene.grid_kind == "plane") {
    rp.grid_lo[0] = scene.grid_range1[0];
    rp.grid_width[0] = scene.grid_range1[1] - scene.grid_range1[0];
    rp.grid_lo[1] = scene.grid_range2[0];
    rp.grid_width[1] = scene.grid_range2[1] - scene.grid_range2[0];
    rp.grid_fixed = scene.grid_fixed;
  }
}

void fill_indicator_ints(const Scene& scene, IntParams& ip) {
  if (scene.initial != "grid") return;
  if (scene.grid_kind == "healpix") {
    ip.grid_kind = AW_GRID_HEALPIX;
    ip.grid_n[0] = scene.grid_nside;
    ip.grid_n[1] = 1;
  } else {
    ip.grid_kind = scene.grid_kind == "lonlat" ? AW_GRID_LONLAT : AW_GRID_PLANE;
    ip.grid_n[0] = static_cast<std::int64_t>(scene.grid_resolution[0]);
    ip.grid_n[1] = static_cast<std::int64_t>(scene.grid_resolution[1]);
  }
  const int a = static_cast<int>(scene.grid_axes[0]), b = static_cast<int>(scene.grid_axes[1]);
  ip.grid_axes[0] = a;
  ip.grid_axes[1] = b;
  ip.grid_axes[2] = 3 - a - b;
}

}  // namespace arnoldweb::detail
