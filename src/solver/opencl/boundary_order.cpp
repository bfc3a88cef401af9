// The repulsion kernel's work order, sorted on the host or on the device (boundary_order.hpp).
#include "boundary_order.hpp"

#include <algorithm>

#include "../counting_sort.hpp"
#include "animpak/state.hpp"
#include "device_buffers.hpp"

namespace animpak::opencl {

BoundaryOrder::BoundaryOrder(const cl::Context& context, const cl::CommandQueue& queue, const cl::Program& program,
                             std::vector<std::int32_t> boundary, const GridInfo& grid, const WorldInfo& world,
                             const cl::Buffer& positions, bool on_device)
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
  const std::size_t per_vertex = static_cast<std::size_t>(count_);
  cell_ = ints(per_vertex, "boundary_cell");
  previous_ = ints(per_vertex, "boundary_previous");
  sorted_buf_ = ints(per_vertex, "boundary_sorted");
  start_buf_ = ints(static_cast<std::size_t>(grid_.cells) + 1, "boundary_cell_start");
  cells_ = Kernel(program, "boundary_cells");
  cells_.bind({{"grid", grid_},
               {"world", world},
               {"order", order_},
               {"positions", positions},
               {"cell", cell_},
               {"previous", previous_}});
  sort_ =
      DeviceCountingSort(context, program, count_, grid_.cells, cell_, StartPlane{start_buf_}, sorted_buf_, "order: ");
  gather_ = Kernel(program, "boundary_gather");
  gather_.bind({{"grid", grid_}, {"sorted", sorted_buf_}, {"previous", previous_}, {"order", order_}});
}

std::array<Launch, 9> BoundaryOrder::launches() {
  const std::array<Launch, 7> sort = sort_.launches();
  return {{{&cells_, count_}, sort[0], sort[1], sort[2], sort[3], sort[4], sort[5], sort[6], {&gather_, count_}}};
}

void BoundaryOrder::sort_on_host(const cl::CommandQueue& queue, const std::vector<float>& x,
                                 const std::vector<float>& y, const std::vector<float>& t) {
  // As the device does: each vertex's cell, the stable counting sort, the vertices in sorted order.
  const std::vector<std::int32_t> previous = host_;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    const std::int32_t v = previous[i];
    keys_[i] = grid_linear_cell(x[v], y[v], t[v], grid_.cell, grid_.n);
  }
  counting_sort(keys_, grid_.cells, start_, sorted_);
  for (std::size_t j = 0; j < sorted_.size(); ++j) host_[j] = previous[sorted_[j]];
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
