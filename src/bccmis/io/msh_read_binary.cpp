// The Gmsh MSH 4.1 binary reader (msh.h): the sections' numbers read as
// little-endian machine values from a cursor over the bytes.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <unordered_map>

#include "bccmis/io/detail/msh_binary.h"
#include "bccmis/io/parse_error.h"

namespace bccmis::io::detail {

namespace {

constexpr std::uint64_t kMaxCount = 0xfffffffeu;

class Bytes {
 public:
  Bytes(std::string_view text, const std::string& name, std::size_t pos) : text_(text), name_(name), pos_(pos) {}

  [[noreturn]] void fail(const std::string& message) const { fail_at(pos_, message); }
  [[noreturn]] void fail_at(std::size_t at, const std::string& message) const {
    int line = 1;
    std::size_t line_start = 0;
    for (std::size_t i = 0; i < at && i < text_.size(); ++i)
      if (text_[i] == '\n') ++line, line_start = i + 1;
    throw ParseError(name_, line, static_cast<int>(at - line_start + 1), message);
  }

  template <class T>
  T value(const char* what) {
    if (text_.size() - pos_ < sizeof(T)) fail(std::string("unexpected end of file: expected ") + what);
    T v;
    std::memcpy(&v, text_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  std::uint64_t count(const char* what) {
    const std::size_t at = pos_;
    const auto n = value<std::uint64_t>(what);
    if (n > kMaxCount) fail_at(at, std::string(what) + " " + std::to_string(n) + " is out of range");
    return n;
  }
  /// The text `word` at the cursor, after any white space.
  void expect(std::string_view word) {
    while (pos_ < text_.size() && (text_[pos_] == '\n' || text_[pos_] == '\r' || text_[pos_] == ' ')) ++pos_;
    if (text_.substr(pos_, word.size()) != word) fail("expected '" + std::string(word) + "'");
    pos_ += word.size();
  }
  /// The next line's first word ("" at the end), the cursor after its line.
  std::string_view section() {
    while (pos_ < text_.size() && (text_[pos_] == '\n' || text_[pos_] == '\r' || text_[pos_] == ' ')) ++pos_;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    const std::string_view word = text_.substr(pos_, end - pos_);
    pos_ = std::min(end + 1, text_.size());
    return word;
  }
  /// Skips to after the line `end`.
  void skip_to(const std::string& end) {
    const std::size_t at = text_.find("\n" + end, pos_ == 0 ? 0 : pos_ - 1);
    if (at == std::string_view::npos) fail("unexpected end of file: expected '" + end + "'");
    pos_ = at + 1 + end.size();
  }
  std::size_t pos() const { return pos_; }
  /// "numEntityBlocks num minTag maxTag": the number of blocks.
  std::uint64_t section_header() {
    const std::uint64_t blocks = count("the number of blocks");
    for (int i = 0; i < 3; ++i) value<std::uint64_t>("the section's counts");
    return blocks;
  }
  /// "entityDim entityTag" at the start of a block.
  void block_entity() {
    value<std::int32_t>("the entity dimension");
    value<std::int32_t>("the entity tag");
  }

 private:
  std::string_view text_;
  const std::string& name_;
  std::size_t pos_;
};

}  // namespace

d3::TetMeshF read_msh_binary(std::string_view text, const std::string& name, std::size_t pos, Orientation orientation) {
  Bytes in(text, name, pos);
  if (in.value<std::int32_t>("the byte-order int") != 1) in.fail("the byte-order int is not 1 (not little-endian)");
  in.expect("$EndMeshFormat");
  d3::TetMeshF mesh;
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of;
  bool nodes = false, elements = false;
  for (std::string_view key = in.section(); !key.empty(); key = in.section()) {
    if (key == "$Nodes") {
      if (nodes) in.fail("a second '$Nodes' section");
      nodes = true;
      const std::uint64_t blocks = in.section_header();
      for (std::uint64_t b = 0; b < blocks; ++b) {
        in.block_entity();
        if (in.value<std::int32_t>("the parametric flag") != 0) in.fail("parametric nodes");
        const std::uint64_t n = in.count("the number of nodes in the block");
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (std::uint64_t i = 0; i < n; ++i) {
          const std::size_t at = in.pos();
          const auto tag = in.value<std::uint64_t>("a node tag");
          if (!vertex_of.emplace(tag, first + static_cast<std::uint32_t>(i)).second)
            in.fail_at(at, "node tag " + std::to_string(tag) + " appears twice");
        }
        for (std::uint64_t i = 0; i < n; ++i) {
          d3::Vec3 p{};
          for (double& c : p) {
            c = in.value<double>("a coordinate");
            if (!std::isfinite(c)) in.fail("a coordinate that is not finite");
          }
          mesh.vertices.push_back(p);
          mesh.kind.push_back(0);
        }
      }
      in.expect("$EndNodes");
    } else if (key == "$Elements") {
      if (!nodes) in.fail("'$Elements' before '$Nodes'");
      if (elements) in.fail("a second '$Elements' section");
      elements = true;
      const std::uint64_t blocks = in.section_header();
      for (std::uint64_t b = 0; b < blocks; ++b) {
        in.block_entity();
        const auto type = in.value<std::int32_t>("the element type");
        const int corners = type == 4 ? 4 : type == 2 ? 3 : type == 1 ? 2 : type == 15 ? 1 : 0;
        if (corners == 0)
          in.fail("element type " + std::to_string(type) +
                  ": read 4 (tetrahedra), and skip 2, 1 and 15 (triangles, lines, points)");
        const std::uint64_t n = in.count("the number of elements in the block");
        for (std::uint64_t i = 0; i < n; ++i) {
          const std::size_t at = in.pos();
          in.value<std::uint64_t>("an element tag");
          std::array<std::uint32_t, 4> t{};
          for (std::size_t k = 0; k < static_cast<std::size_t>(corners); ++k) {
            const auto it = vertex_of.find(in.value<std::uint64_t>("a node tag"));
            if (it == vertex_of.end()) in.fail_at(at, "an unknown node tag");
            t[k] = it->second;
            for (std::size_t j = 0; j < k; ++j)
              if (t[j] == t[k]) in.fail_at(at, "a node appears twice");
          }
          if (type != 4) continue;
          if (const std::string why = orientation_fault(orientation, mesh.vertices, t); !why.empty())
            in.fail_at(at, "tetrahedron " + std::to_string(mesh.tets.size() + 1) + why);
          mesh.tets.push_back(t);
          mesh.level.push_back(0);
        }
      }
      in.expect("$EndElements");
    } else if (key.size() > 1 && key[0] == '$' && !key.starts_with("$End")) {
      in.skip_to("$End" + std::string(key.substr(1)));
    } else {
      in.fail("expected a section ($Nodes, $Elements, ...)");
    }
  }
  if (!elements) in.fail("unexpected end of file: no '$Elements' section");
  return mesh;
}

}  // namespace bccmis::io::detail
