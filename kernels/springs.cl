/* Edge forces, paper Eq. 2 (src/solver/reference/springs.cpp): k_edg · u/|u| · s (|u| − ℓ)², summed
 * over v's own CSR slots in slot order (each spring is stored at both ends). */

/** Eq. 2 summed over vertex v's springs. */
void spring_force(const ForceParams p,
                  int v,
                  __global const int* spring_begin,
                  __global const int* spring_other,
                  __global const uchar* spring_class,
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
