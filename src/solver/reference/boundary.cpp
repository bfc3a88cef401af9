// Boundary force, paper Eq. 4: F_bdr = k_bdr (p_b − x) for a vertex outside the container, p_b the
// closest point on the container's boundary; the wall's repulsion on a boundary vertex inside; and the
// containment projection that backs them up (docs/parameters.md, "Containment"). The test and the
// force are in x, y only: at the vertex's own t, the container is the one at rest (the segments) moved
// by its motion at t (docs/scene-format.md, "A container that moves"), so a point is taken back to the
// container at rest, tested there, and its nearest point brought forward again. Holes count: the
// even–odd rule over the segments of all rings puts a vertex inside a hole outside the container, and
// p_b is searched on every ring.
#include <algorithm>
#include <cmath>

#include "animpak/reference/boundary.hpp"
#include "animpak/reference/segments.hpp"

namespace animpak::reference {

ContainerQuery container_query(const ContainerGeometry& box, float px, float py, bool nearest) {
  ContainerQuery q;
  const std::size_t segments = box.ax.size();
  if (segments == 0) return q;
  const ContainerIndex& ix = box.index;
  bool inside = false;
  if (ix.nx > 0) {
    // Only segments whose y range holds py can cross the ray; the band lists them in index order.
    const std::int32_t j = grid_axis_cell(py - ix.y0, ix.cell, ix.ny);
    for (std::int32_t k = ix.data[j]; k < ix.data[j + 1]; ++k) {
      const std::int32_t i = ix.data[ix.band_segments + k];
      if (ray_crosses_segment(px, py, box.ax[i], box.ay[i], box.bx[i], box.by[i])) inside = !inside;
    }
  } else {
    for (std::size_t i = 0; i < segments; ++i)
      if (ray_crosses_segment(px, py, box.ax[i], box.ay[i], box.bx[i], box.by[i])) inside = !inside;
  }
  q.inside = inside;
  q.qx = px;
  q.qy = py;
  if (inside && !nearest) return q;

  // Closest point; the first segment (by index) reaching the minimum wins. Inside the index's grid, the
  // cell's list holds every segment that can be nearest there, in index order; elsewhere every segment.
  const auto try_segment = [&](std::int32_t i) {
    float cx, cy;
    const float d2 = closest_point_on_segment(px, py, box.ax[i], box.ay[i], box.bx[i], box.by[i], cx, cy);
    if (d2 < q.distance2) {
      q.distance2 = d2;
      q.qx = cx;
      q.qy = cy;
    }
  };
  const float fx = std::floor((px - ix.x0) / ix.cell), fy = std::floor((py - ix.y0) / ix.cell);
  if (ix.nx > 0 && fx >= 0.0f && fy >= 0.0f && fx < static_cast<float>(ix.nx) && fy < static_cast<float>(ix.ny)) {
    const std::int32_t c = static_cast<std::int32_t>(fy) * ix.nx + static_cast<std::int32_t>(fx);
    for (std::int32_t k = ix.data[ix.cell_start + c]; k < ix.data[ix.cell_start + c + 1]; ++k)
      try_segment(ix.data[ix.cell_segments + k]);
  } else {
    for (std::size_t i = 0; i < segments; ++i) try_segment(static_cast<std::int32_t>(i));
  }
  return q;
}

ContainerFrame container_frame(const ContainerGeometry& box, float t) {
  const std::int32_t intervals = static_cast<std::int32_t>(box.motion_a.size()) - 1;
  const float u = t * static_cast<float>(intervals);
  float f = std::floor(u);
  if (!(f >= 0.0f)) f = 0.0f;
  const float last = static_cast<float>(intervals - 1);
  if (f > last) f = last;
  const std::int32_t i = static_cast<std::int32_t>(f);
  float w = u - f;
  if (!(w >= 0.0f)) w = 0.0f;
  if (w > 1.0f) w = 1.0f;
  const auto lerp = [&](const std::vector<float>& v) { return v[i] + (v[i + 1] - v[i]) * w; };
  return {lerp(box.motion_a), lerp(box.motion_b), lerp(box.motion_ex), lerp(box.motion_ey)};
}

void ContainerFrame::to_rest(float wx, float wy, float& px, float& py) const {
  const float s2 = a * a + b * b, dx = wx - ex, dy = wy - ey;
  px = (a * dx + b * dy) / s2;
  py = (a * dy - b * dx) / s2;
}

void ContainerFrame::from_rest(float px, float py, float& wx, float& wy) const {
  wx = a * px - b * py + ex;
  wy = b * px + a * py + ey;
}

ContainerQuery container_query(const ContainerGeometry& box, float px, float py, float pt, bool nearest) {
  if (!box.moves()) return container_query(box, px, py, nearest);
  const ContainerFrame m = container_frame(box, pt);
  float lx, ly;
  m.to_rest(px, py, lx, ly);
  ContainerQuery q = container_query(box, lx, ly, nearest);
  if (!(q.distance2 < std::numeric_limits<float>::infinity())) {
    q.qx = px;  // no nearest point was sought: the point itself, as at rest
    q.qy = py;
    return q;
  }
  m.from_rest(q.qx, q.qy, q.qx, q.qy);
  const float ux = q.qx - px, uy = q.qy - py;
  q.distance2 = ux * ux + uy * uy;
  return q;
}

bool edge_crosses_container(const ContainerGeometry& box, float px, float py, float nx, float ny, float pt) {
  if (!box.moves()) return edge_crosses_container(box, px, py, nx, ny);
  const ContainerFrame m = container_frame(box, pt);
  float lx, ly, mx, my;
  m.to_rest(px, py, lx, ly);
  m.to_rest(nx, ny, mx, my);
  return edge_crosses_container(box, lx, ly, mx, my);
}

bool edge_crosses_container(const ContainerGeometry& box, float px, float py, float nx, float ny) {
  const std::size_t segments = box.ax.size();
  const ContainerIndex& ix = box.index;
  if (ix.nx > 0) {
    // A segment crossing the edge meets it at a y inside the edge's y range, so it is listed in that
    // y's band: the bands from the lower end's to the upper end's hold every candidate.
    const std::int32_t j0 = grid_axis_cell(std::min(py, ny) - ix.y0, ix.cell, ix.ny);
    const std::int32_t j1 = grid_axis_cell(std::max(py, ny) - ix.y0, ix.cell, ix.ny);
    for (std::int32_t j = j0; j <= j1; ++j)
      for (std::int32_t k = ix.data[j]; k < ix.data[j + 1]; ++k) {
        const std::int32_t i = ix.data[ix.band_segments + k];
        if (segments_cross_properly(px, py, nx, ny, box.ax[i], box.ay[i], box.bx[i], box.by[i])) return true;
      }
    return false;
  }
  for (std::size_t i = 0; i < segments; ++i)
    if (segments_cross_properly(px, py, nx, ny, box.ax[i], box.ay[i], box.bx[i], box.by[i])) return true;
  return false;
}

Vec3f boundary_force(const ForceParams& params, const ContainerQuery& q, float px, float py, bool boundary) {
  if (!q.inside) {
    const float k = params.k_boundary;
    return {k * (q.qx - px), k * (q.qy - py), 0.0f};
  }
  // Inside, a boundary vertex is pushed off the wall as by a neighbour's closest point (Eq. 1), so an
  // element pressed to the wall, which stops growing there, moves back into open space. Only within
  // wall_range, as a neighbour's triangles repel only within the repulsion shell: a wall felt from
  // across the container presses every element towards the middle (docs/parameters.md, "Containment").
  if (!boundary || !(q.distance2 > 0.0f) || !(q.distance2 < params.wall_range2)) return {};
  const float ux = px - q.qx, uy = py - q.qy;
  const float inv_len = 1.0f / std::sqrt(q.distance2);
  const float w = inv_len * (1.0f / (params.repulsion_epsilon + q.distance2));
  const float k = params.k_wall;
  return {k * (ux * w), k * (uy * w), 0.0f};
}

Vec3f boundary_force(const Topology& topo, const SimState& state, const ForceParams& params, std::int32_t v) {
  const float px = state.x[v], py = state.y[v];
  const bool boundary = (topo.flags[v] & vertex_boundary) != 0;
  return boundary_force(params, container_query(topo.container, px, py, state.t[v], boundary), px, py, boundary);
}

void apply_containment(const Topology& topo, SimState& state) {
  const std::int32_t n = topo.vertex_count();
  for (std::int32_t v = 0; v < n; ++v) {
    const float px = state.x[v], py = state.y[v];
    const ContainerQuery q = container_query(topo.container, px, py, state.t[v], false);
    if (q.inside) continue;
    // Past p_b along the direction from x to p_b, so rounding cannot leave the vertex on the outside;
    // a vertex exactly on the boundary has no such direction and stays.
    const float dx = q.qx - px, dy = q.qy - py;
    const float d2 = dx * dx + dy * dy;
    if (!(d2 > 0.0f)) continue;
    const float w = containment_margin / std::sqrt(d2);
    state.x[v] = q.qx + dx * w;
    state.y[v] = q.qy + dy * w;
    state.vx[v] = 0.0f;
    state.vy[v] = 0.0f;
  }
}

}  // namespace animpak::reference
