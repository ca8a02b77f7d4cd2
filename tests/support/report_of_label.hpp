// Which reported object stands for a labelled one: the report holding most of its points, as the
// scene benchmark matches them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::testing {

// The report whose point_indices hold most points of `labels` equal to `label`; null when none
// holds any. `labels`: per input point, its truth label.
inline const pipeline::ObjectResult* report_of_label(
    const std::vector<pipeline::ObjectResult>& reports, const std::vector<std::uint32_t>& labels,
    std::uint32_t label) {
  const pipeline::ObjectResult* holder = nullptr;
  std::size_t most = 0;
  for (const auto& o : reports) {
    std::size_t held = 0;
    for (std::uint32_t i : o.point_indices) held += labels[i] == label ? 1 : 0;
    if (held > most) most = held, holder = &o;
  }
  return holder;
}

}  // namespace cloudshape::testing
