// The reference's step after the forces' phases: their sum, paper Eq. 7 (src/solver/reference/forces.cpp),
//   F = ((((((F_rpl + F_edg) + F_tgt) + F_bdr) + F_ovr) + F_tor) + F_tmp),
// the symplectic Euler step with the velocity cap (§5, integrate.cpp) and the slice constraints of §5.2
// (constraints.cpp), hard projections applied after every integration; containment follows them
// (boundary.hpp). kernels/forces.cl, integrate.cl and constraints.cl are their twins.
#pragma once

#include <cstdint>
#include <limits>

#include "animpak/reference/boundary.hpp"
#include "animpak/reference/overlap.hpp"
#include "animpak/solver/grids.hpp"
#include "animpak/solver/step.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

/// What a step reads besides the forces for one vertex (growth, §5.3, and the statistics).
struct ContactGap {
  /// For a boundary vertex, the distance to the nearest other element or container wall (the slice gap
  /// of §5.3 counts the wall as a neighbour), 0 when it overlaps; +inf for interior vertices.
  float closest = std::numeric_limits<float>::infinity();
  std::uint8_t contact = 0;  ///< ContactBit flags
};

/// Vertex v's ContactGap from the step's queries: the overlap test, the nearest other element's
/// distance (`nearest`, RepulsionResult::closest) and the container query. contact.cpp; kernels/contact.cl.
ContactGap contact_gap(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                       const OverlapResult& overlap, float nearest, const ContainerQuery& wall);

/// Eq. 7 for every vertex from one snapshot of positions; with `out`, every force apart too. forces.cpp.
StepForces step_forces(const Topology& topo, const SimState& state, const ForceParams& params,
                       const CollisionGrid& grid, ForceBreakdown* out);

/// Symplectic Euler with the velocity cap (§5). integrate.cpp.
void integrate(const ForceField& force, const ForceParams& params, SimState& state);

/// End-to-end (§5.2): element e's first slice to t = 0, last slice to t = 1. constraints.cpp.
void apply_end_to_end(const Topology& topo, SimState& state, std::int32_t e);

/// Simultaneity (§5.2): every inner slice of element e snapped to the mean t of its vertices.
/// constraints.cpp.
void apply_simultaneity(const Topology& topo, SimState& state, std::int32_t e);

/// Loop (§5.2): both vertices of every loop pair move to the average of their x, y; t untouched.
/// constraints.cpp.
void apply_loop(const Topology& topo, SimState& state);

}  // namespace animpak::reference
