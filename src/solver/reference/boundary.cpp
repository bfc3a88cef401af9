// Boundary force, paper Eq. 4: F_bdr = k_bdr (p_b − x) for a vertex outside the container, p_b the
// closest point on the container's boundary. The container is the same in every t, so the test and
// the force are in x, y only. Holes count: the even–odd rule over the segments of all rings puts a
// vertex inside a hole outside the container, and p_b is searched on every ring (the authors'
// hole branch pulled towards the outer ring only, notes §3.12.7).
#include <limits>

#include "animpak/reference.hpp"

namespace animpak::reference {

bool ray_crosses_segment(float px, float py, float ax, float ay, float bx, float by) {
  // Half-open in y (one end above, one not) so a ray through a shared vertex counts once.
  if ((ay > py) == (by > py)) return false;
  const float xi = (bx - ax) * (py - ay) / (by - ay) + ax;
  return px < xi;
}

Vec3f boundary_force(const Topology& topo, const SimState& state, const Params& params, std::int32_t v) {
  const ContainerGeometry& box = topo.container;
  const std::size_t segments = box.ax.size();
  const float px = state.x[v], py = state.y[v];
  bool inside = false;
  for (std::size_t i = 0; i < segments; ++i)
    if (ray_crosses_segment(px, py, box.ax[i], box.ay[i], box.bx[i], box.by[i])) inside = !inside;
  if (inside || segments == 0) return {};

  // Closest point over all segments; the first segment reaching the minimum wins.
  float best2 = std::numeric_limits<float>::infinity();
  float qx = px, qy = py;
  for (std::size_t i = 0; i < segments; ++i) {
    const float dx = box.bx[i] - box.ax[i], dy = box.by[i] - box.ay[i];
    const float len2 = dx * dx + dy * dy;
    float s = 0.0f;
    if (len2 > 0.0f) s = ((px - box.ax[i]) * dx + (py - box.ay[i]) * dy) / len2;
    if (s < 0.0f) s = 0.0f;
    if (s > 1.0f) s = 1.0f;
    const float cx = box.ax[i] + dx * s, cy = box.ay[i] + dy * s;
    const float ex = px - cx, ey = py - cy;
    const float d2 = ex * ex + ey * ey;
    if (d2 < best2) {
      best2 = d2;
      qx = cx;
      qy = cy;
    }
  }
  const float k = static_cast<float>(params.k_boundary);
  return {k * (qx - px), k * (qy - py), 0.0f};
}

}  // namespace animpak::reference
