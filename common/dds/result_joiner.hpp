// Joins the per-object result messages of a cloud (the solver publishes one per object)
// into the cloud's complete list, once, dropping duplicates (a cloud sent again after a fault).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cloudshape.h"

namespace cloudshape::dds {

class ResultJoiner {
 public:
  // `remembered`: how many completed clouds are remembered to drop their duplicates, and
  // how many incomplete clouds are kept at most: memory stays bounded on an endless stream.
  explicit ResultJoiner(std::size_t remembered = 4096) : remembered_(remembered) {}

  // Adds one object's result; returns every object of its cloud, in object order, once the
  // last one arrived. A cloud of 0 or 1 object completes at once. A sample of a cloud already
  // completed, or an object already held, is a duplicate: dropped and counted.
  std::optional<std::vector<msg::ShapeResult>> add(msg::ShapeResult result) {
    const Key key{result.header().cloud_id(), result.header().source()};
    if (completed_.count(key) != 0) {
      ++duplicates_;
      return std::nullopt;
    }
    const std::uint32_t count = result.header().object_count();
    if (count <= 1) {
      remember(key);
      return std::vector<msg::ShapeResult>{std::move(result)};
    }
    const std::uint32_t index = result.header().object_index();
    if (index >= count) return std::nullopt;  // malformed: never completes a cloud
    auto& objects = pending_[key];
    if (!objects.emplace(index, std::move(result)).second) {
      ++duplicates_;
      return std::nullopt;
    }
    if (objects.size() < count) {
      // The oldest incomplete cloud goes when too many are open (its rest never came).
      if (pending_.size() > remembered_) pending_.erase(pending_.begin());
      return std::nullopt;
    }
    std::vector<msg::ShapeResult> all;
    for (auto& [i, object] : objects) all.push_back(std::move(object));
    pending_.erase(key);
    remember(key);
    return all;
  }

  std::size_t incomplete() const { return pending_.size(); }
  std::uint64_t duplicates() const { return duplicates_; }

 private:
  using Key = std::pair<std::uint64_t, std::string>;

  void remember(const Key& key) {
    completed_.insert(key);
    completion_order_.push_back(key);
    if (completion_order_.size() > remembered_) {
      completed_.erase(completion_order_.front());
      completion_order_.pop_front();
    }
  }

  std::size_t remembered_;
  std::map<Key, std::map<std::uint32_t, msg::ShapeResult>> pending_;
  std::set<Key> completed_;
  std::deque<Key> completion_order_;
  std::uint64_t duplicates_ = 0;
};

}  // namespace cloudshape::dds
