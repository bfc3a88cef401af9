// The OpenCL backend's grids (device_backend.hpp): the collision grid (§5.1) and the overlap test's
// broadphase, built either on the device (GPUs: a step then never waits for the host) or on the host
// (CPU devices): the collision grid's stable counting sort (count → exclusive scan → scatter) from the
// cell ids read back, the broadphase from the slice boxes read back every step (overlap_broadphase.cpp);
// and the repulsion kernel's work order by cell, refreshed every 100 steps (boundary_order.cpp).
#include "../counting_sort.hpp"
#include "device_backend.hpp"

namespace animpak::opencl {

// The repulsion kernel's work-items in the order of their vertices' grid cells (boundary_order.hpp):
// on the device, or on the host from the positions read back (one transfer every 100 steps).
void DeviceBackend::order_boundary_by_cell() {
  if (boundary_.on_device()) {
    for (const Launch& l : boundary_.launches()) timed(times_.grid, *l.kernel, l.items);
  } else {
    const std::size_t n = static_cast<std::size_t>(world_.vertices);
    std::vector<float> px(n), py(n), pt(n);
    read(positions_, AP_X, px), read(positions_, AP_Y, py), read(positions_, AP_T, pt, true);
    settle_times();
    PhaseStopwatch w(times_.transfer), own(host_reorder_);
    ++host_reorders_;
    boundary_.sort_on_host(queue_, px, py, pt);
  }
  boundary_ordered_ = true;
  boundary_ordered_at_ = iteration_;
}

// Centroids and cells on the device, the stable counting sort on the device or on the host (as
// grid.cpp), then the per-slot copies the force kernels read.
void DeviceBackend::build_grid() {
  timed(times_.grid, envelope_cells_, grid_.triangles);
  if (sort_ == GridSort::device) {
    for (const Launch& l : grid_sort_.launches()) timed(times_.grid, *l.kernel, l.items);
  } else {
    host_sort();
  }
  timed(times_.grid, grid_gather_, grid_.triangles);
  if (grid_.far_cells != 0) {
    timed(times_.grid, run_counts_, grid_.cells);
    for (const Launch& l : run_scan_.launches()) timed(times_.grid, *l.kernel, l.items);
    timed(times_.grid, grid_runs_, grid_.cells);
  }
  grid_built_ = true;
}

void DeviceBackend::host_sort() {
  read(scratch_.triangle_cell, cells_, "triangle_cell", true);
  settle_times();
  PhaseStopwatch w(times_.grid), own(host_sort_);
  ++host_sorts_;
  counting_sort(cells_, grid_.cells, cell_start_, sorted_);
  // The host vectors stay untouched until the next build, which first waits on this queue.
  scratch_.grid_index.write(queue_, AP_INDEX_CELL_START, cell_start_, false);
  if (!sorted_.empty())
    check(
        queue_.enqueueWriteBuffer(scratch_.sorted, CL_FALSE, 0, sizeof(std::int32_t) * sorted_.size(), sorted_.data()),
        "clEnqueueWriteBuffer(sorted_triangles)");
}

// The overlap test's broadphase from this step's slice boxes: on the device, or on the host from the
// boxes read back.
void DeviceBackend::build_overlap_grid() {
  if (broadphase_.on_device()) {
    for (const Launch& l : broadphase_.launches()) timed(times_.forces, *l.kernel, l.items);
  } else {
    const PlaneBuffer& g = scratch_.slice_geometry;
    read(g, AP_GEOM_X0, boxes_.x0), read(g, AP_GEOM_Y0, boxes_.y0);
    read(g, AP_GEOM_X1, boxes_.x1), read(g, AP_GEOM_Y1, boxes_.y1);
    read(g, AP_GEOM_T, boxes_.t, true);
    settle_times();
    PhaseStopwatch watch(times_.forces), own(host_overlap_grid_);
    ++host_overlap_builds_;
    broadphase_.upload(queue_, topo_, boxes_);
  }
  broadphase_.bind(repulsion_force_);
}

}  // namespace animpak::opencl
