// S2-S9 of spec/stuffing.md in one call: the lattice (background.cpp) and
// the stuffer of the chosen implementation (reference_stuffer.cpp,
// flat_stuffer.cpp).
#include <utility>

#include "bccmis/stuff/detail/stuffer.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

Stuffed stuff_fitted(const Shape& shape, const Fit& fit, const StuffOptions& options, Impl impl, PhaseTimes* times,
                     const std::function<void(std::size_t, double)>& on_lattice) {
  const auto t0 = Clock::now();
  const auto lattice_done = [&](std::size_t leaves) {
    const double seconds = seconds_since(t0);
    if (times) times->lattice = seconds;
    if (on_lattice) on_lattice(leaves, seconds);
  };
  if (impl == Impl::reference) {
    const d3::Graph g = background(shape, fit, options);
    lattice_done(g.C.size());
    return stuff(shape, fit, g, options, times);
  }
  d3::fast::Lattice g = background_fast(shape, fit, options);
  lattice_done(g.cell_count());
  return stuff(shape, fit, std::move(g), options, times);  // M26: freed after S6
}

Stuffed stuff_shape(const Shape& shape, const StuffOptions& options, Impl impl, PhaseTimes* times) {
  return stuff_fitted(shape, fit_lattice(shape.bounds(), options), options, impl, times);
}

}  // namespace bccmis::stuff
