// Where the 45 real Kinect frames of shared/data/real/mosd_learn are, for the tests that read them;
// CI must have them, a developer's checkout without shared/ skips.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace cloudshape::mosd {

inline const std::filesystem::path kDir =
    std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/mosd_learn";

inline bool data_missing() {
  if (std::filesystem::exists(kDir / "learn0.pcd")) return false;
  const char* ci = std::getenv("CI");
  if (ci && std::string(ci) == "true") ADD_FAILURE() << kDir << " missing on CI";
  return true;
}

inline std::string frame_path(int frame) {
  return (kDir / ("learn" + std::to_string(frame) + ".pcd")).string();
}

}  // namespace cloudshape::mosd
