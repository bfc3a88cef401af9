// The repulsion kernel's work order for the OpenCL backend (docs/architecture.md, "The repulsion
// order"): the boundary vertices sorted by the collision-grid cell they are in, so that the work-items
// of one work-group (a GPU warp) walk the same cell rows in step instead of diverging, refreshed every
// `interval()` steps as the vertices move. Any order gives the same forces, since each work-item writes
// only its own vertex. Sorted either on the host from the positions read back (CPU devices, where the
// read costs little) or on the device by the collision grid's counting-sort kernels (GPUs, where a
// blocking read stops the queue).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "device_sort.hpp"
#include "kernel.hpp"

namespace animpak::opencl {

class BoundaryOrder {
 public:
  BoundaryOrder() = default;
  /// The boundary vertices in `boundary`'s order, uploaded; on the device, its sort's kernels bound to
  /// the positions group (its planes `world.vertex_stride` apart) and the collision grid's shape `grid`.
  BoundaryOrder(const cl::Context& context, const cl::CommandQueue& queue, const cl::Program& program,
                std::vector<std::int32_t> boundary, const GridInfo& grid, const WorldInfo& world,
                const cl::Buffer& positions, bool on_device);
  BoundaryOrder(const BoundaryOrder&) = delete;
  BoundaryOrder& operator=(const BoundaryOrder&) = delete;
  BoundaryOrder(BoundaryOrder&&) = default;
  BoundaryOrder& operator=(BoundaryOrder&&) = default;

  /// Steps between refreshes: the vertices move little in that many steps.
  static constexpr std::uint64_t interval() { return 100; }

  bool on_device() const { return on_device_; }
  std::int32_t count() const { return count_; }
  /// The boundary vertices in the current order: the repulsion and wall-image kernels' work list.
  const cl::Buffer& buffer() const { return order_; }

  /// A device refresh's launches, in order (on_device() only): a fixed array, so nothing is allocated.
  std::array<Launch, 9> launches();

  /// A host refresh from every vertex's position (read back), uploaded without waiting; the host copy
  /// stays untouched until the next refresh, which the caller starts after waiting on the queue.
  void sort_on_host(const cl::CommandQueue& queue, const std::vector<float>& x, const std::vector<float>& y,
                    const std::vector<float>& t);

  /// The current order (a blocking read).
  std::vector<std::int32_t> read(const cl::CommandQueue& queue) const;

 private:
  bool on_device_ = false;
  std::int32_t count_ = 0;
  GridInfo grid_{};  ///< the collision grid's shape, with `triangles` the boundary vertex count
  cl::Buffer order_;
  // Host refresh only: the order last uploaded, kept alive for its non-blocking write, and the sort's
  // arrays (counting_sort.cpp).
  std::vector<std::int32_t> host_, keys_, start_, sorted_;
  // Device refresh only: each vertex's cell and the order it is sorted from, the collision grid's sort
  // over them, the sort's outputs.
  cl::Buffer cell_, previous_, sorted_buf_, start_buf_;
  DeviceCountingSort sort_;
  Kernel cells_, gather_;
};

}  // namespace animpak::opencl
