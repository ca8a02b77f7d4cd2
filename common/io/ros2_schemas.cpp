// The ros2msg schema texts a recording carries for the messages cloudshape writes: the message's
// definition, then each type it uses after a "MSG: pkg/Type" separator, as rosbag2 stores them.
#include "io/ros2_schemas.hpp"

#include <map>
#include <stdexcept>
#include <vector>

namespace cloudshape::io {
namespace {

// Type names are written in full (pkg/Type) so no reader has to guess a package.
const std::map<std::string, std::string>& definitions() {
  static const std::map<std::string, std::string> all = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n"},
      {"geometry_msgs/Pose", "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
      {"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n"},
      {"sensor_msgs/PointField",
       "uint8 INT8=1\nuint8 UINT8=2\nuint8 INT16=3\nuint8 UINT16=4\nuint8 INT32=5\nuint8 UINT32=6\n"
       "uint8 FLOAT32=7\nuint8 FLOAT64=8\nstring name\nuint32 offset\nuint8 datatype\nuint32 count\n"},
      {"sensor_msgs/PointCloud2",
       "std_msgs/Header header\nuint32 height\nuint32 width\nsensor_msgs/PointField[] fields\n"
       "bool is_bigendian\nuint32 point_step\nuint32 row_step\nuint8[] data\nbool is_dense\n"},
      {"sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data\n"},
      {"vision_msgs/ObjectHypothesis", "string class_id\nfloat64 score\n"},
      {"vision_msgs/ObjectHypothesisWithPose",
       "vision_msgs/ObjectHypothesis hypothesis\ngeometry_msgs/PoseWithCovariance pose\n"},
      {"vision_msgs/BoundingBox3D", "geometry_msgs/Pose center\ngeometry_msgs/Vector3 size\n"},
      {"vision_msgs/Detection3D",
       "std_msgs/Header header\nvision_msgs/ObjectHypothesisWithPose[] results\nvision_msgs/BoundingBox3D bbox\n"
       "string id\n"},
      {"vision_msgs/Detection3DArray", "std_msgs/Header header\nvision_msgs/Detection3D[] detections\n"},
      {"visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"},
      {"visualization_msgs/MeshFile", "string filename\nuint8[] data\n"},
      {"visualization_msgs/Marker",
       "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\nint32 LINE_LIST=5\n"
       "int32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\nint32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\n"
       "int32 TRIANGLE_LIST=11\nint32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\nint32 DELETEALL=3\n"
       "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\ngeometry_msgs/Pose pose\n"
       "geometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\nbuiltin_interfaces/Duration lifetime\n"
       "bool frame_locked\ngeometry_msgs/Point[] points\nstd_msgs/ColorRGBA[] colors\nstring texture_resource\n"
       "sensor_msgs/CompressedImage texture\nvisualization_msgs/UVCoordinate[] uv_coordinates\nstring text\n"
       "string mesh_resource\nvisualization_msgs/MeshFile mesh_file\nbool mesh_use_embedded_materials\n"},
      {"visualization_msgs/MarkerArray", "visualization_msgs/Marker[] markers\n"},
  };
  return all;
}

// The types a definition uses, each once, depth first in order of appearance.
void collect(const std::string& type, std::vector<std::string>& order) {
  const std::string& body = definitions().at(type);
  std::size_t line_start = 0;
  while (line_start < body.size()) {
    const std::size_t line_end = body.find('\n', line_start);
    const std::string line = body.substr(line_start, line_end - line_start);
    line_start = line_end + 1;
    std::string field_type = line.substr(0, line.find(' '));
    field_type = field_type.substr(0, field_type.find('['));
    if (field_type.find('/') == std::string::npos) continue;  // a primitive or a constant
    bool seen = false;
    for (const std::string& t : order) seen = seen || t == field_type;
    if (seen) continue;
    order.push_back(field_type);
    collect(field_type, order);
  }
}

}  // namespace

std::string ros2_schema_text(const std::string& schema_name) {
  const std::size_t msg = schema_name.find("/msg/");
  const std::string type =
      msg == std::string::npos ? schema_name : schema_name.substr(0, msg) + "/" + schema_name.substr(msg + 5);
  if (schema_name != kPointCloud2SchemaName && schema_name != kDetection3DArraySchemaName &&
      schema_name != kMarkerArraySchemaName) {
    throw std::invalid_argument("no ros2msg schema for '" + schema_name + "'");
  }
  std::vector<std::string> order;
  collect(type, order);
  std::string text = definitions().at(type);
  for (const std::string& dependency : order) {
    text += std::string(80, '=') + "\nMSG: " + dependency + "\n" + definitions().at(dependency);
  }
  return text;
}

}  // namespace cloudshape::io
