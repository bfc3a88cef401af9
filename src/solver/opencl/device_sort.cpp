// The stable counting sort on the device (device_sort.hpp).
#include "device_sort.hpp"

#include <algorithm>

#include "device_buffers.hpp"

namespace animpak::opencl {

DeviceCountingSort::DeviceCountingSort(const cl::Context& context, const cl::Program& program, std::int32_t items,
                                       std::int32_t cells, const cl::Buffer& keys, const cl::Buffer& start,
                                       const cl::Buffer& sorted, const std::string& label)
    : items_(items), cells_(cells) {
  const auto ints = [&](std::int32_t n, const char* name) {
    return make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * std::max<std::size_t>(n, 1), name);
  };
  const std::int32_t blocks = (cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  count_ = ints(cells, "cell_count");
  block_sum_ = ints(blocks, "scan_blocks");
  cursor_ = ints(cells, "cell_cursor");
  // The kernels read the item and cell counts from a GridInfo (its other fields are the grid's shape).
  const GridInfo info{0, 1.0f, items, cells, 0};
  const auto kernel = [&](const char* name) {
    return Kernel(program, name, label.empty() ? nullptr : (label + name).c_str());
  };
  clear_ = kernel("grid_clear");
  clear_.bind(info, count_);
  count_kernel_ = kernel("grid_count");
  count_kernel_.bind(info, keys, count_);
  block_sums_ = kernel("grid_block_sums");
  block_sums_.bind(info, count_, block_sum_);
  scan_blocks_ = kernel("grid_scan_blocks");
  scan_blocks_.bind(info, block_sum_);
  scan_cells_ = kernel("grid_scan_cells");
  scan_cells_.bind(info, count_, block_sum_, start, cursor_);
  scatter_ = kernel("grid_scatter");
  scatter_.bind(info, keys, cursor_, sorted);
  order_ = kernel("grid_order_cells");
  order_.bind(info, start, sorted);
}

std::array<Launch, 7> DeviceCountingSort::launches() {
  const std::int32_t blocks = (cells_ + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  return {{{&clear_, cells_},
           {&count_kernel_, items_},
           {&block_sums_, blocks},
           {&scan_blocks_, AP_LOCAL_SIZE},  // one work-group
           {&scan_cells_, blocks},
           {&scatter_, items_},
           {&order_, cells_}}};
}

}  // namespace animpak::opencl
