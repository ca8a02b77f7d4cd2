// The picture's colours: the canvas, the wireframes (one bright colour no point is drawn in)
// and one hue per object for its points, points of no object in grey.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace cloudshape::render {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

inline constexpr Rgb kCanvas{22, 24, 30};
inline constexpr Rgb kWire{255, 200, 0};
inline constexpr Rgb kWireHalo{0, 0, 0};
inline constexpr Rgb kUnassignedPoints{150, 150, 150};
inline constexpr Rgb kText{235, 235, 235};
inline constexpr Rgb kCaption{160, 165, 175};

// Hues far from the wireframe's amber and from each other, light enough on the dark canvas.
inline Rgb object_colour(std::size_t index) {
  constexpr std::array<Rgb, 8> hues = {Rgb{110, 170, 255}, Rgb{90, 215, 140}, Rgb{235, 110, 200},
                                       Rgb{80, 215, 225},  Rgb{190, 150, 255}, Rgb{255, 120, 110},
                                       Rgb{170, 220, 90},  Rgb{225, 190, 160}};
  return hues[index % hues.size()];
}

}  // namespace cloudshape::render
