// The collision grid's stable counting sort (paper §5.1; docs/architecture.md, "One step"):
// count → exclusive scan → scatter. The reference builds its grid with it, and the OpenCL backend runs
// it on the host for CPU devices; the device sort (kernels/grid.cl) produces the same arrays.
#pragma once

#include <cstdint>
#include <vector>

namespace animpak {

/// Sorts items 0 .. item_cell.size() − 1 by their cell in [0, cells): `cell_start` gets cells + 1
/// entries (cell c holds sorted[cell_start[c], cell_start[c + 1])), and within a cell the items keep
/// their increasing order (stable), so every backend visits them in the same order.
void counting_sort(const std::vector<std::int32_t>& item_cell, std::int32_t cells,
                   std::vector<std::int32_t>& cell_start, std::vector<std::int32_t>& sorted);

}  // namespace animpak
