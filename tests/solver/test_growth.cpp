// §5.3 growth on a real (tiny) world (docs/parameters.md, "Growth"): a slice that spills, or overlaps
// an element no larger than itself, shrinks; one that overlaps only larger elements, or is at the wall,
// keeps its g; the others grow by exactly growth_rate · Δt_sim up to max_growth
// and never past growth_ratio × their element's smallest slice; only the springs with an end on a
// changed slice get new rest lengths.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <limits>

#include "animpak/reference.hpp"
#include "animpak/scene.hpp"
#include "scene/tiny_scenes.hpp"
#include "tiny_worlds.hpp"

using namespace animpak;

namespace {

World growth_world() { return make_world(parse_scene(animpak::test::star_scene(2, 5, 6), "tiny.json", "/")); }

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE(
    "growth: spilling slices and the larger of overlapping ones shrink, the smaller and slices at the wall pause, the "
    "others grow, capped") {
  const World w = growth_world();
  const Topology& topo = w.topology;
  REQUIRE(topo.slice_count() == 10);
  Params params = w.params;
  params.growth.growth_rate = 3.0;  // step 0.15: visible in float at every g used below
  params.growth.shrink_rate = 2.0;  // 0.1
  params.growth.max_growth = 2.0;
  params.growth.growth_ratio = 100.0;  // no ratio limits in this case
  params.growth.neighbour_growth_ratio = 100.0;
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  const float shrink = static_cast<float>(params.growth.shrink_rate * params.forces.dt);

  SimState state = w.state;
  const std::int32_t overlapping = 1, smaller = 2, nearly_full = 3, outside = 4, at_wall = 6, full = 7, at_floor = 8;
  state.growth[overlapping] = 1.5f;
  state.growth[smaller] = 1.5f;      // overlaps a larger element: pauses
  state.growth[nearly_full] = 1.9f;  // 1.9 + 0.15 passes the cap: clamps to 2
  state.growth[outside] = 1.5f;
  state.growth[at_wall] = 1.5f;
  state.growth[full] = 2.0f;       // already at the cap: does not count as growing
  state.growth[at_floor] = 1.05f;  // overlapping: shrinks to 1, never below the start
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  contact[topo.slice_begin[overlapping + 1] - 1] =
      contact_overlap | contact_block | contact_yield;  // the last vertex only
  contact[topo.slice_begin[smaller]] = contact_overlap | contact_block;
  contact[topo.slice_begin[outside]] = contact_outside;
  contact[topo.slice_begin[at_wall] + 1] = contact_wall;
  contact[topo.slice_begin[at_floor]] = contact_overlap | contact_block | contact_inside | contact_yield;

  const SimState before = state;
  std::vector<std::uint8_t> changed;
  const std::int32_t count = test::grow_step(topo, contact, params, true, state, changed);
  REQUIRE(changed.size() == static_cast<std::size_t>(topo.slice_count()));
  CHECK(count == topo.slice_count() - 6);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    if (s == overlapping || s == outside) {
      CHECK(changed[s] == growth_shrank);
      CHECK(same_bits(state.growth[s], before.growth[s] - shrink));
    } else if (s == at_floor) {
      CHECK(changed[s] == growth_shrank);
      CHECK(state.growth[s] == 1.0f);
    } else if (s == at_wall || s == full || s == smaller) {
      CHECK(changed[s] == growth_kept);
      CHECK(same_bits(state.growth[s], before.growth[s]));
    } else if (s == nearly_full) {
      CHECK(changed[s] == growth_grew);
      CHECK(state.growth[s] == 2.0f);
    } else {
      CHECK(changed[s] == growth_grew);
      CHECK(same_bits(state.growth[s], before.growth[s] + step));
    }
  }

  // Nothing else of the state moves.
  CHECK(state.x == before.x);
  CHECK(state.spring_rest == before.spring_rest);
}

