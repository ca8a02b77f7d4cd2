// What every process-level DDS test needs from its environment: its domain id, shifted by
// CLOUDSHAPE_TEST_DOMAIN_OFFSET, and a private folder for its clouds and logs.
#pragma once

#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace cloudshape::testing {

// CLOUDSHAPE_TEST_DOMAIN_OFFSET shifts every test's domain, so that two checkouts can run
// their DDS tests on one machine at the same time without hearing each other.
inline int domain_offset() {
  const char* v = std::getenv("CLOUDSHAPE_TEST_DOMAIN_OFFSET");
  return v == nullptr ? 0 : std::atoi(v);
}

// A new folder /tmp/cloudshape-<name>-XXXXXX.
inline std::string make_temp_dir(const std::string& name) {
  std::string templ = (std::filesystem::temp_directory_path() / ("cloudshape-" + name + "-XXXXXX")).string();
  if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return templ;
}

}  // namespace cloudshape::testing
