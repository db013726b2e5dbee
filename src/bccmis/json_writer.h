// bccmis::JsonWriter: one JSON document built member by member, the one way
// the tools write JSON (`--json` reports).
//
// Layout: members and elements are separated by ", ", keys by ": ", on one
// line, e.g. {"shape": "sphere r=1", "leaves": 12, "seconds": {"total": 0.5}}.
// Strings are escaped by json_string (bccmis/io/format.h); doubles are written
// with 9 significant digits (%.9g), enough to tell apart any two numbers a
// report compares; integers exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "bccmis/io/format.h"

namespace bccmis {

class JsonWriter {
 public:
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  /// The key of the next member of the enclosing object.
  JsonWriter& key(std::string_view name) {
    separate();
    text_ += json_string(name);
    text_ += ": ";
    keyed_ = true;
    return *this;
  }

  JsonWriter& value(std::string_view s) { return raw(json_string(s)); }
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  JsonWriter& value(bool b) { return raw(b ? "true" : "false"); }
  JsonWriter& value(double x) { return raw(number(x)); }
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
  JsonWriter& value(I i) {
    return raw(std::to_string(i));
  }
  JsonWriter& null() { return raw("null"); }
  /// A value already written as JSON: a number in a fixed format ("%.6f"),
  /// a document made elsewhere.
  JsonWriter& json_value(std::string_view text) { return raw(text); }

  /// key(name).value(v) in one call.
  template <class T>
  JsonWriter& member(std::string_view name, const T& v) {
    return key(name).value(v);
  }

  /// The document so far.
  const std::string& str() const { return text_; }

  /// %.9g: what every report writes for a double.
  static std::string number(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", x);
    return buf;
  }

 private:
  // Before an element of an array, or a key of an object: ", " unless first.
  void separate() {
    if (keyed_) return;
    if (!first_.empty()) {
      if (!first_.back()) text_ += ", ";
      first_.back() = false;
    }
  }
  JsonWriter& raw(std::string_view s) {
    separate();
    keyed_ = false;
    text_ += s;
    return *this;
  }
  JsonWriter& open(char c) {
    separate();
    keyed_ = false;
    text_ += c;
    first_.push_back(true);
    return *this;
  }
  JsonWriter& close(char c) {
    text_ += c;
    first_.pop_back();
    return *this;
  }

  std::string text_;
  std::vector<bool> first_;  ///< per open object or array: no member yet
  bool keyed_ = false;       ///< a key was written, its value is next
};

}  // namespace bccmis
