#include "render/picture_png.hpp"

#include <cairo.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/cairo_helpers.hpp"
#include "render/hidden_lines.hpp"
#include "render/palette.hpp"
#include "render/picture_text.hpp"
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

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

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
