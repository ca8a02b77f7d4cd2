// Joins the per-object result messages of a cloud (the solver publishes one per object)
// into the cloud's complete list, as cloudshape-echo needs to print one line per cloud.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cloudshape.h"

namespace cloudshape::dds {

class ResultJoiner {
 public:
  // Adds one object's result; returns every object of its cloud, in object order, once the
  // last one arrived. A cloud of 0 or 1 object completes at once.
  std::optional<std::vector<msg::ShapeResult>> add(msg::ShapeResult result) {
    const std::uint32_t count = result.header().object_count();
    if (count <= 1) return std::vector<msg::ShapeResult>{std::move(result)};
    const Key key{result.header().cloud_id(), result.header().source()};
    auto& slots = pending_[key];
    slots.resize(count);
    const std::uint32_t index = result.header().object_index();
    if (index >= count) return std::nullopt;  // malformed: never completes a cloud
    slots[index] = std::move(result);
    for (const auto& s : slots) {
      if (!s) return std::nullopt;
    }
    std::vector<msg::ShapeResult> all;
    for (auto& s : slots) all.push_back(std::move(*s));
    pending_.erase(key);
    return all;
  }

  std::size_t incomplete() const { return pending_.size(); }

 private:
  using Key = std::pair<std::uint64_t, std::string>;
  std::map<Key, std::vector<std::optional<msg::ShapeResult>>> pending_;
};

}  // namespace cloudshape::dds
