// RecognitionResult <-> the JSON object of INTERFACE.md ("cloudshape-recognize" and
// "cloudshape-echo" output), with its exact key order:
//   source, points_in, points_used, resolution,
//   objects[{shape, confidence, dimensions{..}, pose{center, axes}, partial,
//            keypoints{corner, edge, border}, extent{center, axes, size},
//            polygon (prism), vertices + regular (tetrahedron), reason (only when non-empty)}],
//   timings_ms{preprocess, planes, keypoints, classify, solve, total}
// Lengths, pose and confidence are written at full double precision (they round-trip
// exactly); timings are rounded to 0.01 ms.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::report {

// A JSON value that is not a recognizer result: names the offending key path and the problem.
class ResultFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

nlohmann::ordered_json result_to_json(const pipeline::RecognitionResult& result);

// The compact one-line form (JSON Lines; no trailing newline). Invalid UTF-8 in `source`
// is replaced by U+FFFD rather than throwing.
std::string result_to_json_line(const pipeline::RecognitionResult& result);

// The same object, indented (for --pretty).
std::string result_to_json_pretty(const pipeline::RecognitionResult& result, int indent = 2);

// Parses a result. Required keys must be present with the right types (extra keys are ignored,
// so newer producers stay readable); throws ResultFormatError otherwise. Dimensions of the
// shapes named in INTERFACE.md come back in its canonical order (e.g. length, width, height),
// other dimension names after them in input order.
pipeline::RecognitionResult result_from_json(const nlohmann::json& json);
pipeline::RecognitionResult result_from_json(const nlohmann::ordered_json& json);
// Parses one JSON line; malformed JSON is a ResultFormatError too.
pipeline::RecognitionResult result_from_json_line(const std::string& line);

// The dimension names INTERFACE.md lists for `shape`, in order (prism: `side` only for a
// regular cross-section); empty for "unknown" and for shape names it does not know.
const std::vector<std::string>& dimension_names(const std::string& shape);

// The shape names INTERFACE.md defines (unknown included).
const std::vector<std::string>& known_shape_names();

// Timings as written: rounded to 0.01 ms.
double round_timing_ms(double ms);

// Every way `json` departs from the INTERFACE.md contract (key set and order, types, shape and
// dimension names, box length >= width >= height, orthonormal axes, counts >= 0, confidence in
// [0, 1], ...); empty when it conforms. For tests of every producer (recognize, echo).
std::vector<std::string> schema_problems(const nlohmann::ordered_json& json);

}  // namespace cloudshape::report
