// The overlap test's broadphase for the OpenCL backend (docs/architecture.md, "The overlap test"): the
// three buffers the repulsion kernel reads (the grid's shape, its cell ranges, its element lists),
// filled every step either on the host from the slice boxes read back (reference::build_overlap_grid:
// CPU devices, where the read costs little) or on the device (kernels/overlap_grid.cl: GPUs, where a
// blocking read stops the queue). Both give the same forces: the broadphase only chooses which
// elements the exact box test tries.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "animpak/solver/grids.hpp"
#include "device_buffers.hpp"
#include "kernel.hpp"

namespace animpak::opencl {

class OverlapBroadphase {
 public:
  OverlapBroadphase() = default;
  /// The buffers for `topo`'s slice pairs, and on the device its kernels bound to the slice boxes in
  /// `scratch`'s slice_geometry, its planes `world.slice_stride` apart (slice_boxes fills them before each
  /// build).
  OverlapBroadphase(const cl::Context& context, const cl::CommandQueue& queue, const cl::Program& program,
                    const Topology& topo, const WorldInfo& world, const ScratchBuffers& scratch, bool on_device);
  OverlapBroadphase(const OverlapBroadphase&) = delete;
  OverlapBroadphase& operator=(const OverlapBroadphase&) = delete;
  OverlapBroadphase(OverlapBroadphase&&) = default;
  OverlapBroadphase& operator=(OverlapBroadphase&&) = default;

  bool on_device() const { return on_device_; }

  /// A device build's launches, in order (on_device() only): a fixed array, so a step allocates nothing.
  std::array<Launch, 8> launches();

  /// A host build: the broadphase of `boxes` (this step's, read back), uploaded without waiting; the
  /// host copies stay untouched until the next build, which the caller starts after waiting on the queue.
  void upload(const cl::CommandQueue& queue, const Topology& topo, const SliceBoxes& boxes);

  /// Sets the repulsion kernel's overlap_grid, overlap_start and overlap_elements to the grid's shape,
  /// cell ranges and element lists (the buffers change when they grow, so every step).
  void bind(Kernel& repulsion) const;
  /// The same three buffers, as values to bind the repulsion kernel from at first.
  void add_values(ArgValues& values) const;

  /// A device build's element lists in all, as of the last build (read with the statistics).
  const cl::Buffer& total() const { return total_; }
  /// Given the total read back: when the lists came within a quarter of their room or over it, the
  /// room for twice the total. An overgrown build drops its grid (every query tries every element:
  /// the same forces, slower).
  void make_room(std::int32_t total);
  /// Room for `entries` list entries from now on (the tests shrink it to make a build overgrow).
  void set_capacity(std::size_t entries);

  /// The broadphase as the last build left it (read with a blocking read).
  OverlapGrid read(const cl::CommandQueue& queue) const;

 private:
  void bind_lists();

  bool on_device_ = false;
  cl::Context context_;
  std::int32_t pairs_ = 0, cell_capacity_ = 0;
  std::size_t capacity_ = 0;        ///< element list entries the buffer holds
  std::size_t start_capacity_ = 0;  ///< cell range entries the buffer holds
  cl::Buffer info_, start_, elements_;
  ArgValues values_;  ///< the device build's kernels' arguments, the slice boxes (its input) among them
  // Device build only:
  cl::Buffer pair_slice_, pair_element_, count_, cursor_, block_sum_, total_;
  Kernel extent_, clear_, count_kernel_, block_sums_, scan_blocks_, scan_cells_, scatter_, order_;
  // Host build only: what the last upload sent, kept alive for its non-blocking writes.
  OverlapGrid host_;
  OverlapGridInfo host_info_{};
};

}  // namespace animpak::opencl
