// The DDS acceptance criterion as a function: two sets of result JSON lines (recognizer vs
// echo) agree per source file: same shape, counts and reason, numbers within 1e-6 relative.
#pragma once

#include <string>
#include <vector>

namespace cloudshape::testing {

// One human-readable line per difference; empty when the results agree. A line that is not a
// result is reported, not thrown.
std::vector<std::string> result_differences(const std::vector<std::string>& expected_lines,
                                            const std::vector<std::string>& actual_lines);

}  // namespace cloudshape::testing
