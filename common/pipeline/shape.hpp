// The solid classes cloudshape recognises and their names on the wire and in JSON
// (INTERFACE.md): names never change meaning, new shapes get new names.
#pragma once

#include <array>
#include <string>

namespace cloudshape::pipeline {

enum class Shape { unknown, box, tetrahedron, pentagonal_prism, cone, cylinder, sphere, prism, frustum };

// The thesis' six: every cloud with a solid in it is tried against each of them.
inline constexpr std::array<Shape, 6> kSolidShapes = {Shape::box,  Shape::tetrahedron,
                                                      Shape::pentagonal_prism, Shape::cone,
                                                      Shape::cylinder, Shape::sphere};
// Every named shape; the shapes beyond the six are tried only where the faces call for them.
inline constexpr std::array<Shape, 8> kNamedShapes = {
    Shape::box,      Shape::tetrahedron, Shape::pentagonal_prism, Shape::cone,
    Shape::cylinder, Shape::sphere,      Shape::prism,            Shape::frustum};

// A solid with a curved surface.
inline bool is_round(Shape s) {
  return s == Shape::sphere || s == Shape::cylinder || s == Shape::cone || s == Shape::frustum;
}

// The polyhedra the key-points name from their corner counts (the classifier's first candidate):
// where one of them is named, a round solid is only a rival hypothesis.
inline bool polyhedron_by_corners(Shape s) {
  return s == Shape::box || s == Shape::tetrahedron || s == Shape::pentagonal_prism;
}

// Whether one shape is the other with a parameter pinned (a box is a four-sided prism, a cylinder
// a frustum of equal radii, a cone one closed at its top), or the same: such a pair explaining the
// same points is one answer said twice, not two.
inline bool same_family(Shape a, Shape b) {
  const auto special_of = [](Shape special, Shape general) {
    return (general == Shape::prism &&
            (special == Shape::box || special == Shape::pentagonal_prism)) ||
           (general == Shape::frustum && (special == Shape::cylinder || special == Shape::cone));
  };
  return a == b || special_of(a, b) || special_of(b, a);
}

inline std::string shape_name(Shape s) {
  switch (s) {
    case Shape::box: return "box";
    case Shape::tetrahedron: return "tetrahedron";
    case Shape::pentagonal_prism: return "pentagonal_prism";
    case Shape::cone: return "cone";
    case Shape::cylinder: return "cylinder";
    case Shape::sphere: return "sphere";
    case Shape::prism: return "prism";
    case Shape::frustum: return "frustum";
    case Shape::unknown: break;
  }
  return "unknown";
}

}  // namespace cloudshape::pipeline
