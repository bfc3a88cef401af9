/* Symplectic Euler with the velocity cap (src/solver/reference/integrate.cpp): v ← v + F Δt, cap |v|
 * at velocity_cap · Δt keeping its direction, then x ← x + v Δt. */

/** One Euler step of vertex i. */
__kernel void integrate(const WorldInfo world,
                        const ForceParams p,
                        __global const float* forces, /* input: Eq. 7, x, y, t */
                        __global float* velocities,   /* input/output: x, y, t */
                        __global float* positions) {  /* input/output: x, y, t */
  __global const float* fx = forces + AP_X * world.vertex_stride;
  __global const float* fy = forces + AP_Y * world.vertex_stride;
  __global const float* ft = forces + AP_T * world.vertex_stride;
  __global float* vx = velocities + AP_X * world.vertex_stride;
  __global float* vy = velocities + AP_Y * world.vertex_stride;
  __global float* vt = velocities + AP_T * world.vertex_stride;
  __global float* x = positions + AP_X * world.vertex_stride;
  __global float* y = positions + AP_Y * world.vertex_stride;
  __global float* t = positions + AP_T * world.vertex_stride;
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
