// §5.3 growth on a real (tiny) world: a slice with a vertex inside another element keeps its g, the
// others grow by exactly growth_rate · Δt_sim up to max_growth, and only the springs with an end on a
// grown slice get new rest lengths.
#include <catch2/catch.hpp>

#include <cstring>

#include "animpak/reference.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"

using namespace animpak;

namespace {

World tiny_world() {
  return make_world(parse_scene(animpak::test::star_scene(2, 5, 6), "tiny.json", "/"));
}

bool same_float(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("grow_slices: a slice with an inside vertex pauses, the others grow by rate · dt, capped") {
  const World w = tiny_world();
  const Topology& topo = w.topology;
  REQUIRE(topo.slice_count() == 10);
  Params params = w.params;
  params.growth_rate = 3.0;  // step 0.15: visible in float at every g used below
  params.max_growth = 2.0;
  const float step = static_cast<float>(params.growth_rate * params.dt);

  SimState state = w.state;
  const std::int32_t blocked = 1, nearly_full = 3, full = 7;
  state.growth[nearly_full] = 1.9f;  // 1.9 + 0.15 passes the cap: clamps to 2
  state.growth[full] = 2.0f;         // already at the cap: does not count as growing
  state.growth[5] = 1.25f;
  std::vector<std::uint8_t> inside(topo.vertex_count(), 0);
  inside[topo.slice_begin[blocked + 1] - 1] = 1;  // the last vertex of slice 1 only

  const SimState before = state;
  std::vector<std::uint8_t> grew;
  const std::int32_t count = reference::grow_slices(topo, inside, params, state, grew);
  REQUIRE(grew.size() == static_cast<std::size_t>(topo.slice_count()));
  CHECK(count == topo.slice_count() - 2);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    if (s == blocked || s == full) {
      CHECK(grew[s] == 0);
      CHECK(same_float(state.growth[s], before.growth[s]));
    } else if (s == nearly_full) {
      CHECK(grew[s] == 1);
      CHECK(state.growth[s] == 2.0f);
    } else {
      CHECK(grew[s] == 1);
      CHECK(same_float(state.growth[s], before.growth[s] + step));
    }
  }

  // Nothing else of the state moves.
  CHECK(state.x == before.x);
  CHECK(state.spring_rest == before.spring_rest);
}

TEST_CASE("update_rest_lengths: exactly the springs touching a grown slice change, to their g references") {
  const World w = tiny_world();
  const Topology& topo = w.topology;
  SimState state = w.state;
  std::vector<std::uint8_t> grew(topo.slice_count(), 0);
  // Two slices of element 0 (their time springs reach slices 0, 2 and 4 unchanged) and the last
  // slice of element 1.
  for (const std::int32_t s : {1, 3, topo.slice_count() - 1}) {
    grew[s] = 1;
    state.growth[s] = 1.5f;
  }
  const std::vector<float> before = state.spring_rest;
  reference::update_rest_lengths(topo, grew, state);

  int touching = 0, wrong = 0, changed_elsewhere = 0, unchanged_touching = 0;
  for (std::int32_t v = 0; v < topo.vertex_count(); ++v)
    for (std::int32_t k = topo.spring_begin[v]; k < topo.spring_begin[v + 1]; ++k) {
      if (grew[topo.slice[v]] || grew[topo.slice[topo.spring_other[k]]]) {
        ++touching;
        wrong += !same_float(state.spring_rest[k], reference_rest_length(topo, state.growth, v, k));
        unchanged_touching += same_float(state.spring_rest[k], before[k]);
      } else {
        changed_elsewhere += !same_float(state.spring_rest[k], before[k]);
      }
    }
  CHECK(touching > 0);
  CHECK(wrong == 0);
  CHECK(unchanged_touching == 0);  // g 1 → 1.5 changes every such length well beyond float rounding
  CHECK(changed_elsewhere == 0);
}
