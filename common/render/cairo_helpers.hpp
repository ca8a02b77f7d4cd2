// The few Cairo calls every drawing step shares: a palette colour as the source, and one line
// of text in the picture's font.
#pragma once

#include <cairo.h>

#include <string>

#include "render/palette.hpp"

namespace cloudshape::render {

inline constexpr const char* kFont = "DejaVu Sans";

inline void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, alpha);
}

inline void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size, Rgb colour,
               cairo_font_weight_t weight = CAIRO_FONT_WEIGHT_NORMAL) {
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL, weight);
  cairo_set_font_size(cr, size);
  set_colour(cr, colour);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

}  // namespace cloudshape::render
