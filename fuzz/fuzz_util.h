// Helpers shared by the fuzz targets: failing loudly with a replayable trace,
// and the shape every ParseError must have. The byte programs of the
// operation-sequence targets are tests/testing/byte_program.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "bccmis/io/format.h"

namespace bccmis::fuzz {

/// Prints `what` and, if given, the equivalent text trace (readable by
/// `bccmis replay`; a Trace or a d3::Trace) to stderr, then aborts so that the
/// fuzzing engine records a crash. With BCCMIS_FUZZ_TRACE=path in the
/// environment the trace is also written to that file.
template <class T = Trace>
[[noreturn]] void fail(std::string_view target, const std::string& what, const T* trace = nullptr) {
  std::string text = "# " + std::string(target) + ": " + what + "\n";
  if (trace) text += format_trace(*trace);
  std::fprintf(stderr, "\n==== %.*s failure: %s\n", static_cast<int>(target.size()), target.data(), what.c_str());
  if (trace) {
    std::fprintf(stderr, "==== equivalent trace (bccmis replay FILE):\n%s==== end of trace\n", text.c_str());
    if (const char* path = std::getenv("BCCMIS_FUZZ_TRACE")) {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
  }
  std::fflush(stderr);
  std::abort();
}

/// A parse error must be one printable line `file:line:column: message` that
/// points into the text: 1 <= line <= number of lines, 1 <= column <= length
/// of that line + 1.
inline void check_parse_error(std::string_view target, const ParseError& e, std::string_view file,
                              std::string_view text) {
  auto bad = [&](const std::string& why) { fail(target, "malformed ParseError (" + why + "): " + e.what()); };
  const std::string what = e.what();
  if (e.file != file) bad("wrong file name");
  const std::string prefix = std::string(file) + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ";
  if (what.compare(0, prefix.size(), prefix) != 0 || what.size() == prefix.size()) bad("not file:line:column: message");
  if (what.substr(prefix.size()) != e.message) bad("what() does not end with message");
  for (char ch : what) {
    const auto u = static_cast<unsigned char>(ch);
    if (u < 0x20 || u >= 0x7f) bad("unprintable byte in the message");
  }
  if (what.size() > 1000) bad("message longer than 1000 bytes");
  // Locate line e.line in text.
  std::size_t start = 0;
  int line = 1;
  while (line < e.line) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) bad("line number past the end of the text");
    start = nl + 1;
    ++line;
  }
  if (e.line < 1) bad("line number < 1");
  const std::size_t end = text.find('\n', start);
  const std::size_t length = (end == std::string_view::npos ? text.size() : end) - start;
  if (e.column < 1 || static_cast<std::size_t>(e.column) > length + 1) bad("column outside the line");
}

}  // namespace bccmis::fuzz
