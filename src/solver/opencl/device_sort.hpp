// The stable counting sort on the device (kernels/grid.cl, grid_clear … grid_order_cells): the device
// twin of counting_sort.cpp. `items` keys in [0, cells) become the cell ranges (`start`, cells + 1
// entries) and the item indices by cell, increasing within a cell (`sorted`): the same arrays as the
// host's. The collision grid sorts its envelope triangles with one (GPUs), the repulsion order its
// boundary vertices with another (boundary_order.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "kernel.hpp"

namespace animpak::opencl {

class DeviceCountingSort {
 public:
  DeviceCountingSort() = default;
  /// Its kernels bound to `keys` (input, `items` ints) and to `start` and `sorted` (outputs), with
  /// counts, block sums and cursors of its own; `label`, when not empty, prefixes its kernels' names in
  /// the profile ("order: grid_count").
  DeviceCountingSort(const cl::Context& context, const cl::Program& program, std::int32_t items, std::int32_t cells,
                     const cl::Buffer& keys, const cl::Buffer& start, const cl::Buffer& sorted,
                     const std::string& label = "");

  /// The sort's launches, in order: count, scan, scatter, then each cell's range put in increasing order.
  std::array<Launch, 7> launches();

 private:
  std::int32_t items_ = 0, cells_ = 0;
  cl::Buffer count_, block_sum_, cursor_;
  Kernel clear_, count_kernel_, block_sums_, scan_blocks_, scan_cells_, scatter_, order_;
};

}  // namespace animpak::opencl
