/* Edge forces, paper Eq. 2 (src/solver/reference/springs.cpp): k_edg · u/|u| · s (|u| − ℓ)², summed
 * over v's own CSR slots in slot order (each spring is stored at both ends). */

/** Eq. 2 summed over vertex v's springs. */
void spring_force(const ForceParams p,
                  int v,
                  __global const int* spring_begin,
                  __global const int* spring_other,
                  __global const int* spring_class,
                  __global const float* spring_rest,
                  __global const float* x,
                  __global const float* y,
                  __global const float* t,
                  float* fx,
                  float* fy,
                  float* ft) {
  const float xa = x[v], ya = y[v], ta = t[v];
  float sx = 0.0f, sy = 0.0f, st = 0.0f;
  for (int k = spring_begin[v]; k < spring_begin[v + 1]; ++k) {
    const int b = spring_other[k];
    const float ux = x[b] - xa, uy = y[b] - ya, ut = t[b] - ta;
    const float d2 = ux * ux + uy * uy + ut * ut;
    if (!(d2 > 0.0f)) continue;
    const float len = sqrt(d2);
    const float inv_len = 1.0f / len;
    const float stretch = len - spring_rest[k];
    const float s = stretch > 0.0f ? 1.0f : (stretch < 0.0f ? -1.0f : 0.0f);
    const int cls = spring_class[k];
    /* An unknown class has no stiffness, as reference::spring_stiffness answers. */
    const float stiffness = cls < AP_SPRING_CLASSES ? p.k_spring[cls] : 0.0f;
    const float w = stiffness * inv_len * s * (stretch * stretch);
    sx = sx + ux * w;
    sy = sy + uy * w;
    st = st + ut * w;
  }
  *fx = sx;
  *fy = sy;
  *ft = st;
}

/** The fold guard (reference fold_force, docs/parameters.md, "Folds"): every slice triangle of v squeezed
 * below fold_area · g² of its rest copy's signed area pushes v back along its height, k_fold times the
 * height missing; summed in v's incident-triangle order. */
void fold_force(const ForceParams p,
                int v,
                __global const int* slice,
                __global const int* tri_begin,
                __global const int* tri_list,
                __global const int* tri_a,
                __global const int* tri_b,
                __global const int* tri_c,
                __global const float* rest_copy_x,
                __global const float* rest_copy_y,
                __global const float* growth,
                __global const float* x,
                __global const float* y,
                float* fx,
                float* fy) {
  float sx = 0.0f, sy = 0.0f;
  if (p.k_fold > 0.0f) {
    const float g = growth[slice[v]];
    const float g2 = g * g;
    const float vx = x[v], vy = y[v];
    const float rvx = rest_copy_x[v], rvy = rest_copy_y[v];
    for (int k = tri_begin[v]; k < tri_begin[v + 1]; ++k) {
      const int i = tri_list[k];
      const int a = tri_a[i], b = tri_b[i], c = tri_c[i];
      const int pv = v == a ? b : (v == b ? c : a);
      const int qv = v == a ? c : (v == b ? a : b);
      const float rest =
          (rest_copy_x[pv] - rvx) * (rest_copy_y[qv] - rvy) - (rest_copy_y[pv] - rvy) * (rest_copy_x[qv] - rvx);
      const float now = (x[pv] - vx) * (y[qv] - vy) - (y[pv] - vy) * (x[qv] - vx);
      const float s = rest < 0.0f ? -1.0f : 1.0f;
      const float deficit = p.fold_area * (s * rest) * g2 - s * now;
      if (!(deficit > 0.0f)) continue;
      const float gx = s * (y[pv] - y[qv]), gy = s * (x[qv] - x[pv]);
      const float gg = gx * gx + gy * gy;
      if (!(gg > 0.0f)) continue;
      const float w = p.k_fold * deficit / gg;
      sx = sx + gx * w;
      sy = sy + gy * w;
    }
  }
  *fx = sx;
  *fy = sy;
}
