// The host side of kernels/shared_types.h: the layouts and constants the kernels rely on are checked
// here at compile time. ForceParams, the step's float constants, comes from step_params
// (include/animpak/step_params.hpp), the one conversion of Params both backends read.
#include <cstddef>

#include "animpak/curve.hpp"
#include "animpak/reference/grid.hpp"
#include "animpak/spring_class.hpp"
#include "cl_host.hpp"

namespace animpak::opencl {

static_assert(sizeof(ap_int) == sizeof(cl_int) && sizeof(ap_float) == sizeof(cl_float));
static_assert(sizeof(GridInfo) == 28 && offsetof(GridInfo, cell) == 4 && offsetof(GridInfo, cells) == 12 &&
              offsetof(GridInfo, far_cells) == 16 && offsetof(GridInfo, slot_stride) == 24);
static_assert(sizeof(ContainerIndexInfo) == 32 && offsetof(ContainerIndexInfo, nx) == 12 &&
              offsetof(ContainerIndexInfo, cell_segments) == 28);
static_assert(sizeof(WorldInfo) == 56 && offsetof(WorldInfo, breakdown) == 20 &&
              offsetof(WorldInfo, boundaries) == 24 && offsetof(WorldInfo, vertex_stride) == 28 &&
              offsetof(WorldInfo, segment_stride) == 48 && offsetof(WorldInfo, motion_entries) == 52);
static_assert(sizeof(OverlapGridInfo) == 32 && offsetof(OverlapGridInfo, x0) == 12 &&
              offsetof(OverlapGridInfo, cell_t) == 28);
// ForceParams: 32 fields of its own, one per force of AP_LOCAL_FORCES after k_torsion, and the pad that
// keeps the size a multiple of 8 bytes; a 4-byte scalar each, so no padding between them.
static_assert(sizeof(ForceParams) == (32 + AP_LOCAL_FORCE_COUNT + 2 - AP_LOCAL_FORCE_COUNT % 2) * 4 &&
              sizeof(ForceParams) % 8 == 0);
static_assert(offsetof(ForceParams, k_spring) == 12 && offsetof(ForceParams, k_target) == 32 &&
              offsetof(ForceParams, dt) == 52 + 4 * AP_LOCAL_FORCE_COUNT &&
              offsetof(ForceParams, boost_step) == 124 + 4 * AP_LOCAL_FORCE_COUNT &&
              offsetof(ForceParams, pad) == 128 + 4 * AP_LOCAL_FORCE_COUNT);
static_assert(AP_VERTEX_BOUNDARY == vertex_boundary && AP_VERTEX_ANCHOR == vertex_anchor &&
              AP_VERTEX_HOLD_ANGLE == vertex_hold_angle);
static_assert(AP_SPRING_CLASSES == spring_class_count);
static_assert(AP_CURVE_LINEAR == curve_linear && AP_CURVE_MONOTONE == curve_monotone &&
              AP_CURVE_SPLINE == curve_spline);
static_assert(AP_CONTACT_OVERLAP == contact_overlap && AP_CONTACT_OUTSIDE == contact_outside &&
              AP_CONTACT_WALL == contact_wall && AP_CONTACT_INSIDE == contact_inside &&
              AP_CONTACT_YIELD == contact_yield && AP_CONTACT_BLOCK == contact_block);
static_assert(AP_GROWTH_GREW == growth_grew && AP_GROWTH_SHRANK == growth_shrank && AP_GROWTH_HELD == growth_held);
static_assert(AP_CONTAINMENT_MARGIN == containment_margin);
static_assert(static_cast<int>(SpringClass::target) == AP_SPRING_CLASSES - 1);

ContainerIndexInfo container_index_info(const ContainerIndex& index) {
  return {index.x0,         index.y0,           index.cell, index.nx, index.ny, index.band_segments,
          index.cell_start, index.cell_segments};
}

GridInfo grid_info(const Params& params, std::int32_t triangles) {
  GridInfo g{};  // the strides of its grouped buffers come with the device (with_grid_strides)
  g.n = reference::grid_cells_per_axis(params.forces.cell_size);
  g.cell = static_cast<float>(params.forces.cell_size);
  g.triangles = triangles;
  g.cells = g.n * g.n * g.n;
  g.far_cells = params.forces.far_cells != 0 ? 1 : 0;
  return g;
}

}  // namespace animpak::opencl
