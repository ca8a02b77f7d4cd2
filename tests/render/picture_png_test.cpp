// The PNG as drawn: its size, the wireframe's pixels where the plan projects the solid (faint
// where points hide it), the points' colours, and a clear error for a picture that cannot be written.
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "render/palette.hpp"
#include "render/picture_plan.hpp"
#include "render/picture_png.hpp"

namespace cloudshape::render {
namespace {

namespace fs = std::filesystem;

constexpr int kColourTolerance = 40;  // per channel, for anti-aliased lines

struct Box {
  Eigen::Vector3d center{0.05, -0.03, 1.2};
  Eigen::Matrix3d axes;
  Eigen::Vector3d size{0.30, 0.20, 0.10};
  Box() {
    axes = Eigen::AngleAxisd(0.5, Eigen::Vector3d(0.2, 1.0, 0.4).normalized()).toRotationMatrix().transpose();
  }
  Eigen::Vector3d corner(int sx, int sy, int sz) const {
    return center + 0.5 * (sx * size[0] * axes.row(0).transpose() + sy * size[1] * axes.row(1).transpose() +
                           sz * size[2] * axes.row(2).transpose());
  }
};

// Points on the box's six faces, 100 x 100 per face.
PointList box_surface(const Box& box) {
  PointList points;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side : {-1, 1})
      for (int i = 0; i < 100; ++i)
        for (int j = 0; j < 100; ++j) {
          Eigen::Vector3d local = Eigen::Vector3d::Zero();
          local[axis] = 0.5 * side * box.size[axis];
          local[u] = (-0.5 + (i + 0.5) / 100.0) * box.size[u];
          local[v] = (-0.5 + (j + 0.5) / 100.0) * box.size[v];
          points.push_back(box.center + box.axes.transpose() * local);
        }
  }
  return points;
}

pipeline::RecognitionResult box_result(const Box& box, std::size_t points) {
  pipeline::RecognitionResult r;
  r.source = "box.pcd";
  r.points_in = points;
  pipeline::ObjectResult o;
  o.shape = "box";
  o.confidence = 0.9;
  o.dimensions = {{"length", box.size[0]}, {"width", box.size[1]}, {"height", box.size[2]}};
  o.center = box.center;
  o.axes = box.axes;
  for (std::size_t i = 0; i < points; ++i) o.point_indices.push_back(static_cast<std::uint32_t>(i));
  r.objects.push_back(o);
  return r;
}

// A grid layout that marks the cloud as organized (seen by a depth camera at the origin).
GridLayout organized(std::size_t points) {
  GridLayout g;
  g.width = points / 2;
  g.height = 2;
  for (std::size_t i = 0; i < points; ++i) g.pixel.push_back(static_cast<std::uint32_t>(i));
  return g;
}

using Image = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

Image read_png(const fs::path& path) {
  return Image(cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy);
}

Rgb pixel_at(cairo_surface_t* image, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(image);
  const int stride = cairo_image_surface_get_stride(image);
  const std::uint32_t word = *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x);
  return Rgb{static_cast<std::uint8_t>(word >> 16), static_cast<std::uint8_t>(word >> 8),
             static_cast<std::uint8_t>(word)};
}

bool near_colour(Rgb a, Rgb b) {
  return std::abs(a.r - b.r) <= kColourTolerance && std::abs(a.g - b.g) <= kColourTolerance &&
         std::abs(a.b - b.b) <= kColourTolerance;
}

// Whether some pixel within one of `at` has `colour`.
bool colour_near(cairo_surface_t* image, const Eigen::Vector2d& at, Rgb colour) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = static_cast<int>(std::floor(at.x())) + dx, y = static_cast<int>(std::floor(at.y())) + dy;
      if (x >= 0 && y >= 0 && x < cairo_image_surface_get_width(image) && y < cairo_image_surface_get_height(image) &&
          near_colour(pixel_at(image, x, y), colour))
        return true;
    }
  return false;
}