TEST_CASE(
    "growth: while settling, nothing grows and every overlapping slice shrinks at settle_shrink_rate, the smaller side "
    "too") {
  const World w = growth_world();
  const Topology& topo = w.topology;
  Params params = w.params;
  params.growth.growth_ratio = 100.0;
  params.growth.neighbour_growth_ratio = 100.0;
  params.growth.shrink_rate = 0.01;
  params.growth.settle_shrink_rate = 0.04;
  SimState state = w.state;
  std::fill(state.growth.begin(), state.growth.end(), 1.5f);
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  contact[topo.slice_begin[2]] = contact_overlap | contact_block | contact_yield;
  contact[topo.slice_begin[5]] = contact_outside;
  // Overlaps a larger element: growing, it would pause and leave the shrinking to the other side, but
  // that side may not see the overlap (its slice times differ a little), so settling shrinks it too.
  contact[topo.slice_begin[7]] = contact_overlap | contact_block;
  contact[topo.slice_begin[8]] = contact_wall;  // at the wall: holds
  const SimState start = state;
  std::vector<std::uint8_t> changed;
  CHECK(test::grow_step(topo, contact, params, false, state, changed) == 0);
  const float settle = static_cast<float>(params.growth.settle_shrink_rate * params.forces.dt);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    CHECK(same_bits(state.growth[s], s == 2 || s == 5 || s == 7 ? 1.5f - settle : 1.5f));
  }
  // Growing, the smaller side of an overlap pauses and the wall holds; the rest grows.
  state = start;
  test::grow_step(topo, contact, params, true, state, changed);
  const float shrink = static_cast<float>(params.growth.shrink_rate * params.forces.dt);
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    const float expected = s == 2 || s == 5 ? 1.5f - shrink : s == 7 || s == 8 ? 1.5f : 1.5f + step;
    CHECK(same_bits(state.growth[s], expected));
  }
}

TEST_CASE("growth: a secondary element keeps its size until secondary_since, and a primary slice ignores it") {
  World w = growth_world();
  Topology& topo = w.topology;
  REQUIRE(topo.element_count() == 2);
  topo.element_secondary = {0, 1};  // slices 5..9 are the secondary element's
  Params params = w.params;
  params.growth.growth_ratio = 100.0;
  params.growth.neighbour_growth_ratio = 100.0;
  SimState state = w.state;
  std::fill(state.growth.begin(), state.growth.end(), 1.5f);
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  // Slice 1 overlaps the secondary element only (the overlap test gives no contact_block): it grows.
  contact[topo.slice_begin[1]] = contact_overlap | contact_inside;
  // Slice 6 of the secondary element overlaps a primary one: it gives way, held or not.
  contact[topo.slice_begin[6]] = contact_overlap | contact_block | contact_yield;
  const SimState start = state;
  std::vector<std::uint8_t> changed;
  test::grow_step(topo, contact, params, true, state, changed);
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  const float shrink = static_cast<float>(params.growth.shrink_rate * params.forces.dt);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    const float expected = s < 5 ? 1.5f + step : s == 6 ? 1.5f - shrink : 1.5f;
    CHECK(same_bits(state.growth[s], expected));
  }
  // Once the secondary elements may grow, they do.
  state = start;
  state.secondary_since = 40;
  test::grow_step(topo, contact, params, true, state, changed);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    CHECK(same_bits(state.growth[s], s == 6 ? 1.5f - shrink : 1.5f + step));
  }
  // Settling, the primary slice that overlaps only a secondary element does not shrink.
  state = start;
  test::grow_step(topo, contact, params, false, state, changed);
  CHECK(same_bits(state.growth[1], 1.5f));
  CHECK(state.growth[6] < 1.5f);
}

