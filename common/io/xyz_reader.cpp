// Reads plain-text point clouds: one "x y z" per line (.xyz, .txt).
// Spaces, tabs or commas separate values; extra columns, blank lines and '#' lines are ignored.
#include "io/xyz_reader.hpp"

#include <cmath>

#include "io/detail/input.hpp"
#include "io/detail/parse_number.hpp"
#include "io/detail/text_lines.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {

CloudFile read_xyz_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  detail::check_buffer(data, name, limits);
  // Editors on Windows prepend a UTF-8 byte-order mark that is not part of the first value.
  const std::size_t start = data.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;

  CloudFile out;
  out.format = "xyz";
  detail::LineCursor lines(data, start);
  std::string_view line;
  while (lines.next(line)) {
    detail::TokenCursor tokens(line, /*commas=*/true);
    std::string_view token;
    if (!tokens.next(token) || token.front() == '#') continue;
    const std::string place = detail::at_line(lines.line_number());
    double xyz[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < 3; ++a) {
      if (a > 0 && !tokens.next(token)) {
        throw ReadError(name, place, "too few values: expected x y z, found " + std::to_string(a));
      }
      if (!detail::parse_double(token, xyz[a])) {
        throw ReadError(name, place, "non-numeric value " + detail::quoted(token) + " in column " +
                                         std::to_string(a + 1));
      }
    }
    if (out.points.size() + out.non_finite_dropped >= limits.max_points) {
      throw ReadError(name, place, "more than the limit of " + std::to_string(limits.max_points) + " points");
    }
    if (std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])) {
      out.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else {
      ++out.non_finite_dropped;
    }
  }
  return out;
}

}  // namespace cloudshape::io
