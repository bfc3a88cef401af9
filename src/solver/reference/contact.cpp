// What a step reads besides the forces (kernels/contact.cl): each vertex's gap to its nearest
// neighbour, the wall counted as one (§5.3's slice gap: a lone element stops at the container), and its
// contact bits, which growth (§5.3) and the statistics read.
#include <cmath>

#include "animpak/reference/step.hpp"

namespace animpak::reference {

ContactGap contact_gap(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v,
                       const OverlapResult& overlap, float nearest, const ContainerQuery& wall) {
  ContactGap r;
  const bool boundary = (topo.flags[v] & vertex_boundary) != 0;
  std::uint8_t contact = wall.inside ? 0 : contact_outside;
  if (boundary) {
    const float px = state.x[v], py = state.y[v];
    float wall_gap = wall.inside ? std::sqrt(wall.distance2) : 0.0f;
    // With the mirror image, the wall's neighbour is that image, twice as far away.
    if (params.k_mirror != 0.0f) wall_gap = wall_gap + wall_gap;
    // Both ends inside, the boundary edge to the next vertex may still leave the container around a
    // reflex corner. Only when the wall is nearer than the edge is long can it cross (the crossing point
    // is on the wall): that edge counts as outside, and its vertex touches.
    if (wall.inside) {
      const std::int32_t s = topo.slice[v];
      const std::int32_t lo = topo.slice_begin[s];
      const std::int32_t next = v - lo + 1 == topo.slice_boundary[s] ? lo : v + 1;
      const float ex = state.x[next] - px, ey = state.y[next] - py;
      if (wall.distance2 < ex * ex + ey * ey &&
          edge_crosses_container(topo.container, px, py, state.x[next], state.y[next], state.t[v])) {
        contact = contact_outside;
        wall_gap = 0.0f;
      }
    }
    // A vertex that overlaps touches, whatever the nearest triangle's distance (a point of a slice
    // interval may overlap where v itself is clear).
    r.closest = overlap.overlap ? 0.0f : (wall_gap < nearest ? wall_gap : nearest);
    if (wall_gap < params.stop_gap) contact |= contact_wall;
  }
  if (overlap.overlap) contact |= contact_overlap;
  if (overlap.inside) contact |= contact_inside;
  if (overlap.yield) contact |= contact_yield;
  if (overlap.block) contact |= contact_block;
  r.contact = contact;
  return r;
}

}  // namespace animpak::reference
