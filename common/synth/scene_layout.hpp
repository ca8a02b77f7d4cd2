// Named arrangements of solids for synthetic scenes (touching, stacked, a row, against walls,
// random, a lidar yard), each with its structure and a sensor pose that sees it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "synth/range_sensor.hpp"
#include "synth/scene.hpp"

namespace cloudshape::synth {

enum class SceneLayout { touching, stacked, row, wall, random, lidar };

std::string to_string(SceneLayout layout);
std::optional<SceneLayout> scene_layout_from_string(std::string_view name);
const std::vector<SceneLayout>& all_scene_layouts();

struct SceneRecipe {
  SceneLayout layout = SceneLayout::row;
  std::size_t count = 3;  // objects, 1..5 (touching and stacked need at least 2)
  std::uint64_t seed = 1;
  double scale = 1.0;  // the scene's unit: 1 = a table in metres, 1000 = the same in millimetres
  int walls = -1;      // 0, 1 or 2; -1 takes the layout's own (wall: 1, lidar: 2, others: 0)
  double fov_y_deg = 45.0;  // of the camera that will look at a table scene
};

struct GeneratedScene {
  Scene scene;  // world frame, z up, the support plane at z = 0
  SensorPose sensor;
  bool lidar = false;  // the sensor is a lidar (z up) rather than a depth camera
  // Pairs of object indices placed flush against each other (gap 0), and (upper, lower) pairs
  // of a stack: what the layout promises, for tests and for the truth file.
  std::vector<std::pair<std::size_t, std::size_t>> touching, stacked;
  // (object index, wall label) for objects pushed flush against a wall.
  std::vector<std::pair<std::size_t, std::uint32_t>> against_wall;
};

// Throws std::invalid_argument for a count out of range or a bad scale or wall count.
GeneratedScene make_scene(const SceneRecipe& recipe);

// Where a table scene's camera looks from: above the objects and in front of any wall; along
// the row (oblique, from either end) when `along_row`, so the objects partly hide each other.
SensorPose table_camera(const Scene& scene, int walls, bool along_row, double fov_y_deg,
                        std::mt19937_64& rng);

// A support plane under the objects with a margin, and walls behind (+y) and to the side (+x)
// at the given positions (nullopt: none).
void add_structure(Scene& scene, std::optional<double> back_wall_y,
                   std::optional<double> side_wall_x, double unit, std::mt19937_64& rng);

}  // namespace cloudshape::synth
