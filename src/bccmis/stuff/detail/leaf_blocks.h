// The tetrahedra of the graded mesh of a lattice (spec/mesh3d.md M1-M4),
// handed on block by block of leaves in the order of d3::detail::tetrahedra_of,
// extracted by several threads at once (spec/stuffing.md S28).
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <span>
#include <thread>
#include <vector>

#include "bccmis/d3/detail/tetrahedra.h"
#include "bccmis/stuff/detail/parallel_ranges.h"

namespace bccmis::stuff::detail {

/// The leaves a block holds: a block's tetrahedra (about 13 a leaf, 96
/// bytes each) stay within a few megabytes.
inline constexpr std::size_t kLeavesPerBlock = 4096;

/// visit(slot, block) for consecutive blocks of the tetrahedra of g, leaf
/// by leaf in the order of cells(g), so that the blocks joined are
/// d3::detail::tetrahedra_of(g). `threads` threads (0: every core) extract
/// `threads` blocks at a time, each into its own buffer (slot 0, 1, ...),
/// and run prepare(slot, block) on it on the extracting thread; the blocks
/// are visited in order on the calling thread, so what visit sees does not
/// depend on the number of threads when prepare's result depends on the
/// block alone. G's const queries must be safe to call from several
/// threads (they read only).
template <class G, class Prepare, class Visit>
void for_each_block(const G& g, int threads, Prepare&& prepare, Visit&& visit) {
  const std::vector<d3::Point> leaves = cells(g);
  const std::size_t n = static_cast<std::size_t>(thread_count(threads));
  std::vector<std::vector<d3::Tet>> blocks(n);
  std::vector<std::exception_ptr> errors(n);
  const auto extract = [&](std::size_t slot, std::size_t first) {
    try {
      std::vector<d3::Tet>& out = blocks[slot];
      out.clear();
      const std::size_t last = std::min(leaves.size(), first + kLeavesPerBlock);
      for (std::size_t i = first; i < last; ++i) d3::detail::leaf_tetrahedra(g, leaves[i], out);
      prepare(slot, std::span<const d3::Tet>(out));
    } catch (...) {
      errors[slot] = std::current_exception();
    }
  };
  for (std::size_t round = 0; round < leaves.size(); round += n * kLeavesPerBlock) {
    std::vector<std::thread> helpers;
    for (std::size_t k = 1; k < n && round + k * kLeavesPerBlock < leaves.size(); ++k)
      helpers.emplace_back(extract, k, round + k * kLeavesPerBlock);
    extract(0, round);
    for (std::thread& t : helpers) t.join();
    for (std::size_t k = 0; k < n && round + k * kLeavesPerBlock < leaves.size(); ++k) {
      if (errors[k]) std::rethrow_exception(errors[k]);
      visit(k, std::span<const d3::Tet>(blocks[k]));
    }
  }
}

}  // namespace bccmis::stuff::detail
