// The reference's forces that read only a vertex's own mesh (src/solver/reference/springs.cpp,
// target.cpp, torsion.cpp, temporal.cpp; kernels/springs.cl, target.cl, torsion.cl and temporal.cl are
// their twins):
//   Eq. 2, F_edg = k_edg · u/|u| · s (|u| − ℓ)², u = x_b − x_a, s = sign(|u| − ℓ), over v's springs, with the
//          target-point spring of a guided element's anchor (ℓ = 0) and the fold guard (docs/parameters.md,
//          "Folds") beside it;
//   Eq. 5, F_tor = −sign(θ) k_tor u⊥ about the slice's current centroid;
//   Eq. 6, F_tmp = k_tmp (t_rest − t) along t.
// Each returns the force on vertex v only, from one snapshot of positions.
#pragma once

#include <cstdint>
#include <vector>

#include "animpak/spring_class.hpp"
#include "animpak/state.hpp"
#include "animpak/step_params.hpp"

namespace animpak::reference {

/// Stiffness of one spring class (Eq. 2's k_edg per class): params.k_spring[c], 0 for an unknown class (as
/// kernels/springs.cl reads it).
float spring_stiffness(const ForceParams& params, SpringClass c);

/// Eq. 2 summed over v's CSR slots in slot order. springs.cpp.
Vec3f spring_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// The fold guard (docs/parameters.md, "Folds"): for every slice triangle of v whose signed area (oriented
/// as its rest copy's) is below fold_area · g² · its rest copy's, k_fold · the height it misses, along the
/// normal of the edge opposite v; summed in v's incident-triangle order. Zero with k_fold 0. springs.cpp.
Vec3f fold_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// Eq. 2 for the target-point spring of an anchor vertex (rest length 0, class target); zero for
/// vertices without a target. target.cpp.
Vec3f target_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);

/// Current centroid of every slice (mean of its vertices in index order), for Eq. 5. torsion.cpp.
void slice_centroids(const Topology& topo, const SimState& state, std::vector<float>& cx, std::vector<float>& cy);

/// Eq. 5 with the slice centroid (cx, cy) of v's slice, at k_target_angle for a vertex_hold_angle vertex
/// and k_torsion otherwise. torsion.cpp.
Vec3f torsion_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v, float cx,
                    float cy);

/// The force of each row of AP_LOCAL_FORCES (kernels/shared_types.h) on vertex v, in its own file
/// (name.cpp): Eq. 6's temporal_force, k_tmp (rest_t − t) along t, in temporal.cpp.
#define AP_DECLARE_LOCAL_FORCE(name, ...) \
  Vec3f name##_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v);
AP_LOCAL_FORCES(AP_DECLARE_LOCAL_FORCE)
#undef AP_DECLARE_LOCAL_FORCE

}  // namespace animpak::reference
