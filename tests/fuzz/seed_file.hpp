// Writes one fuzz seed file: a message serialized by its generated type (CDR with encapsulation),
// the bytes a DataReader receives. Shared by the seed writers of the ingest and pointcloud2 targets.
#pragma once

#include <cstdio>
#include <fstream>
#include <string>

#include <fastdds/rtps/common/SerializedPayload.h>

namespace cloudshape::fuzz {

// DIR/NAME.cdr; false (and a line on stderr naming `tool`) when it does not serialize or write.
template <class PubSub, class Message>
bool write_seed(const std::string& dir, const std::string& name, Message& m, const char* tool) {
  PubSub type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(&m)());
  if (!type.serialize(&m, &payload)) {
    std::fprintf(stderr, "%s: %s does not serialize\n", tool, name.c_str());
    return false;
  }
  const std::string path = dir + "/" + name + ".cdr";
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(payload.data), payload.length);
  if (!out) {
    std::fprintf(stderr, "%s: cannot write %s\n", tool, path.c_str());
    return false;
  }
  return true;
}

}  // namespace cloudshape::fuzz
