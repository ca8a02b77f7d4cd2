#include "render/picture_png.hpp"

#include <cairo.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/hidden_lines.hpp"
#include "render/label.hpp"
#include "render/palette.hpp"
#include "render/point_splat.hpp"

namespace cloudshape::render {
namespace {

struct Stroke {
  Rgb colour;
  double alpha;
  double width;
  bool dashed = false;
};
// A dark halo under each wire keeps it visible over points of any colour.
constexpr Stroke kHaloStroke{kWireHalo, 0.75, 5.0};
constexpr Stroke kWireStroke{kWire, 1.0, 2.4};
constexpr Stroke kHiddenStroke{kWire, 0.7, 1.4, true};
constexpr double kLabelSize = 13.0;
constexpr double kLabelPad = 4.0;
constexpr const char* kFont = "DejaVu Sans";

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

void clip_to(cairo_t* cr, const PixelRect& r) {
  cairo_reset_clip(cr);
  cairo_rectangle(cr, r.x, r.y, r.width, r.height);
  cairo_clip(cr);
}

// Hidden pieces first, thin and faint; then a dark halo under every visible piece, so that no
// solid's outline cuts through another's wire; then the visible wires.
void draw_wireframes(cairo_t* cr, const Panel& panel, const DepthBuffer& depth) {
  std::vector<WirePiece> pieces;
  for (const Wireframe& w : panel.wireframes) {
    const std::vector<WirePiece> more = wire_pieces(panel.view, w, depth);
    pieces.insert(pieces.end(), more.begin(), more.end());
  }
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const auto& [stroke, hidden] : {std::pair{kHiddenStroke, true}, std::pair{kHaloStroke, false},
                                       std::pair{kWireStroke, false}}) {
    for (const WirePiece& p : pieces) {
      if (p.hidden != hidden) continue;
      cairo_move_to(cr, p.from.x(), p.from.y());
      cairo_line_to(cr, p.to.x(), p.to.y());
    }
    set_colour(cr, stroke.colour, stroke.alpha);
    cairo_set_line_width(cr, stroke.width);
    const double dash[] = {5.0, 4.0};
    cairo_set_dash(cr, dash, stroke.dashed ? 2 : 0, 0.0);
    cairo_stroke(cr);
  }
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

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

void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size, Rgb colour,
               cairo_font_weight_t weight = CAIRO_FONT_WEIGHT_NORMAL) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, weight);
  cairo_set_font_size(cr, size);
  set_colour(cr, colour);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

// Each object's full label, column by column, a swatch of its points' colour before it.
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

void draw_panel(cairo_t* cr, cairo_surface_t* surface, const Panel& panel, const PointList& points,
                const std::vector<int>& object_of, const pipeline::RecognitionResult& result) {
  cairo_surface_flush(surface);
  PixelBuffer buffer{reinterpret_cast<std::uint32_t*>(cairo_image_surface_get_data(surface)),
                     cairo_image_surface_get_stride(surface) / 4, cairo_image_surface_get_width(surface),
                     cairo_image_surface_get_height(surface)};
  const DepthBuffer depth = splat_points(panel.view, panel.rect, points, object_of, buffer);
  cairo_surface_mark_dirty(surface);
  clip_to(cr, panel.rect);
  draw_wireframes(cr, panel, depth);
  draw_tags(cr, panel, result, points);
  // The caption on a strip of canvas, so that points never run through it.
  const double strip = 26.0;
  cairo_rectangle(cr, panel.rect.x, panel.rect.y + panel.rect.height - strip, panel.rect.width, strip);
  set_colour(cr, kCanvas, 0.85);
  cairo_fill(cr);
  draw_text(cr, panel.caption, panel.rect.x + 12, panel.rect.y + panel.rect.height - 9, 13, kCaption);
  cairo_reset_clip(cr);
}

}  // namespace

void write_picture_png(const PointList& points, const GridLayout& grid,
                       const pipeline::RecognitionResult& result, const std::string& png_path,
                       const RenderOptions& options) {
  if (options.width < 200 || options.height < 150)
    throw RenderError(png_path + ": a picture needs at least 200 x 150 pixels");
  const PicturePlan plan = plan_picture(points, grid, result, options);
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, plan.width, plan.height),
                  cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw RenderError(png_path + ": " + cairo_status_to_string(cairo_surface_status(surface.get())));
  Context cr(cairo_create(surface.get()), cairo_destroy);
  set_colour(cr.get(), kCanvas);
  cairo_paint(cr.get());

  const std::vector<int> object_of = object_of_points(result, points.size());
  for (const Panel& panel : plan.panels)
    draw_panel(cr.get(), surface.get(), panel, points, object_of, result);
  set_colour(cr.get(), kCaption, 0.5);
  cairo_set_line_width(cr.get(), 1.0);
  for (std::size_t k = 1; k < plan.panels.size(); ++k) {
    cairo_move_to(cr.get(), plan.panels[k].rect.x + 0.5, plan.panels[k].rect.y);
    cairo_line_to(cr.get(), plan.panels[k].rect.x + 0.5, plan.height);
  }
  cairo_stroke(cr.get());
  draw_header(cr.get(), plan, result, points.size());
  draw_legend(cr.get(), plan, result);

  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
    throw RenderError(png_path + ": drawing failed: " + cairo_status_to_string(cairo_status(cr.get())));
  const cairo_status_t written = cairo_surface_write_to_png(surface.get(), png_path.c_str());
  if (written != CAIRO_STATUS_SUCCESS)
    throw RenderError(png_path + ": cannot write the PNG: " + cairo_status_to_string(written));
}

}  // namespace cloudshape::render
