// The stable counting sort on the device (device_sort.hpp).
#include "device_sort.hpp"

#include <algorithm>

#include "device_buffers.hpp"

namespace animpak::opencl {

namespace {

cl::Buffer ints(const cl::Context& context, std::int32_t n, const char* name) {
  return make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * std::max<std::size_t>(n, 1), name);
}

// The kernels read the item and cell counts from a GridInfo (its other fields are the grid's shape), and
// the stride of the planes the cell ranges are written to from its index_stride.
GridInfo counts_info(std::int32_t items, std::int32_t cells, std::int32_t start_stride) {
  return GridInfo{0, 1.0f, items, cells, 0, start_stride, 0};
}

Kernel labelled(const cl::Program& program, const std::string& label, const char* name) {
  return Kernel(program, name, label.empty() ? nullptr : (label + name).c_str());
}

}  // namespace

DeviceScan::DeviceScan(const cl::Context& context, const cl::Program& program, std::int32_t cells,
                       const cl::Buffer& count, const StartPlane& start, const std::string& label)
    : cells_(cells) {
  block_sum_ = ints(context, (cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK, "scan_blocks");
  cursor_ = ints(context, cells, "cell_cursor");
  const GridInfo info = counts_info(0, cells, start.stride);
  block_sums_ = labelled(program, label, "grid_block_sums");
  block_sums_.bind({{"grid", info}, {"cell_count", count}, {"block_sum", block_sum_}});
  scan_blocks_ = labelled(program, label, "grid_scan_blocks");
  scan_blocks_.bind({{"grid", info}, {"block_sum", block_sum_}});
  scan_cells_ = labelled(program, label, "grid_scan_cells");
  scan_cells_.bind({{"grid", info},
                    {"start_plane", start.plane},
                    {"cell_count", count},
                    {"block_start", block_sum_},
                    {"starts", start.buffer},
                    {"cursor", cursor_}});
}

std::array<Launch, 3> DeviceScan::launches() {
  const std::int32_t blocks = (cells_ + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  return {{{&block_sums_, blocks}, {&scan_blocks_, AP_LOCAL_SIZE} /* one work-group */, {&scan_cells_, blocks}}};
}

DeviceCountingSort::DeviceCountingSort(const cl::Context& context, const cl::Program& program, std::int32_t items,
                                       std::int32_t cells, const cl::Buffer& keys, const StartPlane& start,
                                       const cl::Buffer& sorted, const std::string& label)
    : items_(items), cells_(cells) {
  count_ = ints(context, cells, "cell_count");
  scan_ = DeviceScan(context, program, cells, count_, start, label);
  const GridInfo info = counts_info(items, cells, start.stride);
  clear_ = labelled(program, label, "grid_clear");
  clear_.bind({{"grid", info}, {"cell_count", count_}});
  count_kernel_ = labelled(program, label, "grid_count");
  count_kernel_.bind({{"grid", info}, {"triangle_cell", keys}, {"cell_count", count_}});
  scatter_ = labelled(program, label, "grid_scatter");
  scatter_.bind({{"grid", info}, {"triangle_cell", keys}, {"cursor", scan_.cursor()}, {"sorted_triangles", sorted}});
  order_ = labelled(program, label, "grid_order_cells");
  order_.bind({{"grid", info}, {"start_plane", start.plane}, {"starts", start.buffer}, {"sorted_triangles", sorted}});
}

std::array<Launch, 7> DeviceCountingSort::launches() {
  const std::array<Launch, 3> scan = scan_.launches();
  return {
      {{&clear_, cells_}, {&count_kernel_, items_}, scan[0], scan[1], scan[2], {&scatter_, items_}, {&order_, cells_}}};
}

}  // namespace animpak::opencl