// Whether `c` is `base` darkened by depth (point_splat.cpp: 35% to 100% of it), within 6 a channel.
bool shade_of(Rgb c, Rgb base) {
  const double k = static_cast<double>(c.b) / base.b;
  return k >= 0.3 && k <= 1.01 && std::abs(c.r - k * base.r) <= 6.0 && std::abs(c.g - k * base.g) <= 6.0;
}

// Whether some pixel within one of `at` is a shade of `base`.
bool shade_near(cairo_surface_t* image, const Eigen::Vector2d& at, Rgb base) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (shade_of(pixel_at(image, static_cast<int>(at.x()) + dx, static_cast<int>(at.y()) + dy), base)) return true;
  return false;
}

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

// Of a grid of places on the box face most turned to the camera, the pixel farthest from `drawn`.
Eigen::Vector2d pixel_far_from_edges(const Box& box, const Panel& panel,
                                     const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& drawn) {
  const Eigen::Vector3d viewer = panel.view.camera.toward_viewer(box.center);
  int face = 0, facing = 1;
  double best = -1.0;
  for (int i = 0; i < 3; ++i)
    for (int side : {-1, 1})
      if (side * box.axes.row(i).dot(viewer) > best) {
        best = side * box.axes.row(i).dot(viewer);
        face = i;
        facing = side;
      }
  const int u = (face + 1) % 3, v = (face + 2) % 3;
  Eigen::Vector2d far_pixel = panel.view.pixel(box.center)->head<2>();
  double farthest = -1.0;
  for (double su = -0.4; su <= 0.41; su += 0.1)
    for (double sv = -0.4; sv <= 0.41; sv += 0.1) {
      Eigen::Vector3d local = Eigen::Vector3d::Zero();
      local[face] = 0.5 * facing * box.size[face];
      local[u] = su * box.size[u];
      local[v] = sv * box.size[v];
      const Eigen::Vector2d px = panel.view.pixel(box.center + box.axes.transpose() * local)->head<2>();
      double nearest = 1e9;
      for (const auto& [a, b] : drawn) nearest = std::min(nearest, distance_to_segment(px, a, b));
      if (nearest > farthest) {
        farthest = nearest;
        far_pixel = px;
      }
    }
  return far_pixel;
}

class PicturePng : public ::testing::TestWithParam<bool> {
 protected:
  fs::path dir_ = fs::temp_directory_path() / ("cloudshape_render_test_" + std::to_string(::getpid()) +
                                               "_" + test_name());

  static std::string test_name() {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& c : name)
      if (c == '/') c = '_';
    return name;
  }
  void SetUp() override { fs::create_directories(dir_); }
  // A failed test leaves its picture behind to be looked at.
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
};

