// Numerical integration (paper §5, "Computing total force and numerical integration"): symplectic
// (semi-implicit) Euler with unit mass. The paper calls it explicit Euler, but the order it describes
// is the symplectic one ("we update velocities using forces, and update positions using velocities"):
// velocity first, v ← v + F Δt, then the cap, then position from the NEW velocity, x ← x + v Δt. Updating x with the
// old velocity (forward Euler) gains energy on every spring; the symplectic order does not, and the
// cap then bounds every step's displacement by cap · Δt.
//
// The cap: |v| (3D, over x, y, t) is at most velocity_cap · Δt; a faster vertex keeps its direction
// and is scaled down by cap / |v| (one division, three products). Rounding can leave |v| a few ulps
// above the cap.
#include <cmath>

#include "animpak/reference/step.hpp"

namespace animpak::reference {

void integrate(const ForceField& force, const ForceParams& params, SimState& state) {
  const float dt = params.dt;
  const float cap = params.velocity_cap;  // velocity_cap · Δt
  const std::size_t n = state.x.size();
  for (std::size_t v = 0; v < n; ++v) {
    float vx = state.vx[v] + force.x[v] * dt;
    float vy = state.vy[v] + force.y[v] * dt;
    float vt = state.vt[v] + force.t[v] * dt;
    const float speed = std::sqrt(vx * vx + vy * vy + vt * vt);
    if (speed > cap) {
      const float scale = cap / speed;
      vx = vx * scale;
      vy = vy * scale;
      vt = vt * scale;
    }
    state.vx[v] = vx;
    state.vy[v] = vy;
    state.vt[v] = vt;
    state.x[v] = state.x[v] + vx * dt;
    state.y[v] = state.y[v] + vy * dt;
    state.t[v] = state.t[v] + vt * dt;
  }
}

}  // namespace animpak::reference
