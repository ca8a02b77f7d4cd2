// The shared sample data (../shared/data beside the repository) as the tests reach it, and
// the one rule for when it is missing: a failure under CI (CI=true), a skip elsewhere.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace cloudshape::testing {

// CI=true (as .ci/run and the usual CI services set it): the real-data tests must run.
inline bool ci_run() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && (std::string(ci) == "true" || std::string(ci) == "1");
}

// `relative` under the shared data folder (CLOUDSHAPE_SHARED_DATA_DIR, e.g. "real/ycb").
inline std::filesystem::path shared_data_path(const std::string& relative) {
  return std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / relative;
}

// Empty when `path` exists; otherwise what to tell the reader about it.
inline std::string shared_data_missing(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) return {};
  return "shared data missing: " + path.string() + " (check out shared/ beside the repository" +
         (ci_run() ? "; CI=true requires it)" : "; skipped outside CI, CI=true fails instead)");
}

}  // namespace cloudshape::testing

// In a test body: stops the test when `path` (a file or folder of the shared data) is absent,
// as a failure under CI and as a skip elsewhere. A macro because both must return from the
// test itself.
#define CLOUDSHAPE_REQUIRE_SHARED_DATA(path)                                                  \
  do {                                                                                        \
    const std::string cloudshape_missing_ = ::cloudshape::testing::shared_data_missing(path); \
    if (cloudshape_missing_.empty()) break;                                                   \
    if (::cloudshape::testing::ci_run()) FAIL() << cloudshape_missing_;                       \
    GTEST_SKIP() << cloudshape_missing_;                                                      \
  } while (false)
