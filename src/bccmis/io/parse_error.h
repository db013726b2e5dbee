// bccmis::ParseError: the error every text parser of bccmis throws on the
// first malformed input (traces, states, Medit meshes). what() is
// `file:line:column: message`.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace bccmis {

/// A malformed input file. what() is `file:line:column: message`.
struct ParseError : std::runtime_error {
  ParseError(std::string file_, int line_, int column_, std::string message_)
      : std::runtime_error(file_ + ":" + std::to_string(line_) + ":" + std::to_string(column_) + ": " + message_),
        file(std::move(file_)),
        line(line_),
        column(column_),
        message(std::move(message_)) {}
  std::string file;
  int line;
  int column;
  std::string message;
};

}  // namespace bccmis
