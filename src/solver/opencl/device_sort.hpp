// The stable counting sort on the device (kernels/grid.cl, grid_clear … grid_order_cells), and the scan
// it is built on: the device
// twin of counting_sort.cpp. `items` keys in [0, cells) become the cell ranges (`start`, cells + 1
// entries) and the item indices by cell, increasing within a cell (`sorted`): the same arrays as the
// host's. The collision grid sorts its envelope triangles with one (GPUs), the repulsion order its
// boundary vertices with another (boundary_order.hpp); the far field's runs are packed by a scan
// (grid_schedule.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "kernel.hpp"

namespace animpak::opencl {

/// Where a scan writes its cell ranges: plane `plane` of `buffer`, planes `stride` ints apart (a grouped
/// buffer's, such as grid_index's cell or run ranges; plane 0 and stride 0 for a buffer of its own). The
/// kernels take the whole buffer and form the plane themselves (kernels/grid.cl, grid_scan_cells).
struct StartPlane {
  cl::Buffer buffer;
  cl_int plane = 0;
  std::int32_t stride = 0;
};

/// The exclusive scan of `cells` counts on the device (grid_block_sums, grid_scan_blocks, grid_scan_cells):
/// `start` gets cells + 1 entries, the total last, and its own `cursor` a copy of the first `cells`
/// (the counting sort's scatter takes its slots from it).
class DeviceScan {
 public:
  DeviceScan() = default;
  DeviceScan(const cl::Context& context, const cl::Program& program, std::int32_t cells, const cl::Buffer& count,
             const StartPlane& start, const std::string& label = "");

  /// The scan's launches, in order: block sums, their scan in one work-group, then each block's cells.
  std::array<Launch, 3> launches();
  const cl::Buffer& cursor() const { return cursor_; }

 private:
  std::int32_t cells_ = 0;
  cl::Buffer block_sum_, cursor_;
  Kernel block_sums_, scan_blocks_, scan_cells_;
};

class DeviceCountingSort {
 public:
  DeviceCountingSort() = default;
  /// Its kernels bound to `keys` (input, `items` ints) and to `start` and `sorted` (outputs), with
  /// counts and a scan of its own; `label`, when not empty, prefixes its kernels' names in
  /// the profile ("order: grid_count").
  DeviceCountingSort(const cl::Context& context, const cl::Program& program, std::int32_t items, std::int32_t cells,
                     const cl::Buffer& keys, const StartPlane& start, const cl::Buffer& sorted,
                     const std::string& label = "");

  /// The sort's launches, in order: count, scan, scatter, then each cell's range put in increasing order.
  std::array<Launch, 7> launches();

 private:
  std::int32_t items_ = 0, cells_ = 0;
  cl::Buffer count_;
  DeviceScan scan_;
  Kernel clear_, count_kernel_, scatter_, order_;
};

}  // namespace animpak::opencl
