// Random cross-sections for synthetic right prisms: triangles, rhombi, hexagons, convex
// n-gons, and the non-convex L, T, plus and star profiles, none a rectangle or a regular pentagon.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "geometry/polygon.hpp"

namespace cloudshape::synth {

enum class SectionKind { triangle, rhombus, regular_hexagon, hexagon, convex, letter_l, letter_t, plus, star };

const std::vector<SectionKind>& all_section_kinds();
std::string to_string(SectionKind kind);

struct PrismSection {
  SectionKind kind = SectionKind::triangle;
  geometry::Polygon2 polygon;  // counter-clockwise, area centroid at the origin, largest extent 1
  bool regular = false;        // equal edges and equal corners (the regular hexagon)
};

// Every corner turns at least 25 deg and no edge is shorter than 10% of the largest extent,
// so that each side is a face a camera sees and RANSAC finds.
PrismSection random_section(SectionKind kind, std::mt19937_64& rng);

}  // namespace cloudshape::synth
