#include "render/point_splat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/palette.hpp"

namespace cloudshape::render {
namespace {

// Steps of depth shading: fine enough to show no bands, few enough to keep PNGs smaller.
constexpr int kShades = 16;
constexpr double kFarthestBrightness = 0.35;

struct Projected {
  int x, y;
  float depth;
  std::uint32_t index;
};

double percentile(std::vector<float> values, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

std::uint32_t shaded(Rgb c, double brightness) {
  const auto channel = [&](std::uint8_t v) {
    return static_cast<std::uint32_t>(std::lround(v * brightness));
  };
  return 0xff000000u | channel(c.r) << 16 | channel(c.g) << 8 | channel(c.b);
}

// The points' typical spacing in pixels, from the median number of distinct pixels they hit in
// the occupied cells of a coarse grid (empty space around a scene does not count), widened a
// half again: a closed surface seen through shows two layers, and scan lines leave gaps.
int splat_size(const std::vector<Projected>& seen, int x0, int y0, int x1, int y1) {
  constexpr int kCell = 16;
  constexpr int kLargest = 6;
  constexpr double kLayers = 1.8;
  const int w = x1 - x0, columns = (w + kCell - 1) / kCell, rows = (y1 - y0 + kCell - 1) / kCell;
  std::vector<std::uint8_t> hit(static_cast<std::size_t>(w) * (y1 - y0), 0);
  std::vector<int> counts(static_cast<std::size_t>(columns) * rows, 0);
  for (const Projected& p : seen) {
    std::uint8_t& h = hit[static_cast<std::size_t>(p.y - y0) * w + (p.x - x0)];
    if (h) continue;
    h = 1;
    ++counts[static_cast<std::size_t>((p.y - y0) / kCell) * columns + (p.x - x0) / kCell];
  }
  std::vector<float> occupied;
  for (int c : counts)
    if (c > 0) occupied.push_back(static_cast<float>(c));
  const double spacing = kCell / std::sqrt(std::max(1.0, percentile(occupied, 0.5)));
  return std::clamp(static_cast<int>(std::ceil(kLayers * spacing)), 1, kLargest);
}

}  // namespace

std::vector<int> object_of_points(const pipeline::RecognitionResult& result, std::size_t points) {
  std::vector<int> out(points, -1);
  for (std::size_t k = 0; k < result.objects.size(); ++k)
    for (std::uint32_t i : result.objects[k].point_indices)
      if (i < points) out[i] = static_cast<int>(k);
  return out;
}

float DepthBuffer::at(int x, int y) const {
  if (x < x0 || y < y0 || x >= x0 + width || y >= y0 + height) return std::numeric_limits<float>::infinity();
  return depth[static_cast<std::size_t>(y - y0) * width + (x - x0)];
}

DepthBuffer splat_points(const View& view, const PixelRect& clip, const PointList& points,
                         const std::vector<int>& object_of, PixelBuffer out) {
  const int x0 = std::max(0, static_cast<int>(std::ceil(clip.x)));
  const int y0 = std::max(0, static_cast<int>(std::ceil(clip.y)));
  const int x1 = std::max(x0, std::min(out.width, static_cast<int>(std::floor(clip.x + clip.width))));
  const int y1 = std::max(y0, std::min(out.height, static_cast<int>(std::floor(clip.y + clip.height))));
  const int w = x1 - x0, h = y1 - y0;
  DepthBuffer zbuffer{x0, y0, w, h,
                      std::vector<float>(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity())};

  std::vector<Projected> seen;
  seen.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto p = view.pixel(points[i]);
    if (!p || !(p->x() >= x0 && p->x() < x1 && p->y() >= y0 && p->y() < y1)) continue;
    seen.push_back({static_cast<int>(p->x()), static_cast<int>(p->y()), static_cast<float>(p->z()),
                    static_cast<std::uint32_t>(i)});
  }
  if (seen.empty()) return zbuffer;

  std::vector<float> depths;
  depths.reserve(seen.size());
  for (const Projected& p : seen) depths.push_back(p.depth);
  const int size = splat_size(seen, x0, y0, x1, y1);
  const double near = percentile(depths, 0.02), far = percentile(depths, 0.98);
  const double span = far > near ? far - near : 1.0;
  zbuffer.near = near;
  zbuffer.far = far;
  for (const Projected& p : seen) {
    const double t = std::clamp((p.depth - near) / span, 0.0, 1.0);
    const double shade = std::floor(t * (kShades - 1) + 0.5) / (kShades - 1);
    const int k = p.index < object_of.size() ? object_of[p.index] : -1;
    const Rgb base = k >= 0 ? object_colour(static_cast<std::size_t>(k)) : kUnassignedPoints;
    const std::uint32_t colour = shaded(base, 1.0 - (1.0 - kFarthestBrightness) * shade);
    const int left = p.x - size / 2, top = p.y - size / 2;
    for (int y = std::max(y0, top); y < std::min(y1, top + size); ++y) {
      for (int x = std::max(x0, left); x < std::min(x1, left + size); ++x) {
        float& z = zbuffer.depth[static_cast<std::size_t>(y - y0) * w + (x - x0)];
        if (p.depth >= z) continue;
        z = p.depth;
        out.pixels[static_cast<std::size_t>(y) * out.stride + x] = colour;
      }
    }
  }
  return zbuffer;
}

}  // namespace cloudshape::render