TEST_CASE("growth: no slice outgrows growth_ratio × the smallest slice of its element") {
  const World w = growth_world();
  const Topology& topo = w.topology;
  REQUIRE(topo.element_count() == 2);
  Params params = w.params;
  params.growth.growth_rate = 1.0;  // 0.05 per step
  params.growth.growth_ratio = 1.3;
  params.growth.neighbour_growth_ratio = 100.0;  // the element-wide limit alone; the next case has this one
  SimState state = w.state;
  // Element 0's slice 2 sits at the wall for good; its other slices may grow up to 1.3 × its g.
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  contact[topo.slice_begin[2]] = contact_wall;
  std::vector<std::uint8_t> changed;
  for (int step = 0; step < 40; ++step) test::grow_step(topo, contact, params, true, state, changed);
  for (std::int32_t s = topo.element_slice_begin[0]; s < topo.element_slice_begin[1]; ++s) {
    INFO("slice " << s);
    CHECK(state.growth[s] <= 1.3f * state.growth[2]);
  }
  CHECK(state.growth[2] == 1.0f);
  CHECK(state.growth[0] == 1.3f);
  CHECK((changed[0] & growth_held) != 0);  // it would grow: the limit holds it
  CHECK(changed[2] == growth_kept);        // the wall holds this one, not the limit
  // Element 1 is free and grows evenly: 40 steps of 0.05.
  for (std::int32_t s = topo.element_slice_begin[1]; s < topo.element_slice_begin[2]; ++s)
    CHECK(state.growth[s] == Approx(3.0).epsilon(1e-5));

  // One slice overlapping drags the element's largest slices down with it: the bound holds every step.
  contact.assign(topo.vertex_count(), 0);
  contact[topo.slice_begin[topo.element_slice_begin[1]]] = contact_overlap | contact_block;
  for (int step = 0; step < 10; ++step) {
    test::grow_step(topo, contact, params, true, state, changed);
    float lo = 1e9f, hi = 0.0f;
    for (std::int32_t s = topo.element_slice_begin[1]; s < topo.element_slice_begin[2]; ++s)
      lo = std::min(lo, state.growth[s]), hi = std::max(hi, state.growth[s]);
    CHECK(hi <= 1.3f * lo);
  }
}

TEST_CASE("update_rest_lengths: exactly the springs touching a grown slice change, to their g references") {
  const World w = growth_world();
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
        wrong += !same_bits(state.spring_rest[k], rest_copy_length(topo, state.growth, v, k));
        unchanged_touching += same_bits(state.spring_rest[k], before[k]);
      } else {
        changed_elsewhere += !same_bits(state.spring_rest[k], before[k]);
      }
    }
  CHECK(touching > 0);
  CHECK(wrong == 0);
  CHECK(unchanged_touching == 0);  // g 1 → 1.5 changes every such length well beyond float rounding
  CHECK(changed_elsewhere == 0);
}

TEST_CASE("growth: no slice outgrows either time neighbour by more than neighbour_growth_ratio") {
  const World w = growth_world();
  const Topology& topo = w.topology;
  Params params = w.params;
  params.growth.neighbour_growth_ratio = 1.03;
  params.growth.growth_ratio = 100.0;
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  SimState state = w.state;
  // Element 0's slice 2 (of 0..4) sits at the wall for good: its neighbours stop at 1.03, theirs at
  // about 1.03², so the size falls off smoothly towards the slice that is held.
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  contact[topo.slice_begin[2]] = contact_wall;
  std::vector<std::uint8_t> changed;
  for (int k = 0; k < 2000; ++k) test::grow_step(topo, contact, params, true, state, changed);
  CHECK(state.growth[2] == 1.0f);
  CHECK(state.growth[1] == Approx(1.03f).epsilon(1e-6));
  CHECK(state.growth[3] == Approx(1.03f).epsilon(1e-6));
  // The limit is taken against the neighbour's proposal, so it holds to within one growth step.
  for (std::int32_t s = 0; s + 1 < 5; ++s) {
    INFO("slices " << s << ", " << s + 1);
    CHECK(state.growth[s] <= 1.03f * (state.growth[s + 1] + step));
    CHECK(state.growth[s + 1] <= 1.03f * (state.growth[s] + step));
  }
  CHECK(state.growth[0] > 1.05f);
  // Element 1 is free: its slices grew alike, 2000 steps of growth_rate · dt.
  CHECK(state.growth[5] == Approx(1.0 + 2000 * step).epsilon(1e-3));
}

