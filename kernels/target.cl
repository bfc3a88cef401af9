/* Target-point spring of a guided element's anchor, Eq. 2 with ℓ = 0 (src/solver/reference/target.cpp). */

/** k_target · u/|u| · |u|² towards target point `target` (the caller checks the anchor flag). */
void target_force(const ForceParams p,
                  int target,
                  float px,
                  float py,
                  float pt,
                  __global const float* target_x,
                  __global const float* target_y,
                  __global const float* target_t,
                  float* fx,
                  float* fy,
                  float* ft) {
  const float ux = target_x[target] - px, uy = target_y[target] - py, ut = target_t[target] - pt;
  const float d2 = ux * ux + uy * uy + ut * ut;
  if (!(d2 > 0.0f)) return;
  const float len = sqrt(d2);
  const float inv_len = 1.0f / len;
  const float w = p.k_target * inv_len * (len * len);
  *fx = ux * w;
  *fy = uy * w;
  *ft = ut * w;
}
