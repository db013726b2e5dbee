#include "bccmis/io/d3/format.h"

#include <string>

#include "bccmis/d3/lattice.h"  // static_assert(AdaptiveLattice<Graph>)
#include "bccmis/io/detail/parse.h"
#include "bccmis/io/detail/state_writer.h"
#include "bccmis/io/format.h"
#include "bccmis/text_writer.h"

namespace bccmis::d3 {

void write_canonical_state(std::ostream& out, const Graph& g) { detail::write_state_as(out, g); }

std::string canonical_state(const Graph& g) { return canonical_text(g); }

Graph parse_state(std::string_view text, std::string_view file) { return detail::parse_state_as<Graph>(text, file); }

}  // namespace bccmis::d3

namespace bccmis {

AnyState parse_any_state(std::string_view text, std::string_view file) {
  // The dimension is the number of fields on line 2 (`lattice W H D L`: 5);
  // anything else, malformed texts included, is read and reported as 2D.
  const std::size_t first = text.find('\n');
  if (first != std::string_view::npos) {
    const std::string_view rest = text.substr(first + 1);
    const std::string_view line = rest.substr(0, rest.find('\n'));
    std::size_t fields = 0;
    bool in_field = false;
    for (const char ch : line) {
      if (ch != ' ' && !in_field) ++fields;
      in_field = ch != ' ';
    }
    if (line.starts_with("lattice ") && fields == 5) return d3::parse_state(text, file);
  }
  return parse_state(text, file);
}

}  // namespace bccmis
