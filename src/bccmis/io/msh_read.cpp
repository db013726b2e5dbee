// The Gmsh MSH 4.1 reader (msh.h): one pass over the sections of an ASCII
// file; a binary file goes to msh_read_binary.cpp.
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

#include "bccmis/io/detail/msh_binary.h"
#include "bccmis/io/detail/tokens.h"
#include "bccmis/io/msh.h"

namespace bccmis::io {

namespace {

using detail::Tokens;

constexpr std::int64_t kMaxCount = std::numeric_limits<std::uint32_t>::max() - 1;
constexpr std::int64_t kMaxTag = std::numeric_limits<std::int64_t>::max();

void expect(Tokens& in, std::string_view word) {
  const Tokens::Token t = in.next();
  if (t.text != word)
    in.fail(t, "expected '" + std::string(word) + "', got '" + std::string(t.text.substr(0, 40)) + "'");
}

// "numEntityBlocks numWHATs minWHATTag maxWHATTag": the number of blocks.
std::int64_t section_header(Tokens& in, const std::string& what) {
  const std::int64_t blocks = in.integer(("the number of " + what + " blocks").c_str(), 0, kMaxCount);
  in.integer(("the number of " + what + "s").c_str(), 0, kMaxCount);
  in.integer(("the smallest " + what + " tag").c_str(), 0, kMaxTag);
  in.integer(("the largest " + what + " tag").c_str(), 0, kMaxTag);
  return blocks;
}

// "entityDim entityTag" at the start of a block.
void block_entity(Tokens& in) {
  in.integer("the entity dimension", 0, 3);
  in.integer("the entity tag", std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
}

}  // namespace

d3::TetMeshF read_msh(std::string_view text, const std::string& name, Orientation orientation) {
  Tokens in(text, name);
  expect(in, "$MeshFormat");
  const Tokens::Token version = in.next();
  if (version.text != "4.1")
    in.fail(version, "MSH version '" + std::string(version.text.substr(0, 40)) + "': read 4.1");
  const std::int64_t file_type = in.integer("the file type (0 ASCII, 1 binary)", 0, 1);
  in.integer("the data size", 8, 8);
  if (file_type == 1) {
    // The byte-order int follows the header line's newline.
    const std::size_t line_end = text.find('\n', in.offset());
    return detail::read_msh_binary(text, name, line_end == std::string_view::npos ? text.size() : line_end + 1,
                                   orientation);
  }
  expect(in, "$EndMeshFormat");
  d3::TetMeshF mesh;
  std::unordered_map<std::int64_t, std::uint32_t> vertex_of;  // node tag -> vertex
  bool nodes = false, elements = false;
  for (Tokens::Token key = in.next(); !key.text.empty(); key = in.next()) {
    if (key.text == "$Nodes") {
      if (nodes) in.fail(key, "a second '$Nodes' section");
      nodes = true;
      const std::int64_t blocks = section_header(in, "node");
      for (std::int64_t b = 0; b < blocks; ++b) {
        block_entity(in);
        in.integer("the parametric flag (0: not parametric)", 0, 0);
        const std::int64_t n = in.integer("the number of nodes in the block", 0, kMaxCount);
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        for (std::int64_t i = 0; i < n; ++i) {
          Tokens probe = in;
          const Tokens::Token at = probe.next();
          const std::int64_t tag = in.integer("a node tag", 1, kMaxTag);
          if (!vertex_of.emplace(tag, first + static_cast<std::uint32_t>(i)).second)
            in.fail(at, "node tag " + std::to_string(tag) + " appears twice");
        }
        for (std::int64_t i = 0; i < n; ++i) {
          d3::Vec3 p{};
          for (double& c : p) c = in.real("a coordinate");
          mesh.vertices.push_back(p);
          mesh.kind.push_back(0);
        }
      }
      expect(in, "$EndNodes");
    } else if (key.text == "$Elements") {
      if (!nodes) in.fail(key, "'$Elements' before '$Nodes'");
      if (elements) in.fail(key, "a second '$Elements' section");
      elements = true;
      const std::int64_t blocks = section_header(in, "element");
      for (std::int64_t b = 0; b < blocks; ++b) {
        block_entity(in);
        Tokens probe = in;
        const Tokens::Token type_at = probe.next();
        const std::int64_t type = in.integer("the element type", 1, 1000);
        const int corners = type == 4 ? 4 : type == 2 ? 3 : type == 1 ? 2 : type == 15 ? 1 : 0;
        if (corners == 0)
          in.fail(type_at, "element type " + std::to_string(type) +
                               ": read 4 (tetrahedra), and skip 2, 1 and 15 (triangles, lines, points)");
        const std::int64_t n = in.integer("the number of elements in the block", 0, kMaxCount);
        for (std::int64_t i = 0; i < n; ++i) {
          in.integer("an element tag", 1, kMaxTag);
          std::array<std::uint32_t, 4> t{};
          Tokens::Token first{};
          for (std::size_t k = 0; k < static_cast<std::size_t>(corners); ++k) {
            Tokens node_probe = in;
            const Tokens::Token at = node_probe.next();
            if (k == 0) first = at;
            const auto it = vertex_of.find(in.integer("a node tag", 1, kMaxTag));
            if (it == vertex_of.end()) in.fail(at, "unknown node tag");
            t[k] = it->second;
            for (std::size_t j = 0; j < k; ++j)
              if (t[j] == t[k]) in.fail(at, "node " + std::string(at.text) + " appears twice");
          }
          if (type != 4) continue;
          if (const std::string why = orientation_fault(orientation, mesh.vertices, t); !why.empty())
            in.fail(first, "tetrahedron " + std::to_string(mesh.tets.size() + 1) + why);
          mesh.tets.push_back(t);
          mesh.level.push_back(0);
        }
      }
      expect(in, "$EndElements");
    } else if (key.text.size() > 1 && key.text[0] == '$' && !key.text.starts_with("$End")) {
      // Another section ($PhysicalNames, $Entities, ...): skipped to its end.
      const std::string end = "$End" + std::string(key.text.substr(1));
      Tokens::Token t = in.next();
      while (!t.text.empty() && t.text != end) t = in.next();
      if (t.text.empty()) in.fail(t, "unexpected end of file: expected '" + end + "'");
    } else {
      in.fail(key, "expected a section ($Nodes, $Elements, ...), got '" + std::string(key.text.substr(0, 40)) + "'");
    }
  }
  if (!elements) in.fail(in.next(), "unexpected end of file: no '$Elements' section");
  return mesh;
}

}  // namespace bccmis::io
