/* Temporal force, paper Eq. 6 (src/solver/reference/temporal.cpp). */

/** k_tmp (rest_t − t) along t. */
float temporal_force(const ForceParams p, float rest_t, float pt) { return p.k_temporal * (rest_t - pt); }
