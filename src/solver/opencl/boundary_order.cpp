// The repulsion kernel's work order, sorted on the host or on the device (boundary_order.hpp).
#include "boundary_order.hpp"

#include <algorithm>

#include "animpak/reference.hpp"
#include "device_buffers.hpp"

namespace animpak::opencl {

BoundaryOrder::BoundaryOrder(const cl::Context& context, const cl::CommandQueue& queue, const cl::Program& program,
                             std::vector<std::int32_t> boundary, const GridInfo& grid, const cl::Buffer& x,
                             const cl::Buffer& y, const cl::Buffer& t, bool on_device)
    : on_device_(on_device),
      count_(static_cast<std::int32_t>(boundary.size())),
      grid_(grid),
      host_(std::move(boundary)) {
  grid_.triangles = count_;
  order_ = upload_buffer(context, queue, host_, "boundary_vertices");
  if (!on_device_) {
    keys_.resize(host_.size());
    return;
  }
  const auto ints = [&](std::size_t n, const char* name) {
    return make_buffer(context, CL_MEM_READ_WRITE, sizeof(std::int32_t) * std::max<std::size_t>(n, 1), name);
  };
  const std::size_t per_vertex = static_cast<std::size_t>(count_), cells = static_cast<std::size_t>(grid_.cells);
  const std::int32_t blocks = (grid_.cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  cell_ = ints(per_vertex, "boundary_cell");
  previous_ = ints(per_vertex, "boundary_previous");
  sorted_ = ints(per_vertex, "boundary_sorted");
  count_buf_ = ints(cells, "boundary_cell_count");
  block_sum_ = ints(static_cast<std::size_t>(blocks), "boundary_scan_blocks");
  cell_start_ = ints(cells + 1, "boundary_cell_start");
  cursor_ = ints(cells, "boundary_cell_cursor");
  // The collision grid's counting sort (grid.cl) over the boundary vertices' cells.
  cells_ = Kernel(program, "boundary_cells");
  cells_.bind(grid_, order_, x, y, t, cell_, previous_);
  clear_ = Kernel(program, "grid_clear", "order: grid_clear");
  clear_.bind(grid_, count_buf_);
  count_kernel_ = Kernel(program, "grid_count", "order: grid_count");
  count_kernel_.bind(grid_, cell_, count_buf_);
  block_sums_ = Kernel(program, "grid_block_sums", "order: grid_block_sums");
  block_sums_.bind(grid_, count_buf_, block_sum_);
  scan_blocks_ = Kernel(program, "grid_scan_blocks", "order: grid_scan_blocks");
  scan_blocks_.bind(grid_, block_sum_);
  scan_cells_ = Kernel(program, "grid_scan_cells", "order: grid_scan_cells");
  scan_cells_.bind(grid_, count_buf_, block_sum_, cell_start_, cursor_);
  scatter_ = Kernel(program, "grid_scatter", "order: grid_scatter");
  scatter_.bind(grid_, cell_, cursor_, sorted_);
  order_kernel_ = Kernel(program, "grid_order_cells", "order: grid_order_cells");
  order_kernel_.bind(grid_, cell_start_, sorted_);
  gather_ = Kernel(program, "boundary_gather");
  gather_.bind(grid_, sorted_, previous_, order_);
}

std::array<Launch, 9> BoundaryOrder::launches() {
  const std::int32_t blocks = (grid_.cells + AP_SCAN_BLOCK - 1) / AP_SCAN_BLOCK;
  return {{{&cells_, count_},
           {&clear_, grid_.cells},
           {&count_kernel_, count_},
           {&block_sums_, blocks},
           {&scan_blocks_, AP_LOCAL_SIZE},  // one work-group
           {&scan_cells_, blocks},
           {&scatter_, count_},
           {&order_kernel_, grid_.cells},
           {&gather_, count_}}};
}

void BoundaryOrder::sort_on_host(const cl::CommandQueue& queue, const std::vector<float>& x,
                                 const std::vector<float>& y, const std::vector<float>& t) {
  for (std::size_t i = 0; i < host_.size(); ++i) {
    const std::int32_t v = host_[i];
    const std::int32_t cx = reference::grid_axis_cell(x[v], grid_.cell, grid_.n),
                       cy = reference::grid_axis_cell(y[v], grid_.cell, grid_.n),
                       ct = reference::grid_axis_cell(t[v], grid_.cell, grid_.n);
    keys_[i] = {(ct * grid_.n + cy) * grid_.n + cx, v};
  }
  std::sort(keys_.begin(), keys_.end());
  for (std::size_t i = 0; i < keys_.size(); ++i) host_[i] = keys_[i].second;
  if (!host_.empty())
    check(queue.enqueueWriteBuffer(order_, CL_FALSE, 0, sizeof(std::int32_t) * host_.size(), host_.data()),
          "clEnqueueWriteBuffer(boundary_vertices)");
}

std::vector<std::int32_t> BoundaryOrder::read(const cl::CommandQueue& queue) const {
  std::vector<std::int32_t> out(host_.size());
  if (!out.empty())
    check(queue.enqueueReadBuffer(order_, CL_TRUE, 0, sizeof(std::int32_t) * out.size(), out.data()),
          "clEnqueueReadBuffer(boundary_vertices)");
  return out;
}

}  // namespace animpak::opencl
