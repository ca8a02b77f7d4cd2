// The fields of MCAP's Schema and Channel records, read in the specification's order; one place
// for the reader's data section and the index's summary section to share.
#pragma once

#include <string>

#include "io/detail/mcap_cursor.hpp"
#include "io/mcap_records.hpp"

namespace cloudshape::io::detail::mcap {

inline McapSchema read_schema_fields(RecordCursor& c) {
  McapSchema s;
  s.id = c.u16("id");
  s.name = std::string(c.string("name"));
  s.encoding = std::string(c.string("encoding"));
  s.data = std::string(c.string("data"));
  return s;
}

inline McapChannel read_channel_fields(RecordCursor& c) {
  McapChannel ch;
  ch.id = c.u16("id");
  ch.schema_id = c.u16("schema_id");
  ch.topic = std::string(c.string("topic"));
  ch.message_encoding = std::string(c.string("message_encoding"));
  ch.metadata = c.string_map("metadata");
  return ch;
}

}  // namespace cloudshape::io::detail::mcap
