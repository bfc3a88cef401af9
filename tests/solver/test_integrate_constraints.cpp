// Symplectic Euler with the velocity cap, and the hard slice constraints of §5.2.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "tiny_worlds.hpp"

using namespace animpak;
using namespace animpak::reference;
using animpak::test::WorldBuilder;

namespace {

ForceField field(std::vector<Vec3f> forces) {
  ForceField f;
  f.assign(forces.size());
  for (std::size_t v = 0; v < forces.size(); ++v) f.set(static_cast<std::int32_t>(v), forces[v]);
  return f;
}

test::TinyWorld loose_points(int n) {
  WorldBuilder b;
  test::Ring ring;
  for (int i = 0; i < n; ++i) ring.push_back({0.5f, 0.5f});
  b.add_element({{ring, 0.5f}}, false);
  return b.build();
}

}  // namespace

TEST_CASE("integrate: velocity first, then position from the new velocity") {
  Params p = test::paper_params();
  p.forces.dt = 0.5;           // exact in float, so the expected values are exact
  p.forces.velocity_cap = 10;  // cap 5: not reached
  test::TinyWorld w = loose_points(1);
  w.state.vx[0] = 0.25f;
  integrate(field({{1.0f, -0.5f, 0.25f}}), step_params(p), w.state);
  CHECK(w.state.vx[0] == 0.75f);
  CHECK(w.state.vy[0] == -0.25f);
  CHECK(w.state.vt[0] == 0.125f);
  CHECK(w.state.x[0] == 0.5f + 0.375f);
  CHECK(w.state.y[0] == 0.5f - 0.125f);
  CHECK(w.state.t[0] == 0.5f + 0.0625f);
}

TEST_CASE("integrate: the cap bounds the 3D speed and keeps the direction") {
  const Params p = test::paper_params();
  const float cap = static_cast<float>(p.forces.velocity_cap * p.forces.dt);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> force(-1000.0f, 1000.0f);
  test::TinyWorld w = loose_points(200);
  std::vector<Vec3f> forces;
  for (int v = 0; v < 200; ++v) forces.push_back({force(rng), force(rng), v % 10 == 0 ? 0.0f : force(rng)});
  forces[0] = {1e-3f, 0.0f, 0.0f};  // slow: untouched by the cap
  const test::TinyWorld before = w;
  integrate(field(forces), step_params(p), w.state);
  for (int v = 0; v < 200; ++v) {
    INFO(v);
    const double speed = std::sqrt(double(w.state.vx[v]) * w.state.vx[v] + double(w.state.vy[v]) * w.state.vy[v] +
                                   double(w.state.vt[v]) * w.state.vt[v]);
    CHECK(speed <= cap * (1.0 + 1e-6));
    const Vec3f f = forces[v];
    const double fl = std::sqrt(double(f.x) * f.x + double(f.y) * f.y + double(f.t) * f.t);
    CHECK((w.state.vx[v] * f.x + w.state.vy[v] * f.y + w.state.vt[v] * f.t) / (speed * fl) == Approx(1.0).margin(1e-6));
    const double moved = std::hypot(w.state.x[v] - before.state.x[v], w.state.y[v] - before.state.y[v],
                                    w.state.t[v] - before.state.t[v]);
    CHECK(moved <= cap * p.forces.dt * (1.0 + 1e-4));
  }
  CHECK(w.state.vx[0] == 1e-3f * 0.01f);
}

TEST_CASE("constraints: end-to-end and simultaneity hold after application, per element") {
  WorldBuilder b;
  b.add_element(test::square_tube(0.3f, 0.3f, 0.05f, {0.0f, 0.3f, 0.7f, 1.0f}));
  b.add_element(test::square_tube(0.7f, 0.7f, 0.05f, {0.0f, 0.5f, 1.0f}));
  test::TinyWorld w = b.build();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
  for (float& t : w.state.t) t += jitter(rng);
  const test::TinyWorld jittered = w;

  apply_end_to_end(w.topo, w.state, 0);
  apply_simultaneity(w.topo, w.state, 0);
  for (std::int32_t s = 0; s < 4; ++s) {
    const std::int32_t lo = w.topo.slice_begin[s], hi = w.topo.slice_begin[s + 1];
    double mean = 0.0;
    for (std::int32_t v = lo; v < hi; ++v) mean += jittered.state.t[v];
    mean /= hi - lo;
    for (std::int32_t v = lo; v < hi; ++v) {
      INFO("slice " << s << " vertex " << v);
      if (s == 0) CHECK(w.state.t[v] == 0.0f);
      if (s == 3) CHECK(w.state.t[v] == 1.0f);
      if (s == 1 || s == 2) {
        CHECK(w.state.t[v] == w.state.t[lo]);
        CHECK(w.state.t[v] == Approx(mean).margin(1e-6));
      }
      CHECK(w.state.x[v] == jittered.state.x[v]);
      CHECK(w.state.y[v] == jittered.state.y[v]);
    }
  }
  // Element 1 was not touched.
  for (std::int32_t v = w.topo.slice_begin[4]; v < w.topo.vertex_count(); ++v)
    CHECK(w.state.t[v] == jittered.state.t[v]);
  apply_end_to_end(w.topo, w.state, 1);
  apply_simultaneity(w.topo, w.state, 1);
  for (std::int32_t v = w.topo.slice_begin[4]; v < w.topo.slice_begin[5]; ++v) CHECK(w.state.t[v] == 0.0f);
  for (std::int32_t v = w.topo.slice_begin[5] + 1; v < w.topo.slice_begin[6]; ++v)
    CHECK(w.state.t[v] == w.state.t[w.topo.slice_begin[5]]);
  for (std::int32_t v = w.topo.slice_begin[6]; v < w.topo.slice_begin[7]; ++v) CHECK(w.state.t[v] == 1.0f);
}

TEST_CASE("constraints: loop pairs move both ends to their average x, y and keep t") {
  WorldBuilder b;
  b.add_element(test::square_tube(0.25f, 0.25f, 0.125f, {0.0f, 0.5f, 1.0f}));
  b.add_element(test::square_tube(0.75f, 0.5f, 0.125f, {0.0f, 0.5f, 1.0f}));
  // Element 0's last slice (vertices 8..11) arrives at element 1's first (12..15); 1's last (20..23)
  // arrives at 0's first (0..3): the two-element permutation of Fig. 9d.
  for (std::int32_t k = 0; k < 4; ++k) {
    b.add_loop(8 + k, 12 + k);
    b.add_loop(20 + k, 0 + k);
  }
  test::TinyWorld w = b.build();
  const test::TinyWorld before = w;
  apply_loop(w.topo, w.state);
  for (std::size_t i = 0; i < w.topo.loop_end.size(); ++i) {
    const std::int32_t a = w.topo.loop_end[i], c = w.topo.loop_start[i];
    CHECK(w.state.x[a] == w.state.x[c]);
    CHECK(w.state.y[a] == w.state.y[c]);
    CHECK(w.state.x[a] == Approx((before.state.x[a] + before.state.x[c]) / 2.0).margin(1e-7));
    CHECK(w.state.y[a] == Approx((before.state.y[a] + before.state.y[c]) / 2.0).margin(1e-7));
    CHECK(w.state.t[a] == before.state.t[a]);
    CHECK(w.state.t[c] == before.state.t[c]);
  }
  CHECK(w.state.x[8] == 0.375f);  // vertex 8 at (0.125, 0.125), vertex 12 at (0.625, 0.375)
  CHECK(w.state.y[8] == 0.25f);
  CHECK(w.state.x[4] == before.state.x[4]);  // an inner slice is not part of the loop
}
