// Test helper: cloud messages serialized as the generated types do, then broken where Fast CDR
// refuses them (the header's error flag, a CDR boolean, set to 2) while their cloud id and
// source, at the start, still read: what a faulty or hostile publisher could send.
#pragma once

#include <fastdds/rtps/common/SerializedPayload.h>

#include <cstddef>
#include <memory>
#include <stdexcept>

namespace cloudshape::testing {

using eprosima::fastrtps::rtps::SerializedPayload_t;

// `m` serialized by the generated type `PubSub` (CDR with encapsulation). On the heap because
// SerializedPayload_t copies only its pointer (a copy would free the bytes twice).
template <class PubSub, class Message>
std::unique_ptr<SerializedPayload_t> serialized(const Message& m) {
  PubSub type;
  Message copy = m;
  auto payload = std::make_unique<SerializedPayload_t>(type.getSerializedSizeProvider(&copy)());
  if (!type.serialize(&copy, payload.get())) {
    throw std::logic_error("the generated type did not serialize");
  }
  return payload;
}

// Where the header's error flag of `m` lies in its CDR: the one byte that changes with it.
template <class PubSub, class Message>
std::size_t error_flag_byte(Message m) {
  m.header().error(false);
  const auto clear = serialized<PubSub>(m);
  m.header().error(true);
  const auto set = serialized<PubSub>(m);
  for (std::size_t i = 0; i < clear->length && i < set->length; ++i) {
    if (clear->data[i] != set->data[i]) return i;
  }
  throw std::logic_error("the error flag changes no byte");
}

// Sets the error flag's byte of an already serialized `m` to 2: Fast CDR throws on it.
template <class PubSub, class Message>
void break_error_flag(const Message& m, SerializedPayload_t& payload) {
  payload.data[error_flag_byte<PubSub>(m)] = 2;
}

// A generated type that breaks every sample it serializes (for a test's DataWriter).
template <class Message, class PubSub>
class CorruptingPubSubType : public PubSub {
 public:
  bool serialize(void* data, SerializedPayload_t* payload) override {
    if (!PubSub::serialize(data, payload)) return false;
    break_error_flag<PubSub>(*static_cast<const Message*>(data), *payload);
    return true;
  }
};

}  // namespace cloudshape::testing
