// What one step of either backend computes and writes, in the same layout (docs/architecture.md, "One
// step"): the forces of Eq. 7 per vertex, with every force apart for the comparisons (include/animpak/compare.hpp),
// the slice gaps and contacts that growth and the stop test read (§5.3), growth's per-slice change flags,
// and the containment constraint's margin. The values the kernels share are checked against
// kernels/shared_types.h (AP_GROWTH_*, AP_CONTAINMENT_MARGIN) in src/solver/opencl/layout.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "animpak/state.hpp"
#include "shared_types.h"

namespace animpak {

/// Per-vertex force components, structure of arrays.
struct ForceField {
  std::vector<float> x, y, t;
  /// n zero vectors.
  void assign(std::size_t n) {
    x.assign(n, 0.0f);
    y.assign(n, 0.0f);
    t.assign(n, 0.0f);
  }
  void set(std::int32_t v, Vec3f f) {
    x[v] = f.x;
    y[v] = f.y;
    t[v] = f.t;
  }
  Vec3f at(std::int32_t v) const { return {x[v], y[v], t[v]}; }
};

/// Every force of Eq. 7 separately, one field per row of AP_FORCE_TERMS (kernels/shared_types.h), in its
/// order (the equivalence suite and `validate` compare them one by one).
struct ForceBreakdown {
#define AP_BREAKDOWN_FIELD(name, ...) ForceField name;
  AP_FORCE_TERMS(AP_BREAKDOWN_FIELD)
#undef AP_BREAKDOWN_FIELD
};

struct StepForces {
  ForceField total;  ///< Eq. 7 per vertex
  /// Per boundary vertex, the distance to the nearest other element or container wall (the slice gap of
  /// §5.3 counts the wall as a neighbour), 0 when it overlaps; +inf for interior vertices.
  std::vector<float> closest;
  std::vector<std::uint8_t> contact;  ///< per vertex: ContactBit flags (growth pauses, shrinks, statistics)
};

/// Bits of the per-slice `changed` flags growth writes (§5.3; reference::grow_slices, kernels/growth.cl):
/// whether g grew or shrank, and whether the element's growth_ratio or neighbour_growth_ratio limit held it
/// below its own proposal or below one growth step at growth_rate, whichever is less (such a slice is
/// blocked by a contact elsewhere in its element, so the stop test counts it as touching; one that the
/// limits only slow from the room's boost is not).
enum GrowthChange : std::uint8_t { growth_kept = 0, growth_grew = 1, growth_shrank = 2, growth_held = 4 };

/// How far inside the container the containment constraint puts a vertex that left it (docs/parameters.md,
/// "Containment"; reference::apply_containment, kernels/boundary.cl).
inline constexpr float containment_margin = 1e-5f;

}  // namespace animpak
