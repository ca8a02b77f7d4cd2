// Mesh reader: OBJ through tinyobjloader, PLY faces (ascii and binary) through the shared PLY
// parser, fan triangulation, and index/face errors.
#include "io/mesh_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::append_le;
using test::expect_read_error;
using Triangle = std::array<std::uint32_t, 3>;

TEST(IoMeshReader, ObjWithQuadAndNegativeIndices) {
  test::TempDir dir;
  const std::string path = dir.write("quad.obj",
                                     "mtllib missing.mtl\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                     "usemtl none\n"
                                     "f 1 2 3 4\n"
                                     "f -5/1 -4/1 -1/1\n");
  const Mesh mesh = read_mesh(path);
  ASSERT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.vertices[2], Point(1, 1, 0));
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}));
}

TEST(IoMeshReader, ObjIndexOutOfRange) {
  test::TempDir dir;
  const std::string path = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 1 2 9\n");
  expect_read_error([&] { read_mesh(path); }, path, "face 2", "vertex index out of range (3 vertices)");
}

TEST(IoMeshReader, ObjWithoutFaces) {
  test::TempDir dir;
  const std::string path = dir.write("points.obj", "v 0 0 0\nv 1 0 0\n");
  expect_read_error([&] { read_mesh(path); }, path, "faces", "no faces");
}

TEST(IoMeshReader, ObjZeroIndexIsATinyobjError) {
  test::TempDir dir;
  const std::string path = dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n");
  expect_read_error([&] { read_mesh(path); }, path, "line 4", "Failed parse");
}

const char* const kAsciiPlyMesh =
    "ply\nformat ascii 1.0\n"
    "element vertex 5\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
    "element face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\nproperty float quality\n"
    "end_header\n"
    "0 0 0 9\n1 0 0 9\n1 1 0 9\n0 1 0 9\n0 0 1 9\n"
    "7 4 0 1 2 3 0.5\n"
    "7 3 0 1 4 0.5\n";

TEST(IoMeshReader, AsciiPlyFacesFanTriangulated) {
  const Mesh mesh = read_ply_mesh_buffer(kAsciiPlyMesh, "m.ply");
  ASSERT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.vertices[4], Point(0, 0, 1));
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}));
}

TEST(IoMeshReader, BinaryPlyFacesBeforeVertices) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\n"
      "element face 1\nproperty list uchar uint vertex_index\n"
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "end_header\n";
  append_le<std::uint8_t>(data, 4);
  for (std::uint32_t i : {3u, 2u, 1u, 0u}) append_le<std::uint32_t>(data, i);
  for (int v = 0; v < 4; ++v) {
    append_le<double>(data, v);
    append_le<double>(data, -v);
    append_le<double>(data, 0.5);
  }
  const Mesh mesh = read_ply_mesh_buffer(data, "m.ply");
  EXPECT_EQ(mesh.vertices[3], Point(3, -3, 0.5));
  EXPECT_EQ(mesh.triangles, (std::vector<Triangle>{{3, 2, 1}, {3, 1, 0}}));
}

TEST(IoMeshReader, PlyIndexOutOfRange) {
  std::string ascii = kAsciiPlyMesh;
  ascii.replace(ascii.find("7 3 0 1 4"), 9, "7 3 0 1 5");
  expect_read_error([&] { read_ply_mesh_buffer(ascii, "m.ply"); }, "m.ply", "line 19",
                    "face 1: vertex index 5 out of range (5 vertices)");
  std::string negative = kAsciiPlyMesh;
  negative.replace(negative.find("7 3 0 1 4"), 9, "7 3 0 -1 4");
  expect_read_error([&] { read_ply_mesh_buffer(negative, "m.ply"); }, "m.ply", "line 19", "invalid vertex index '-1'");

  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) append_le<float>(binary, 0.0f);
  append_le<std::uint8_t>(binary, 3);
  append_le<std::int32_t>(binary, 0);
  const std::size_t at = binary.size();
  append_le<std::int32_t>(binary, -2);
  append_le<std::int32_t>(binary, 1);
  expect_read_error([&] { read_ply_mesh_buffer(binary, "m.ply"); }, "m.ply", "byte " + std::to_string(at),
                    "negative vertex index");
}

TEST(IoMeshReader, PlyWithoutFaces) {
  const std::string no_element =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n0 0 0\n";
  expect_read_error([&] { read_ply_mesh_buffer(no_element, "m.ply"); }, "m.ply", "header", "missing element 'face'");
  const std::string empty_faces =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n";
  expect_read_error([&] { read_ply_mesh_buffer(empty_faces, "m.ply"); }, "m.ply", "faces", "no faces");
  const std::string no_indices =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 0\nproperty list uchar int corners\nend_header\n0 0 0\n";
  expect_read_error([&] { read_ply_mesh_buffer(no_indices, "m.ply"); }, "m.ply", "line 7",
                    "missing list property 'vertex_indices'");
}

TEST(IoMeshReader, NonFiniteVertex) {
  std::string ascii = kAsciiPlyMesh;
  ascii.replace(ascii.find("1 1 0 9"), 7, "1 nan 0 9");
  expect_read_error([&] { read_ply_mesh_buffer(ascii, "m.ply"); }, "m.ply", "vertex 2", "non-finite");
}

TEST(IoMeshReader, VertexFaceAndByteLimits) {
  ReadLimits four;
  four.max_points = 4;  // 5 vertices, 3 triangles
  expect_read_error([&] { read_ply_mesh_buffer(kAsciiPlyMesh, "m.ply", four); }, "m.ply", "line 3",
                    "declared 5 vertices, more than the limit of 4");
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1 2 5\n";
  expect_read_error([&] { read_obj_mesh_buffer(obj, "m.obj", four); }, "m.obj", "data",
                    "5 vertices, more than the limit of 4");
  ReadLimits five;  // 5 vertices allowed, but 7 triangles (the quad makes two)
  five.max_points = 5;
  expect_read_error([&] { read_obj_mesh_buffer(obj + "f 2 3 4\nf 1 3 5\nf 1 4 5\nf 2 4 5\n", "m.obj", five); },
                    "m.obj", "face 5", "more than the limit of 5 triangles");
  ReadLimits bytes;
  bytes.max_bytes = 20;
  expect_read_error([&] { read_obj_mesh_buffer(obj, "m.obj", bytes); }, "m.obj", "byte 20",
                    "more than the limit of 20 bytes");
}

TEST(IoMeshReader, UnknownExtensionAndMissingFile) {
  test::TempDir dir;
  const std::string stl = dir.write("m.stl", "solid\n");
  expect_read_error([&] { read_mesh(stl); }, stl, "file name", "unknown mesh extension '.stl'");
  const std::string missing = dir.file("m.obj");
  expect_read_error([&] { read_mesh(missing); }, missing, "open", "cannot open");
  const std::string empty = dir.write("e.obj", "");
  expect_read_error([&] { read_mesh(empty); }, empty, "byte 0", "empty file");
}

}  // namespace
}  // namespace cloudshape::io
