/* Symplectic Euler with the velocity cap (src/solver/reference/integrate.cpp): v ← v + F Δt, cap |v|
 * at velocity_cap · Δt keeping its direction, then x ← x + v Δt. */

/** One Euler step of vertex i. */
__kernel void integrate(const WorldInfo world,
                        const ForceParams p,
                        __global const float* fx,
                        __global const float* fy,
                        __global const float* ft, /* input: Eq. 7 */
                        __global float* vx,
                        __global float* vy,
                        __global float* vt, /* input/output: velocities */
                        __global float* x,
                        __global float* y,
                        __global float* t) { /* input/output: positions */
  const int i = get_global_id(0);
  if (i >= world.vertices) return;
  const float dt = p.dt, cap = p.velocity_cap;
  float ux = vx[i] + fx[i] * dt;
  float uy = vy[i] + fy[i] * dt;
  float ut = vt[i] + ft[i] * dt;
  const float speed = sqrt(ux * ux + uy * uy + ut * ut);
  if (speed > cap) {
    const float scale = cap / speed;
    ux = ux * scale;
    uy = uy * scale;
    ut = ut * scale;
  }
  vx[i] = ux;
  vy[i] = uy;
  vt[i] = ut;
  x[i] = x[i] + ux * dt;
  y[i] = y[i] + uy * dt;
  t[i] = t[i] + ut * dt;
}