TEST_CASE(
    "growth: a free slice grows growth_rate × its gap / boost_gap, at least once and at most growth_boost times") {
  // The multiplier alone: 1 up to boost_gap, then in proportion to the gap, then capped by growth_boost
  // and by the outline's speed limit, never below 1.
  const float inf = std::numeric_limits<float>::infinity();
  CHECK(reference::growth_multiplier(0.0f, 0.02f, 4.0f, inf) == 1.0f);
  CHECK(reference::growth_multiplier(0.01f, 0.02f, 4.0f, inf) == 1.0f);
  CHECK(reference::growth_multiplier(0.02f, 0.02f, 4.0f, inf) == 1.0f);
  CHECK(reference::growth_multiplier(0.05f, 0.02f, 4.0f, inf) == 0.05f / 0.02f);
  CHECK(reference::growth_multiplier(0.5f, 0.02f, 4.0f, inf) == 4.0f);
  CHECK(reference::growth_multiplier(std::numeric_limits<float>::infinity(), 0.02f, 4.0f, inf) == 4.0f);
  CHECK(reference::growth_multiplier(0.5f, 0.02f, 1.0f, inf) == 1.0f);  // growth_boost 1: the paper's one rate
  CHECK(reference::growth_multiplier(0.5f, 0.02f, 4.0f, 2.5f) == 2.5f);
  CHECK(reference::growth_multiplier(0.05f, 0.02f, 4.0f, 3.0f) == 0.05f / 0.02f);
  CHECK(reference::growth_multiplier(0.5f, 0.02f, 4.0f, 0.3f) == 1.0f);  // never below the paper's rate

  // In a growth step: each slice takes the least gap of its vertices; a slice that touches (contact)
  // does not grow whatever its gap; growth_boost 1 gives every free slice growth_rate exactly.
  const World w = growth_world();
  const Topology& topo = w.topology;
  Params params = w.params;
  params.growth.growth_ratio = 100.0;
  params.growth.neighbour_growth_ratio = 100.0;
  params.growth.growth_boost = 4.0;
  params.growth.boost_gap = 0.02;
  params.growth.boost_speed = 1.0;
  params.forces.velocity_cap = 1e6;  // the outline's speed limit out of the way here; it has its own case
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  SimState state = w.state;
  std::fill(state.growth.begin(), state.growth.end(), 1.5f);
  std::vector<float> closest(topo.vertex_count(), 1.0f);  // far from everything: 4×
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  const std::int32_t near = 1, middle = 3, touching = 6;
  closest[topo.slice_begin[near] + 1] = 0.01f;  // one vertex near something: the slice grows at 1×
  closest[topo.slice_begin[middle]] = 0.05f;    // 2.5×
  closest[topo.slice_begin[middle] + 2] = 0.06f;
  contact[topo.slice_begin[touching]] = contact_wall;
  const SimState start = state;
  std::vector<std::uint8_t> changed;
  test::grow_step(topo, contact, closest, params, true, state, changed);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    const float expected = s == near       ? 1.5f + step
                           : s == middle   ? 1.5f + step * (0.05f / 0.02f)
                           : s == touching ? 1.5f
                                           : 1.5f + step * 4.0f;
    CHECK(same_bits(state.growth[s], expected));
  }
  state = start;
  params.growth.growth_boost = 1.0;
  test::grow_step(topo, contact, closest, params, true, state, changed);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    INFO("slice " << s);
    CHECK(same_bits(state.growth[s], s == touching ? 1.5f : 1.5f + step));
  }
}

