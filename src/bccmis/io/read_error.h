// bccmis::io::ReadError: what the surface readers (.off, .obj, .ply, .stl)
// throw on a malformed or truncated file. what() names the file and the
// place: `file:line:column: message` in a text, `file: byte N: message` in a
// binary STL or PLY body.
#pragma once

#include <stdexcept>

namespace bccmis::io {

/// A surface file that does not read; what() is the whole message.
class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bccmis::io