TEST_P(PicturePng, DrawsTheBoxEdgesWhereThePlanProjectsThem) {
  const Box box;
  const PointList points = box_surface(box);
  const GridLayout grid = GetParam() ? organized(points.size()) : GridLayout{};
  const pipeline::RecognitionResult result = box_result(box, points.size());
  const fs::path png = dir_ / "box.png";
  write_picture_png(points, grid, result, png.string());

  SCOPED_TRACE(png.string());
  const Image image = read_png(png);
  ASSERT_EQ(cairo_surface_status(image.get()), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image.get()), 1200);
  EXPECT_EQ(cairo_image_surface_get_height(image.get()), 800);

  const PicturePlan plan = plan_picture(points, grid, result);
  ASSERT_EQ(plan.panels.size(), 2u);
  EXPECT_EQ(plan.panels[0].caption.rfind(GetParam() ? "sensor view" : "principal-axes view", 0), 0u);
  for (const Panel& panel : plan.panels) {
    // Each edge runs along axis i at signs (sj, sk) of the other two: between the faces (j, sj)
    // and (k, sk). With every face sampled, an edge whose two faces both turn away from the
    // camera lies behind points and is drawn faint; any other is drawn in the wire's colour.
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> drawn, visible;
    std::vector<Eigen::Vector2d> hidden_middles;
    for (int i = 0; i < 3; ++i)
      for (int sj : {-1, 1})
        for (int sk : {-1, 1}) {
          const int j = (i + 1) % 3, k = (i + 2) % 3;
          std::array<int, 3> lo{}, hi{};
          lo[i] = -1, hi[i] = 1, lo[j] = hi[j] = sj, lo[k] = hi[k] = sk;
          const Eigen::Vector3d a = box.corner(lo[0], lo[1], lo[2]), b = box.corner(hi[0], hi[1], hi[2]);
          const auto s = panel.view.segment(a, b);
          ASSERT_TRUE(s.has_value());
          drawn.push_back(*s);
          const auto faces_camera = [&](int axis, int sign) {
            const Eigen::Vector3d normal = sign * box.axes.row(axis).transpose();
            const Eigen::Vector3d face = box.center + 0.5 * box.size[axis] * normal;
            return normal.dot(panel.view.camera.toward_viewer(face)) > 0.0;
          };
          if (!faces_camera(j, sj) && !faces_camera(k, sk)) {
            hidden_middles.push_back(0.5 * (s->first + s->second));
            continue;
          }
          visible.push_back(*s);
          // A tag may cover a little of an edge, never a whole quarter of it.
          bool seen = false;
          for (double t : {0.25, 0.5, 0.75}) seen = seen || colour_near(image.get(), (1 - t) * s->first + t * s->second, kWire);
          EXPECT_TRUE(seen) << panel.caption << ": edge " << a.transpose() << " -> " << b.transpose();
        }
    EXPECT_GE(hidden_middles.size(), 1u) << panel.caption;
    for (const Eigen::Vector2d& m : hidden_middles) {
      double nearest = 1e9;
      for (const auto& [a, b] : visible) nearest = std::min(nearest, distance_to_segment(m, a, b));
      if (nearest > 5.0) {
        EXPECT_FALSE(colour_near(image.get(), m, kWire)) << panel.caption << ": hidden edge at " << m.transpose();
      }
    }
    // A pixel on the face most turned to the camera, far from every drawn edge (hidden ones
    // cross faces too): the first object's colour there, shaded by depth, not the wire.
    const Eigen::Vector2d middle = pixel_far_from_edges(box, panel, drawn);
    double nearest = 1e9;
    for (const auto& [a, b] : drawn) nearest = std::min(nearest, distance_to_segment(middle, a, b));
    ASSERT_GT(nearest, 8.0) << panel.caption;
    // Points are squares a little apart: one of the 3 x 3 pixels there shows them.
    EXPECT_FALSE(colour_near(image.get(), middle, kWire)) << panel.caption;
    EXPECT_TRUE(shade_near(image.get(), middle, object_colour(0))) << panel.caption << " at " << middle.transpose();
    // The panel's far corner shows the empty canvas.
    const Rgb corner = pixel_at(image.get(), static_cast<int>(panel.rect.x + 4), static_cast<int>(panel.rect.y + 4));
    EXPECT_TRUE(near_colour(corner, kCanvas)) << panel.caption;
  }
}

TEST_P(PicturePng, AnUnwritablePathIsARenderErrorNamingIt) {
  const Box box;
  const PointList points = box_surface(box);
  const fs::path taken = dir_ / "taken.png";
  fs::create_directories(taken);  // a folder where the file should go
  try {
    write_picture_png(points, {}, box_result(box, points.size()), taken.string());
    FAIL() << "no error";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(taken.string()), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(OrganizedOrNot, PicturePng, ::testing::Bool());

TEST(PicturePlan, AnEmptyResultStillFramesThePoints) {
  const Box box;
  const PointList points = box_surface(box);
  pipeline::RecognitionResult none;
  const PicturePlan plan = plan_picture(points, {}, none);
  ASSERT_EQ(plan.panels.size(), 2u);
  for (const Panel& panel : plan.panels) {
    EXPECT_TRUE(panel.wireframes.empty());
    const auto px = panel.view.pixel(box.center);
    ASSERT_TRUE(px.has_value());
    EXPECT_TRUE(panel.rect.contains(px->head<2>()));
  }
}

}  // namespace
}  // namespace cloudshape::render
