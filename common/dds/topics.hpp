// The pipeline's topic names and the IDL type each carries (README "DDS topics" table).
// One place, so services, tools and other programs agree on every name.
#pragma once

#include "cloudshape.h"
#include "cloudshapePubSubTypes.h"

namespace cloudshape::dds {

// Pairs a topic name with its generated type and TopicDataType (`name` must outlive the spec's
// endpoints: a literal here, a kept string for a ROS 2 topic named at run time).
template <class Msg, class PubSub>
struct TopicSpec {
  using Message = Msg;
  using PubSubType = PubSub;
  const char* name;
};

namespace topics {
inline constexpr TopicSpec<msg::RawCloud, msg::RawCloudPubSubType> raw_cloud{"cloudshape_raw_cloud"};
inline constexpr TopicSpec<msg::FilteredCloud, msg::FilteredCloudPubSubType> filtered_cloud{
    "cloudshape_filtered_cloud"};
inline constexpr TopicSpec<msg::PlanesAndLines, msg::PlanesAndLinesPubSubType> planes{
    "cloudshape_planes"};
inline constexpr TopicSpec<msg::KeypointCloud, msg::KeypointCloudPubSubType> keypoints{
    "cloudshape_keypoints"};
inline constexpr TopicSpec<msg::ClassifiedKeypoints, msg::ClassifiedKeypointsPubSubType> classified{
    "cloudshape_classified"};
inline constexpr TopicSpec<msg::ShapeResult, msg::ShapeResultPubSubType> result{"cloudshape_result"};
inline constexpr TopicSpec<msg::ServiceStatus, msg::ServiceStatusPubSubType> status{
    "cloudshape_status"};
}  // namespace topics

}  // namespace cloudshape::dds
