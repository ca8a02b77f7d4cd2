// The named scene layouts: which solids, where, and what touches what. Every length is a
// multiple of the recipe's scale and every random draw is independent of it, so a scene at
// scale 1000 is the scene at scale 1 times 1000.
#include "synth/scene_layout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "synth/scene_placement.hpp"
#include "synth/solid_support.hpp"

namespace cloudshape::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

ShapeKind random_kind(std::mt19937_64& rng) {
  return all_shape_kinds()[std::uniform_int_distribution<std::size_t>(0, 5)(rng)];
}

// Lines the solids [first, end) up along +x from `start`, each gap drawn from [gap_lo, gap_hi]
// (gap_hi 0: every neighbour touches the next).
void line_up(std::vector<SolidSpec>& solids, std::size_t first, double start, double gap_lo,
             double gap_hi, std::mt19937_64& rng) {
  double cursor = start;
  for (std::size_t i = first; i < solids.size(); ++i) {
    if (i > first) cursor += gap_hi > 0.0 ? uniform(rng, gap_lo, gap_hi) : 0.0;
    set_lowest(solids[i], kX, cursor);
    cursor = highest(solids[i], kX);
  }
}

void shift_all(std::vector<SolidSpec>& solids, const Eigen::Vector3d& offset) {
  for (auto& s : solids) translate(s, offset);
}

// Moves the arrangement so the middle of its footprint is over the origin.
void centre_footprint(std::vector<SolidSpec>& solids) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& s : solids) {
    x0 = std::min(x0, lowest(s, kX)), x1 = std::max(x1, highest(s, kX));
    y0 = std::min(y0, lowest(s, kY)), y1 = std::max(y1, highest(s, kY));
  }
  shift_all(solids, Eigen::Vector3d(-0.5 * (x0 + x1), -0.5 * (y0 + y1), 0.0));
}

// Places resting solids at random centres between min_range and max_range from the origin
// (the reach grows when the solids crowd), their bounding spheres at least `gap` apart.
void scatter(std::vector<SolidSpec>& solids, double min_range, double max_range, double gap,
             std::mt19937_64& rng) {
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const double ri = bounding_radius(solids[i]);
    double reach = max_range;
    for (int attempt = 0;; ++attempt) {
      if (attempt > 0 && attempt % 100 == 0) reach *= 1.2;
      const double angle = uniform(rng, 0.0, 2.0 * kPi);
      const double range = std::sqrt(uniform(rng, min_range * min_range, reach * reach));
      const Eigen::Vector3d at(range * std::cos(angle), range * std::sin(angle), 0.0);
      bool clear = true;
      for (std::size_t j = 0; j < i && clear; ++j) {
        const Eigen::Vector2d d = (at - solids[j].pose.center).head<2>();
        clear = d.norm() > ri + bounding_radius(solids[j]) + gap;
      }
      if (!clear) continue;
      translate(solids[i], Eigen::Vector3d(at.x() - solids[i].pose.center.x(),
                                           at.y() - solids[i].pose.center.y(), 0.0));
      break;
    }
  }
}

std::vector<SolidSpec> random_resting(std::size_t count, std::mt19937_64& rng, double unit) {
  std::vector<SolidSpec> solids;
  for (std::size_t i = 0; i < count; ++i)
    solids.push_back(resting_solid(random_kind(rng), rng, unit));
  return solids;
}

// A box of random height whose footprint is a fraction of the lower box's top face.
SolidSpec smaller_box(const SolidSpec& lower, std::mt19937_64& rng) {
  std::vector<double> top;
  for (int k = 0; k < 3; ++k)
    if (std::abs(lower.pose.axes(k, 2)) < 0.5) top.push_back(lower.dimensions[k].second);
  const double a = top.at(0) * uniform(rng, 0.5, 0.9), b = top.at(1) * uniform(rng, 0.5, 0.9);
  // Height in proportion to the footprint keeps a tall stack from ending in a thin post.
  return make_solid(ShapeKind::box, {a, b, 0.5 * (a + b) * uniform(rng, 0.4, 1.2)});
}

void lidar_structure(Scene& scene, int walls, double unit, std::mt19937_64& rng) {
  const double half = 15.0 * unit, wall_half_height = 1.5 * unit;
  scene.structure.push_back({"plane", Eigen::Vector3d::Zero(), kX, kY, half, half, 1});
  if (walls >= 1)
    scene.structure.push_back(
        {"wall", Eigen::Vector3d(0.0, uniform(rng, 7.0, 10.0) * unit, wall_half_height), kX, kZ,
         half, wall_half_height, 2});
  if (walls >= 2)
    scene.structure.push_back(
        {"wall", Eigen::Vector3d(uniform(rng, 7.0, 10.0) * unit, 0.0, wall_half_height), kY, kZ,
         half, wall_half_height, 3});
}

}  // namespace

std::string to_string(SceneLayout layout) {
  switch (layout) {
    case SceneLayout::touching:
      return "touching";
    case SceneLayout::stacked:
      return "stacked";
    case SceneLayout::row:
      return "row";
    case SceneLayout::wall:
      return "wall";
    case SceneLayout::random:
      return "random";
    case SceneLayout::lidar:
      return "lidar";
  }
  return "?";
}

const std::vector<SceneLayout>& all_scene_layouts() {
  static const std::vector<SceneLayout> all{SceneLayout::touching, SceneLayout::stacked,
                                            SceneLayout::row,      SceneLayout::wall,
                                            SceneLayout::random,   SceneLayout::lidar};
  return all;
}

std::optional<SceneLayout> scene_layout_from_string(std::string_view name) {
  for (const auto layout : all_scene_layouts())
    if (to_string(layout) == name) return layout;
  return std::nullopt;
}

