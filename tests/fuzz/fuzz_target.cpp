// The libFuzzer entry point of one target; CLOUDSHAPE_FUZZ_CHECK names its check (fuzz_checks.hpp).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      cloudshape::fuzz::CLOUDSHAPE_FUZZ_CHECK(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz finding: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
