// The one exception a received raw cloud that cannot be processed raises; ingest turns it into
// the cloud's error result (refused_raw_cloud), so what() must name the problem.
#pragma once

#include <stdexcept>

namespace cloudshape::dds {

// A raw cloud that cannot be processed; what() says why (the header names the cloud).
class RawCloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cloudshape::dds