TEST_CASE("growth: a slice the limits only slow from the room's boost is not held, one they stop is") {
  // The stop test counts a held slice as touching: with the boost, a free slice whose time neighbour
  // grows at the paper's rate is limited below its 4x proposal, but it still grows a full step, so it
  // must not count as touching (two discs in a circle stopped by the gap test with the wall gap at 2.8
  // times half the channel when it did).
  const World w = growth_world();
  const Topology& topo = w.topology;
  Params params = w.params;
  params.growth.growth_boost = 4.0;
  params.growth.boost_gap = 0.01;
  params.forces.velocity_cap = 1e6;  // the outline's speed limit out of the way
  params.growth.growth_ratio = 100.0;
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  // A neighbour limit that lets a slice beside one growing at the paper's rate grow about three steps.
  params.growth.neighbour_growth_ratio = 1.0 + 2.0 * step / 1.5;
  const auto r = static_cast<float>(params.growth.neighbour_growth_ratio);
  SimState state = w.state;
  std::fill(state.growth.begin(), state.growth.end(), 1.5f);
  state.growth[5] = state.growth[7] = r * 1.5f;           // already at the limit of their neighbour at the wall
  std::vector<float> closest(topo.vertex_count(), 1.0f);  // free: 4x
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  closest[topo.slice_begin[1]] = 0.005f;        // slice 1 near something: 1x, and it bounds slices 0 and 2
  contact[topo.slice_begin[6]] = contact_wall;  // slice 6 at the wall: 0, and it bounds slices 5 and 7
  std::vector<std::uint8_t> changed;
  test::grow_step(topo, contact, closest, params, true, state, changed);
  CHECK(same_bits(state.growth[1], 1.5f + step));
  for (const std::int32_t s : {0, 2}) {  // limited below 4 steps, but more than one: not held
    INFO("slice " << s);
    CHECK(same_bits(state.growth[s], r * (1.5f + step)));
    CHECK(state.growth[s] > 1.5f + 2.0f * step);
    CHECK((changed[s] & growth_held) == 0);
  }
  for (const std::int32_t s : {5, 7}) {  // no room at all: held
    INFO("slice " << s);
    CHECK(same_bits(state.growth[s], r * 1.5f));
    CHECK((changed[s] & growth_held) != 0);
  }
  CHECK((changed[6] & growth_held) == 0);  // the wall holds it, not a limit
  CHECK(same_bits(state.growth[3], 1.5f + 4.0f * step));
}

TEST_CASE("growth: the room's boost moves no outline faster than boost_speed × the velocity cap") {
  // A slice's outline moves outwards by its largest rest-copy radius per unit of g; with the boost, the
  // discs of a two-element scene outgrew their meshes (the springs could not follow at the velocity cap)
  // and stopped at g 7.6 with 0.20 of art radius against 0.23 at g 6.6 without.
  const World w = growth_world();
  const Topology& topo = w.topology;
  Params params = w.params;
  params.growth.growth_ratio = 100.0;
  params.growth.neighbour_growth_ratio = 100.0;
  params.growth.growth_boost = 4.0;
  params.growth.boost_gap = 0.01;
  params.growth.boost_speed = 0.5;
  const float step = static_cast<float>(params.growth.growth_rate * params.forces.dt);
  const float largest = step_params(params).boost_step;
  CHECK(largest == static_cast<float>(0.5 * params.forces.velocity_cap * params.forces.dt * params.forces.dt));
  std::vector<float> closest(topo.vertex_count(), 1.0f);  // far from everything
  std::vector<std::uint8_t> contact(topo.vertex_count(), 0);
  for (const double cap : {1e6, 0.035, 1e-9}) {
    INFO("velocity_cap " << cap);
    params.forces.velocity_cap = cap;
    const float limit_step = step_params(params).boost_step;
    SimState state = w.state;
    std::fill(state.growth.begin(), state.growth.end(), 1.5f);
    std::vector<std::uint8_t> changed;
    test::grow_step(topo, contact, closest, params, true, state, changed);
    for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
      INFO("slice " << s);
      float radius2 = 0.0f;
      for (std::int32_t v = topo.slice_begin[s]; v < topo.slice_begin[s + 1]; ++v) {
        const float dx = topo.rest_copy_x[v] - topo.slice_rest_copy_cx[s],
                    dy = topo.rest_copy_y[v] - topo.slice_rest_copy_cy[s];
        radius2 = std::max(radius2, dx * dx + dy * dy);
      }
      const float radius = std::sqrt(radius2);
      REQUIRE(radius > 0.0f);
      const float grown = state.growth[s] - 1.5f;
      if (cap == 1e6) {
        CHECK(same_bits(state.growth[s], 1.5f + 4.0f * step));  // the limit far above the boost
      } else if (cap == 1e-9) {
        CHECK(same_bits(state.growth[s], 1.5f + step));  // the limit below 1: the paper's rate still
      } else {
        const float m = limit_step / (radius * step);
        REQUIRE(m > 1.0f);
        REQUIRE(m < 4.0f);  // this cap binds in this world
        CHECK(same_bits(state.growth[s], 1.5f + step * m));
        CHECK(grown * radius <= limit_step * 1.0001f);  // the outline's step within the limit
      }
    }
  }
}