GeneratedScene make_scene(const SceneRecipe& recipe) {
  const bool pairs =
      recipe.layout == SceneLayout::touching || recipe.layout == SceneLayout::stacked;
  if (recipe.count < (pairs ? 2u : 1u) || recipe.count > 5)
    throw std::invalid_argument("--count: " + to_string(recipe.layout) + " takes " +
                                (pairs ? "2" : "1") + " to 5 objects, not " +
                                std::to_string(recipe.count));
  if (!(recipe.scale > 0.0) || !std::isfinite(recipe.scale))
    throw std::invalid_argument("--scale: must be positive and finite");
  if (recipe.walls < -1 || recipe.walls > 2) throw std::invalid_argument("--walls: 0, 1 or 2");
  if (recipe.layout == SceneLayout::wall && recipe.walls == 0)
    throw std::invalid_argument("--walls: the wall layout stands its objects against 1 or 2 walls");
  const int walls = recipe.walls >= 0                     ? recipe.walls
                    : recipe.layout == SceneLayout::wall  ? 1
                    : recipe.layout == SceneLayout::lidar ? 2
                                                          : 0;
  std::seed_seq seed{recipe.seed, static_cast<std::uint64_t>(recipe.layout),
                     std::uint64_t{0x7363656e65}};
  std::mt19937_64 rng(seed);
  const double unit = recipe.scale;

  GeneratedScene out;
  std::vector<SolidSpec> solids;
  std::optional<double> back_wall, side_wall;
  switch (recipe.layout) {
    case SceneLayout::row:
    case SceneLayout::wall:
      solids = random_resting(recipe.count, rng, unit);
      for (auto& s : solids)
        translate(s, Eigen::Vector3d(0.0, uniform(rng, -0.03, 0.03) * unit, 0.0));
      line_up(solids, 0, 0.0, 0.03 * unit, 0.08 * unit, rng);
      centre_footprint(solids);
      break;
    case SceneLayout::touching:
      for (std::size_t i = 0; i < recipe.count; ++i) {
        solids.push_back(uniform(rng, 0.0, 1.0) < 0.6 ? aligned_box(rng, unit)
                                                      : standing_cylinder(rng, unit));
        if (i > 0) out.touching.emplace_back(i - 1, i);
      }
      line_up(solids, 0, 0.0, 0.0, 0.0, rng);
      centre_footprint(solids);
      break;
    case SceneLayout::stacked: {
      solids.push_back(aligned_box(rng, unit));
      yaw(solids[0], uniform(rng, 0.0, 2.0 * kPi));
      const std::size_t height = std::min<std::size_t>(recipe.count, 3);
      for (std::size_t i = 1; i < height; ++i) {
        SolidSpec upper = smaller_box(solids[i - 1], rng);
        stack_on(upper, solids[i - 1], rng);
        solids.push_back(upper);
        out.stacked.emplace_back(i, i - 1);
      }
      for (std::size_t i = height; i < recipe.count; ++i)
        solids.push_back(resting_solid(random_kind(rng), rng, unit));
      double stack_right = -1e300;
      for (std::size_t i = 0; i < height; ++i)
        stack_right = std::max(stack_right, highest(solids[i], kX));
      line_up(solids, height, stack_right + uniform(rng, 0.03, 0.08) * unit, 0.03 * unit,
              0.08 * unit, rng);
      centre_footprint(solids);
      break;
    }
    case SceneLayout::random:
      solids = random_resting(recipe.count, rng, unit);
      scatter(solids, 0.0, 0.15 * unit * std::sqrt(static_cast<double>(recipe.count)), 0.02 * unit,
              rng);
      centre_footprint(solids);
      break;
    case SceneLayout::lidar:
      // A calibration-sized sphere, then objects larger than a table holds.
      solids.push_back(make_solid(ShapeKind::sphere, {uniform(rng, 0.25, 0.35) * unit}));
      set_lowest(solids[0], kZ, 0.0);
      for (std::size_t i = 1; i < recipe.count; ++i)
        solids.push_back(resting_solid(random_kind(rng), rng, 4.0 * unit));
      scatter(solids, 2.5 * unit, 6.0 * unit, 0.3 * unit, rng);
      break;
  }
  if (recipe.layout == SceneLayout::wall) {
    back_wall = 0.0;
    for (std::size_t i = 0; i < solids.size(); ++i) {
      set_highest(solids[i], kY, 0.0);
      out.against_wall.emplace_back(i, 2);
    }
    if (walls >= 2) {
      side_wall = highest(solids.back(), kX);
      out.against_wall.emplace_back(solids.size() - 1, 3);
    }
  } else if (recipe.layout != SceneLayout::lidar) {
    double y1 = -1e300, x1 = -1e300;
    for (const auto& s : solids)
      y1 = std::max(y1, highest(s, kY)), x1 = std::max(x1, highest(s, kX));
    if (walls >= 1) back_wall = y1 + uniform(rng, 0.05, 0.2) * unit;
    if (walls >= 2) side_wall = x1 + uniform(rng, 0.05, 0.2) * unit;
  }

  for (std::size_t i = 0; i < solids.size(); ++i)
    out.scene.objects.push_back({solids[i], static_cast<std::uint32_t>(20 + 10 * i)});
  if (recipe.layout == SceneLayout::lidar) {
    lidar_structure(out.scene, walls, unit, rng);
    out.lidar = true;
    out.sensor.position = Eigen::Vector3d(0.0, 0.0, uniform(rng, 1.0, 1.8) * unit);
  } else {
    add_structure(out.scene, back_wall, side_wall, unit, rng);
    out.sensor =
        table_camera(out.scene, walls, recipe.layout == SceneLayout::row, recipe.fov_y_deg, rng);
  }
  return out;
}

}  // namespace cloudshape::synth
