// S2-S9 of spec/stuffing.md in one call: the lattice (background.cpp) and
// the stuffer of the chosen implementation (reference_stuffer.cpp,
// flat_stuffer.cpp).
#include "bccmis/stuff/detail/stuffer.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

Stuffed stuff_shape(const Shape& shape, const StuffOptions& options, Impl impl, PhaseTimes* times) {
  const Fit fit = fit_lattice(shape.bounds(), options);
  detail::PhaseClock clock(times);
  if (impl == Impl::reference) {
    const d3::Graph g = background(shape, fit, options);
    clock.lap(&PhaseTimes::lattice);
    return stuff(shape, fit, g, options, times);
  }
  const d3::fast::Lattice g = background_fast(shape, fit, options);
  clock.lap(&PhaseTimes::lattice);
  return stuff(shape, fit, g, options, times);
}

}  // namespace bccmis::stuff
