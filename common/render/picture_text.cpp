#include "render/picture_text.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "render/cairo_helpers.hpp"
#include "render/label.hpp"
#include "render/palette.hpp"

namespace cloudshape::render {
namespace {

constexpr double kLabelSize = 13.0;
constexpr double kLabelPad = 4.0;

// Where a label points: the top of the solid's drawing, else of its points.
std::optional<Eigen::Vector2d> label_anchor(const Panel& panel, const Wireframe& wireframe,
                                            const pipeline::ObjectResult& object, const PointList& points) {
  std::optional<Eigen::Vector2d> top;
  const auto consider = [&](const Eigen::Vector3d& p) {
    const auto px = panel.view.pixel(p);
    if (!px || !panel.rect.contains(px->head<2>())) return;
    if (!top || px->y() < top->y()) top = px->head<2>();
  };
  for (const Polyline& line : wireframe.lines)
    for (const Eigen::Vector3d& p : line.points) consider(p);
  if (!top) {
    const std::size_t step = std::max<std::size_t>(1, object.point_indices.size() / 2000);
    for (std::size_t k = 0; k < object.point_indices.size(); k += step)
      if (object.point_indices[k] < points.size()) consider(points[object.point_indices[k]]);
  }
  return top;
}

bool overlaps(const PixelRect& a, const PixelRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

}  // namespace

void draw_legend(cairo_t* cr, const PicturePlan& plan, const pipeline::RecognitionResult& result) {
  if (plan.legend_rows == 0) return;
  const double column_width = plan.legend.width / plan.legend_columns;
  const std::size_t room = plan.legend_rows * static_cast<std::size_t>(plan.legend_columns);
  const std::size_t n = result.objects.size();
  const std::size_t listed = n <= room ? n : room - 1;
  for (std::size_t k = 0; k <= listed && k < n; ++k) {
    const double x = plan.legend.x + 12 + static_cast<double>(k / plan.legend_rows) * column_width;
    const double y = plan.legend.y + 4 + static_cast<double>(k % plan.legend_rows) * kLegendRowHeight;
    if (k == listed) {
      draw_text(cr, "and " + std::to_string(n - listed) + " more objects", x + 18, y + 14, 13, kCaption);
      break;
    }
    set_colour(cr, object_colour(k));
    cairo_rectangle(cr, x, y + 3, 12, 12);
    cairo_fill(cr);
    draw_text(cr, object_label(result.objects[k], k + 1), x + 18, y + 14, 13, kText);
  }
}

void draw_header(cairo_t* cr, const PicturePlan& plan, const pipeline::RecognitionResult& result,
                 std::size_t points) {
  const std::string objects = std::to_string(result.objects.size()) +
                              (result.objects.size() == 1 ? " object" : " objects");
  draw_text(cr, result.source.empty() ? std::string("(unnamed cloud)") : result.source, 12, 26, 17,
            kText, CAIRO_FONT_WEIGHT_BOLD);
  const std::string facts = std::to_string(points) + (points == 1 ? " point, " : " points, ") + objects;
  cairo_text_extents_t ext;
  cairo_text_extents(cr, facts.c_str(), &ext);
  draw_text(cr, facts, plan.width - ext.x_advance - 12, 26, 14, kCaption);
}

void draw_tags(cairo_t* cr, const Panel& panel, const pipeline::RecognitionResult& result,
               const PointList& points) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kLabelSize);
  std::vector<PixelRect> placed;
  for (std::size_t k = 0; k < result.objects.size(); ++k) {
    const pipeline::ObjectResult& o = result.objects[k];
    const auto anchor = label_anchor(panel, panel.wireframes[k], o, points);
    if (!anchor) continue;
    const std::string text = object_tag(o, k + 1);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text.c_str(), &ext);
    const double w = ext.x_advance + 2 * kLabelPad, h = kLabelSize + 2 * kLabelPad;
    PixelRect box{anchor->x() - w / 2, anchor->y() - h - 14, w, h};
    const auto keep_inside = [&] {
      box.x = std::clamp(box.x, panel.rect.x + 2, panel.rect.x + panel.rect.width - w - 2);
      box.y = std::clamp(box.y, panel.rect.y + 2, panel.rect.y + panel.rect.height - h - 24);
    };
    keep_inside();
    for (int tries = 0; tries < 12 && std::any_of(placed.begin(), placed.end(),
                                                  [&](const PixelRect& p) { return overlaps(p, box); });
         ++tries) {
      box.y += (tries % 2 == 0 ? -1.0 : 1.0) * (tries / 2 + 1) * (h + 3);
      keep_inside();
    }
    placed.push_back(box);
    const Rgb hue = object_colour(k);
    set_colour(cr, hue);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, box.x + box.width / 2, box.y + (anchor->y() > box.y ? box.height : 0.0));
    cairo_line_to(cr, anchor->x(), anchor->y());
    cairo_stroke(cr);
    cairo_rectangle(cr, box.x, box.y, box.width, box.height);
    set_colour(cr, kCanvas, 0.82);
    cairo_fill_preserve(cr);
    set_colour(cr, hue);
    cairo_stroke(cr);
    set_colour(cr, kText);
    cairo_move_to(cr, box.x + kLabelPad - ext.x_bearing, box.y + kLabelPad + kLabelSize * 0.8);
    cairo_show_text(cr, text.c_str());
  }
}

}  // namespace cloudshape::render
