#include "counting_sort.hpp"

namespace animpak {

void counting_sort(const std::vector<std::int32_t>& item_cell, std::int32_t cells,
                   std::vector<std::int32_t>& cell_start, std::vector<std::int32_t>& sorted) {
  // Count, then an exclusive scan in place: where each cell's range starts; the last entry is the total.
  cell_start.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (const std::int32_t c : item_cell) ++cell_start[c + 1];
  for (std::int32_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
  // Scatter in increasing item order, so each cell lists its items in increasing order (stable).
  std::vector<std::int32_t> cursor(cell_start.begin(), cell_start.end() - 1);
  sorted.resize(item_cell.size());
  for (std::size_t i = 0; i < item_cell.size(); ++i) sorted[cursor[item_cell[i]]++] = static_cast<std::int32_t>(i);
}

}  // namespace animpak
