// bccmis render STATE -o FILE: a state (or a trace's final state) as SVG;
// a 3D state as the box and one slice (spec/cli.md, render).
#include <charconv>
#include <string>
#include <type_traits>
#include <variant>

#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

// "--slice AXIS=VALUE" for a 3D lattice of `size`; the middle z plane when empty.
SlicePlane parse_slice(const std::string& text, const d3::LatticeSize3& size) {
  if (text.empty()) return middle_slice(size);
  const std::string axes = "xyz";
  const auto bad = [&](const std::string& why) { return InputError("--slice '" + text + "': " + why); };
  if (text.size() < 3 || text[1] != '=' || axes.find(text[0]) == std::string::npos)
    throw bad("expected AXIS=VALUE with AXIS x, y or z, e.g. z=2");
  SlicePlane s{static_cast<int>(axes.find(text[0])), 0};
  const char* first = text.data() + 2;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, s.value);
  if (ec != std::errc() || end != last) throw bad("the value must be an integer");
  const std::int64_t S = d3::level0_side(size);
  const std::int64_t extent = (s.axis == 0 ? size.W : s.axis == 1 ? size.H : size.D) * S;
  if (s.value < 0 || s.value > extent)
    throw bad("outside the box: " + std::string(1, text[0]) + " in [0, " + std::to_string(extent) + "]");
  return s;
}

}  // namespace

int run(const RenderOptions& o) {
  const AnyState state = read_any_state_or_trace(o.state, o.from_trace);
  const std::string svg = std::visit(
      [&](const auto& g) {
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, d3::Graph3>) {
          return render_svg3(g, display_name(o.state), parse_slice(o.slice, g.size));
        } else {
          if (!o.slice.empty())
            throw InputError(display_name(o.state) + ": a 2D lattice; --slice applies to 3D states");
          return render_svg(g, display_name(o.state));
        }
      },
      state);
  write_atomically(o.output, svg);
  return kExitOk;
}

}  // namespace bccmis::cli
