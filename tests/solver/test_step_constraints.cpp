// §5.2's constraints are hard: after every full reference step on a real (tiny) world, whatever the
// forces did, the first slice of every element is at t = 0, the last at t = 1, inner slices are flat
// in t and loop pairs coincide in x, y — exactly, not approximately.
#include <catch2/catch.hpp>

#include "animpak/scene.hpp"
#include "animpak/simulation.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

TEST_CASE("reference step: end-to-end, simultaneity and loop constraints hold exactly after every step") {
  // A fast growth rate makes the elements press on each other within 20 steps, so forces actually
  // pull the slices out of shape before the constraints project them back.
  const World w = make_world(parse_scene(
      animpak::test::star_scene(2, 5, 4, animpak::test::swapping_pair(R"("growth_rate": 4)")), "tiny.json", "/"));
  const Topology& topo = w.topology;
  REQUIRE(w.elements.size() == 4);
  REQUIRE_FALSE(topo.loop_end.empty());
  auto backend = make_reference_backend(topo, w.state, w.params);
  bool moved_in_t = false;
  for (int step = 1; step <= 20; ++step) {
    backend->step();
    const SimState s = backend->state();
    INFO("step " << step);
    REQUIRE(s.iteration == static_cast<std::uint64_t>(step));
    int bad_ends = 0, bad_flat = 0, bad_loop = 0;
    for (std::int32_t e = 0; e < topo.element_count(); ++e) {
      const std::int32_t first = topo.element_slice_begin[e], last = topo.element_slice_begin[e + 1] - 1;
      for (std::int32_t v = topo.slice_begin[first]; v < topo.slice_begin[first + 1]; ++v) bad_ends += s.t[v] != 0.0f;
      for (std::int32_t v = topo.slice_begin[last]; v < topo.slice_begin[last + 1]; ++v) bad_ends += s.t[v] != 1.0f;
      for (std::int32_t slice = first + 1; slice < last; ++slice) {
        const float t0 = s.t[topo.slice_begin[slice]];
        for (std::int32_t v = topo.slice_begin[slice]; v < topo.slice_begin[slice + 1]; ++v) bad_flat += s.t[v] != t0;
        moved_in_t = moved_in_t || t0 != topo.rest_t[topo.slice_begin[slice]];
      }
    }
    for (std::size_t i = 0; i < topo.loop_end.size(); ++i) {
      const std::int32_t a = topo.loop_end[i], b = topo.loop_start[i];
      bad_loop += s.x[a] != s.x[b] || s.y[a] != s.y[b];
    }
    CHECK(bad_ends == 0);
    CHECK(bad_flat == 0);
    CHECK(bad_loop == 0);
  }
  // Otherwise the flatness check would be vacuous: the temporal and time-spring forces did move slices.
  CHECK(moved_in_t);
}
