// bccmis::io::detail: the scanner the text surface readers (.off, .obj,
// ASCII .stl) share, and the fan of a polygon into a triangle soup.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "bccmis/io/read_error.h"
#include "bccmis/io/triangle_soup.h"

namespace bccmis::io::detail {

/// A text scanned line by line and token by token, with line and column
/// (1-based; a column counts bytes) for messages.
class LineScanner {
 public:
  LineScanner(const std::string& file, const std::string& data) : file_(file), data_(data) {}

  /// The next line, without its end (\n, \r\n); false at the end of the data.
  bool next_line() {
    if (pos_ >= data_.size()) return false;
    const auto end = data_.find('\n', pos_);
    line_start_ = pos_;
    line_end_ = end == std::string::npos ? data_.size() : end;
    pos_ = end == std::string::npos ? data_.size() : end + 1;
    if (line_end_ > line_start_ && data_[line_end_ - 1] == '\r') --line_end_;
    ++line_no_;
    cur_ = line_start_;
    return true;
  }
  /// The next whitespace-separated token of the line, cut at '#' when
  /// `comments`; empty at the end of the line.
  std::string_view token(bool comments = true) {
    while (cur_ < line_end_ && is_space(data_[cur_])) ++cur_;
    tok_start_ = cur_;
    if (cur_ >= line_end_ || (comments && data_[cur_] == '#')) return {};
    while (cur_ < line_end_ && !is_space(data_[cur_]) && !(comments && data_[cur_] == '#')) ++cur_;
    return std::string_view(data_).substr(tok_start_, cur_ - tok_start_);
  }
  /// Whether the rest of the line is blank or a comment.
  bool line_blank() {
    const std::size_t save = cur_;
    const bool blank = token().empty();
    cur_ = save;
    return blank;
  }
  std::size_t line() const { return line_no_; }
  /// The byte offset of the line after the current one (where a binary body
  /// that follows a text header starts).
  std::size_t offset() const { return pos_; }
  /// file:line:col of the last token (or of the end of the line when it was empty).
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_ + ":" + std::to_string(line_no_) + ":" + std::to_string(tok_start_ - line_start_ + 1) + ": " +
                    what);
  }
  double number(std::string_view what) {
    const std::string_view t = token();
    if (t.empty()) fail("expected " + std::string(what) + ", found the end of the line");
    return number(t, what);
  }
  double number(std::string_view t, std::string_view what) const {
    double x = 0;
    const char* first = t.data();
    if (*first == '+') ++first;
    const auto [p, ec] = std::from_chars(first, t.data() + t.size(), x);
    if (ec != std::errc() || p != t.data() + t.size() || !std::isfinite(x))
      fail("bad number '" + std::string(t) + "' (expected " + std::string(what) + ")");
    return x;
  }
  long long integer(std::string_view t, std::string_view what) const {
    long long x = 0;
    const char* first = t.data();
    if (!t.empty() && *first == '+') ++first;
    const auto [p, ec] = std::from_chars(first, t.data() + t.size(), x);
    if (t.empty() || ec != std::errc() || p != t.data() + t.size())
      fail("bad integer '" + std::string(t) + "' (expected " + std::string(what) + ")");
    return x;
  }
  long long integer(std::string_view what) {
    const std::string_view t = token();
    if (t.empty()) fail("expected " + std::string(what) + ", found the end of the line");
    return integer(t, what);
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
  const std::string& file_;
  const std::string& data_;
  std::size_t pos_ = 0, line_start_ = 0, line_end_ = 0, cur_ = 0, tok_start_ = 0, line_no_ = 0;
};

/// Fans a polygon (indices already checked) into triangles of the soup.
inline void add_polygon(TriangleSoup& s, const std::vector<std::uint32_t>& poly, std::size_t face, std::size_t line) {
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    s.triangles.push_back({poly[0], poly[i], poly[i + 1]});
    s.face.push_back(face);
    s.line.push_back(line);
  }
}

}  // namespace bccmis::io::detail
