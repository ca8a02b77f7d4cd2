// Line and token cursors over an in-memory text buffer, for the PCD, PLY and XYZ text parsers.
// They never copy: every line and token is a view into the caller's buffer.
#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>

namespace cloudshape::io::detail {

class LineCursor {
public:
  // `offset` is where reading starts and `first_line` is that line's 1-based number,
  // so body parsers can continue the numbering a header parser started.
  explicit LineCursor(std::string_view text, std::size_t offset = 0, std::size_t first_line = 1)
      : text_(text), pos_(offset < text.size() ? offset : text.size()), next_line_(first_line) {}

  // Yields the next line without its "\n" or "\r\n"; false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const char* const start = text_.data() + pos_;
    const std::size_t left = text_.size() - pos_;
    const void* const newline = std::memchr(start, '\n', left);
    const std::size_t length =
        newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - start) : left;
    line = std::string_view(start, length);
    pos_ += newline ? length + 1 : length;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    line_ = next_line_++;
    return true;
  }

  std::size_t line_number() const { return line_; }    // of the line last returned
  std::size_t next_line_number() const { return next_line_; }
  std::size_t offset() const { return pos_; }          // first byte after the line last returned

private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t next_line_;
  std::size_t line_ = 0;
};

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Splits a line on runs of whitespace, and also on commas when `commas` is set (XYZ files
// come from spreadsheets and scripts that use either).
class TokenCursor {
public:
  explicit TokenCursor(std::string_view line, bool commas = false) : line_(line), commas_(commas) {}

  bool next(std::string_view& token) {
    while (pos_ < line_.size() && is_separator(line_[pos_])) ++pos_;
    if (pos_ >= line_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < line_.size() && !is_separator(line_[pos_])) ++pos_;
    token = line_.substr(start, pos_ - start);
    return true;
  }

  bool at_end() {
    while (pos_ < line_.size() && is_separator(line_[pos_])) ++pos_;
    return pos_ >= line_.size();
  }

private:
  bool is_separator(char c) const { return is_space(c) || (commas_ && c == ','); }

  std::string_view line_;
  bool commas_;
  std::size_t pos_ = 0;
};

inline bool is_blank(std::string_view line) {
  for (const char c : line) {
    if (!is_space(c)) return false;
  }
  return true;
}

}  // namespace cloudshape::io::detail
