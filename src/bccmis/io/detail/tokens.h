// bccmis::io::detail: a tokenizer of text mesh files that knows each
// token's line and column and throws ParseError (`file:line:column:
// message`): the Medit and Gmsh readers (medit_read.cpp, msh_read.cpp).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

#include "bccmis/io/parse_error.h"

namespace bccmis::io::detail {

class Tokens {
 public:
  Tokens(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  /// The offset of the next byte not yet read.
  std::size_t offset() const { return pos_; }

  struct Token {
    std::string_view text;  // empty at the end of the input
    int line = 1, column = 1;
  };

  // The next token; comments (# to the end of the line) and whitespace skipped.
  Token next() {
    skip();
    Token t{{}, line_, column_};
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !space(text_[pos_]) && text_[pos_] != '#') {
      check_byte();
      ++pos_;
      ++column_;
    }
    t.text = text_.substr(start, pos_ - start);
    return t;
  }

  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw ParseError(name_, t.line, t.column, message);
  }

  // The next token as an integer in [lo, hi]; `what` names it in messages.
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi) {
    const Token t = next();
    if (t.text.empty()) fail(t, std::string("unexpected end of file: expected ") + what);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc() && end == t.text.data() + t.text.size() && (v < lo || v > hi)))
      fail(t, std::string(what) + " '" + shown(t.text) + "' is out of range [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail(t, std::string("expected ") + what + ", got '" + shown(t.text) + "'");
    return v;
  }

  // The next token as a finite double.
  double real(const char* what) {
    const Token t = next();
    if (t.text.empty()) fail(t, std::string("unexpected end of file: expected ") + what);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail(t, std::string("expected ") + what + " (a decimal number), got '" + shown(t.text) + "'");
    if (!std::isfinite(v)) fail(t, std::string(what) + " '" + shown(t.text) + "' is not finite");
    return v;
  }

 private:
  static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

  static std::string shown(std::string_view s) {
    return s.size() <= 40 ? std::string(s) : std::string(s.substr(0, 40)) + "...";
  }

  void check_byte() const {
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (c < 0x20 || c >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      throw ParseError(name_, line_, column_, std::string("unexpected byte '") + buf + "'");
    }
  }

  void skip() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        column_ = 1;
        ++pos_;
      } else if (space(c)) {
        ++column_;
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') {
          ++pos_;
          ++column_;
        }
      } else {
        return;
      }
    }
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1, column_ = 1;
};

}  // namespace bccmis::io::detail
