// Ground truth of a synthetic scene as JSON: every object (recognizer schema plus its label and
// visible points), the structure, what touches what; and the label-to-shape sidecar of benchmarks.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "synth/range_sensor.hpp"
#include "synth/scene_layout.hpp"

namespace cloudshape::synth {

// `scene` in the frame of the written cloud (the sensor's). `sensor` describes the sensor.
// {"source", "layout", "seed", "scale", "points", "sensor", "view": [0,0,0],
//  "objects": [{shape, dimensions, pose, "partial": true, "label", "visible_points"}...],
//  "structure": [{"kind", "label", "center", "normal", "size": [2 half_u, 2 half_v]}...],
//  "touching": [[label, label]...], "stacked": [[upper, lower]...], "against_wall": [[object,
//  wall]...]}
nlohmann::json scene_truth_json(const std::string& source, const SceneRecipe& recipe,
                                const GeneratedScene& generated, const Scene& scene,
                                const RangeImage& image, const nlohmann::json& sensor);

// {"groups": {"20": "box", "30": "cylinder", ...}}: the objects with at least one point.
nlohmann::json scene_groups_json(const Scene& scene, const RangeImage& image);

}  // namespace cloudshape::synth
