// The real samples of cloudshape-bench --accuracy: YCB scans and ravens CAD meshes with the
// face-to-face dimensions of shared/data/real/SOURCES.md as truth (no pose truth).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accuracy_score.hpp"

namespace cloudshape::bench {

// The table entries whose file exists under data_dir/real, in table order (empty when the
// folder is absent).
std::vector<std::size_t> present_real_samples(const std::string& shared_data_dir);

// Entry `entry` of the table, sampled at 20k points (seed 1). Throws io::ReadError when the
// mesh cannot be read.
TestCloud make_real_cloud(std::size_t entry, const std::string& shared_data_dir);

}  // namespace cloudshape::bench
