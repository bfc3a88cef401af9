/* Temporal force, paper Eq. 6 (src/solver/reference/temporal.cpp), a force of AP_LOCAL_FORCES. */

/** k_tmp (rest_t − t) along t. */
void temporal_force(const ForceParams p, const LocalForceInputs in, const int v, float* fx, float* fy, float* ft) {
  *fx = 0.0f;
  *fy = 0.0f;
  *ft = p.k_temporal * (in.rest_t[v] - in.t[v]);
}
