// The DDS acceptance criterion as a function: two sets of results (recognizer vs echo) agree per
// source, field by field: numbers within kSameTolerance, axes up to the contract's freedom.
#pragma once

#include <string>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::testing {

// Relative (absolute below 1). Coordinates travel as float64 and the JSON keeps 17 digits, so
// DDS and in-process results are the same numbers; this only absorbs last-bit noise.
inline constexpr double kSameTolerance = 1e-9;

// One human-readable line per difference of `actual` from `expected`, each prefixed with `where`.
std::vector<std::string> result_differences(const pipeline::RecognitionResult& expected,
                                            const pipeline::RecognitionResult& actual, const std::string& where);

// The same for JSON lines matched by source; empty when the results agree. A line that is not
// a result, a source twice, missing or unexpected is a difference too, not an exception.
std::vector<std::string> result_differences(const std::vector<std::string>& expected_lines,
                                            const std::vector<std::string>& actual_lines);

}  // namespace cloudshape::testing
