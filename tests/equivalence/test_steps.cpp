// Whole-step equivalence: the OpenCL backend against the reference backend, step after step, on
// random worlds and on a small real scene (the default example's star in the heart container). Every
// array of the state must match bit for bit, and so must the statistics of the stop test.
#include "animpak/curve.hpp"
#include "animpak/levels.hpp"
#include "animpak/scene.hpp"
#include "equivalence_support.hpp"
#include "scene/tiny_scenes.hpp"

namespace animpak::test {
namespace {

std::string statistics_difference(const StepStatistics& a, const StepStatistics& b) {
  std::ostringstream s;
  if (a.iteration != b.iteration) s << "iteration " << a.iteration << " vs " << b.iteration << "\n";
  s << bit_difference("max_slice_gap", std::vector<float>{a.max_slice_gap}, std::vector<float>{b.max_slice_gap})
    << bit_difference("min_slice_gap", std::vector<float>{a.min_slice_gap}, std::vector<float>{b.min_slice_gap})
    << bit_difference("growth range", std::vector<float>{a.min_growth, a.max_growth},
                      std::vector<float>{b.min_growth, b.max_growth});
  if (a.growing_share != b.growing_share) s << "growing_share " << a.growing_share << " vs " << b.growing_share << "\n";
  if (a.overlapping_vertices != b.overlapping_vertices)
    s << "overlapping_vertices " << a.overlapping_vertices << " vs " << b.overlapping_vertices << "\n";
  if (a.outside_vertices != b.outside_vertices)
    s << "outside_vertices " << a.outside_vertices << " vs " << b.outside_vertices << "\n";
  if (a.finite != b.finite || a.first_bad_vertex != b.first_bad_vertex) s << "finiteness differs\n";
  return s.str();
}

// Runs `steps` steps on both backends, comparing the state every `compare_every` steps and the
// statistics at the end; stops at the first step that differs so the message points at it.
// With `settle_at` > 0 both stop growing (the settling phase) after that step; with `secondary_at` > 0
// both let their secondary elements grow after that step.
void check_steps(const Topology& topo, const SimState& initial, const Params& params, int steps, int compare_every,
                 const std::string& label, int settle_at = 0, int secondary_at = 0) {
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (const DeviceChoice& d : devices)
    for (const GridSort sort : grid_sorts) {
      auto ref = make_reference_backend(topo, initial, params);
      auto dev = make_opencl_backend(topo, initial, params, d, sort);
      const std::string where = label + " on " + d.device.name + " (grid sorted on the " + grid_sort_name(sort) + ")";
      CHECK(statistics_difference(ref->statistics(), dev->statistics()).empty());
      for (int step = 1; step <= steps; ++step) {
        if (step == settle_at + 1 && settle_at > 0) ref->stop_growth(), dev->stop_growth();
        if (step == secondary_at + 1 && secondary_at > 0) {
          REQUIRE(ref->start_secondary_growth());
          REQUIRE(dev->start_secondary_growth());
        }
        ref->step();
        dev->step();
        if (step % compare_every != 0 && step != steps) continue;
        const std::string diff = state_difference(ref->state(), dev->state());
        INFO(where << ", after step " << step << "\n" << diff);
        REQUIRE(diff.empty());
      }
      const std::string stats = statistics_difference(ref->statistics(), dev->statistics());
      INFO(where << ": statistics\n" << stats);
      CHECK(stats.empty());
    }
}

}  // namespace

TEST_CASE("steps: random worlds, 20 steps each", "[equivalence][opencl]") {
  for (std::uint64_t seed = 11; seed <= 14; seed += seed_stride()) {
    RandomWorldShape shape;
    shape.elements = 4;
    shape.max_radius = 0.15f;
    const TinyWorld w = random_world(seed, shape);
    Params params = paper_params();
    params.forces.grid_rebuild_interval = static_cast<int>(seed % 3) + 1;  // rebuilding every k steps, alike
    check_steps(w.topo, w.state, params, 20, 1, "seed " + std::to_string(seed));
  }
}

TEST_CASE("steps: a random world with the wall as the elements' mirror image, 15 steps", "[equivalence][opencl]") {
  for (const std::uint64_t seed : {15}) {
    RandomWorldShape shape;
    shape.elements = 5;
    shape.max_radius = 0.15f;
    const TinyWorld w = random_world(seed, shape);
    Params params = paper_params();
    params.forces.wall_mirror = 1.0;
    params.forces.wall_repulsion = 0.0;
    check_steps(w.topo, w.state, params, 15, 1, "mirror, seed " + std::to_string(seed));
  }
}

TEST_CASE("steps: many small elements, the overlap broadphase leaving most out", "[equivalence][opencl]") {
  RandomWorldShape shape;
  shape.elements = 50;
  shape.min_radius = 0.02f;
  shape.max_radius = 0.06f;
  const TinyWorld w = random_world(31, shape);
  check_steps(w.topo, w.state, paper_params(), 10, 1, "50 small elements");
}

TEST_CASE("steps: 100 steps of a small real scene give identical states", "[equivalence][opencl]") {
  const std::string text = R"({
    "container": {"art": "../shapes/heart-container.path"},
    "elements": [{"name": "star", "art": "star.svg", "count": 4, "animation": {"preset": "rotate", "turns": 1}}],
    "seed": 3, "loop": true, "slices": 6
  })";
  const std::filesystem::path dir = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "default";
  const animpak::World world = make_world(parse_scene(text, dir / "scene.json", dir));
  REQUIRE(world.elements.size() == 4);
  check_steps(world.topology, world.state, world.params, 100, 10, "star scene");
  check_steps(world.topology, world.state, world.params, 60, 10, "star scene, settling from step 30", 30);
}

TEST_CASE(
    "steps: a small real scene with two guided stars that swap places (one spline chain over both), on the "
    "spline and on the monotone cubic",
    "[equivalence][opencl]") {
  const std::string text = R"({
    "container": {"art": "../shapes/heart-container.path"},
    "elements": [{"name": "star", "art": "star.svg", "count": 2, "animation": {"preset": "pulse", "amplitude": 0.1}}],
    "guided": [
      {"name": "up", "element": "star", "loop_to": "down",
       "targets": [{"x": 250, "y": 330, "t": 0}, {"x": 330, "y": 250, "t": 0.5}, {"x": 250, "y": 170, "t": 1}]},
      {"name": "down", "element": "star", "loop_to": "up",
       "targets": [{"x": 250, "y": 170, "t": 0}, {"x": 170, "y": 250, "t": 0.5}, {"x": 250, "y": 330, "t": 1}]}
    ],
    "seed": 5, "loop": true, "slices": 7
  })";
  const std::filesystem::path dir = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "default";
  animpak::World world = make_world(parse_scene(text, dir / "scene.json", dir));
  REQUIRE(world.elements.size() == 4);
  // Not vacuous: the two guided stars share one closed chain of two loops, in the chains link_curves filled
  // where the world was built (the ones both backends step with).
  const CurveChains& chains = world.topology.chains;
  bool shared = false;
  for (std::size_t c = 0; c + 1 < chains.begin.size(); ++c) shared = shared || chains.period[c] == 2.0f;
  CHECK(shared);
  check_steps(world.topology, world.state, world.params, 40, 10, "guided swap, spline");
  world.params.forces.motion_curve = curve_monotone;
  check_steps(world.topology, world.state, world.params, 20, 10, "guided swap, monotone cubic");
}

TEST_CASE("steps: a small real scene with secondary elements, held, then growing, gives identical states",
          "[equivalence][opencl]") {
  const std::string text = R"({
    "container": {"art": "../shapes/heart-container.path"},
    "elements": [{"name": "star", "art": "star.svg", "count": 3, "animation": {"preset": "rotate", "turns": 1}},
                 {"name": "small", "art": "star.svg", "count": 2, "secondary": true}],
    "seed": 3, "loop": true, "slices": 6, "params": {"growth_rate": 0.2}
  })";
  const std::filesystem::path dir = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "default";
  const animpak::World world = make_world(parse_scene(text, dir / "scene.json", dir));
  REQUIRE(world.topology.has_secondary());
  check_steps(world.topology, world.state, world.params, 60, 10, "secondary stars, growing from step 30", 0, 30);
  // Not vacuous: the reference holds the secondary stars at g 1 for 30 steps while the others grow,
  // then grows them too.
  auto ref = make_reference_backend(world.topology, world.state, world.params);
  const auto growth_of = [&](const SimState& s, bool secondary) {
    float most = 0.0f;
    for (std::int32_t k = 0; k < world.topology.slice_count(); ++k)
      if (world.topology.secondary(world.topology.slice_element[k]) == secondary) most = std::max(most, s.growth[k]);
    return most;
  };
  for (int step = 0; step < 30; ++step) ref->step();
  const SimState held = ref->state();
  CHECK(growth_of(held, true) == 1.0f);
  CHECK(growth_of(held, false) > 1.0f);
  REQUIRE(ref->start_secondary_growth());
  for (int step = 0; step < 30; ++step) ref->step();
  CHECK(growth_of(ref->state(), true) > 1.0f);
  CHECK(ref->state().secondary_since == 30);
}

}  // namespace animpak::test

namespace animpak::test {

TEST_CASE("steps: one element alone, and a world without envelope triangles", "[equivalence][opencl]") {
  WorldBuilder alone;
  alone.add_element(square_tube(0.5f, 0.5f, 0.1f, {0.0f, 0.3f, 0.6f, 1.0f}));
  TinyWorld w = alone.build();
  fill_reference_copy(w);
  check_steps(w.topo, w.state, paper_params(), 10, 1, "alone");

  WorldBuilder flat;  // one slice per element: nothing to extrude an envelope from
  flat.add_element(square_tube(0.3f, 0.3f, 0.1f, {0.5f}));
  flat.add_element(square_tube(0.35f, 0.3f, 0.1f, {0.5f}));
  TinyWorld f = flat.build();
  fill_reference_copy(f);
  REQUIRE(f.topo.envelope_count() == 0);
  check_steps(f.topo, f.state, paper_params(), 10, 1, "no envelope");
}

}  // namespace animpak::test

namespace animpak::test {

TEST_CASE("steps: a small real scene across a refinement from the coarse level to the scene's slices stays identical",
          "[equivalence][opencl]") {
  // Coarse to fine (docs/parameters.md, "Coarse to fine"): 30 steps at the coarse level's 4 slices, the fine
  // state made from each backend's own coarse state by the one host routine, then 30 steps at 13 slices.
  const std::string text = star_scene(3, 13, 4, swapping_pair(R"("cell_size": 0.5, "coarse_step": 4)"));
  SceneSpec scene = parse_scene(text, "levels.json", "/");
  const World fine = make_world(scene);
  scene.params.element.slices = coarse_slices(scene.params);
  REQUIRE(scene.params.element.slices == 4);
  const World coarse = make_world(scene);
  const std::vector<DeviceChoice> devices = devices_under_test();
  if (skip_without_devices(devices)) return;
  for (const DeviceChoice& d : devices)
    for (const GridSort sort : grid_sorts) {
      INFO(d.device.name << " (grid sorted on the " << grid_sort_name(sort) << ")");
      auto ref = make_reference_backend(coarse.topology, coarse.state, coarse.params);
      auto dev = make_opencl_backend(coarse.topology, coarse.state, coarse.params, d, sort);
      for (int step = 0; step < 30; ++step) ref->step(), dev->step();
      const SimState ref_coarse = ref->state(), dev_coarse = dev->state();
      INFO(state_difference(ref_coarse, dev_coarse));
      REQUIRE(state_difference(ref_coarse, dev_coarse).empty());
      const SimState ref_fine = refine_state(coarse, ref_coarse, fine),
                     dev_fine = refine_state(coarse, dev_coarse, fine);
      REQUIRE(state_difference(ref_fine, dev_fine).empty());
      ref = make_reference_backend(fine.topology, ref_fine, fine.params);
      dev = make_opencl_backend(fine.topology, dev_fine, fine.params, d, sort);
      for (int step = 1; step <= 30; ++step) {
        ref->step(), dev->step();
        if (step % 10 != 0) continue;
        const std::string diff = state_difference(ref->state(), dev->state());
        INFO("fine level, after step " << step << "\n" << diff);
        REQUIRE(diff.empty());
      }
      // Not vacuous: the fine level moved on from the refined state.
      CHECK(ref->state().iteration == 60);
      CHECK(state_difference(ref_fine, ref->state()) != "");
    }
}

TEST_CASE(
    "steps: a small real scene in a container that travels, turns and scales, with a guided star and a "
    "star pushed half outside, gives identical states",
    "[equivalence][opencl]") {
  const std::string text = R"({
    "container": {"art": "../shapes/heart-container.path", "animation": {"keys": [
      {"t": 0}, {"t": 0.4, "translate": [60, -30], "rotate": 40, "scale": 1.15}, {"t": 1}]}},
    "elements": [{"name": "star", "art": "star.svg", "count": 3, "animation": {"preset": "pulse", "amplitude": 0.1}}],
    "guided": [{"name": "runner", "element": "star",
                "targets": [{"x": 200, "y": 250, "t": 0}, {"x": 300, "y": 260, "t": 0.5}, {"x": 200, "y": 250, "t": 1}]}],
    "seed": 4, "loop": true, "slices": 6, "params": {"initial_scale": 0.15}
  })";
  const std::filesystem::path dir = std::filesystem::path(ANIMPAK_SOURCE_DIR) / "examples" / "default";
  animpak::World world = make_world(parse_scene(text, dir / "scene.json", dir));
  REQUIRE(world.container.motion.moves());
  REQUIRE(world.topology.container.moves());
  // One star pushed well right, so that the boundary force, the containment and the wall's mirror image
  // all act against the moved container at each slice's own time.
  const ElementInstance& pushed = world.elements.back();
  const int end = pushed.vertex_begin + world.library[pushed.library].vertex_count();
  int outside = 0;
  for (int v = pushed.vertex_begin; v < end; ++v) {
    world.state.x[v] += 0.3f;
    const Vec2 p = world.container.motion.at(world.state.t[v]).inverse({world.state.x[v], world.state.y[v]});
    outside += world.container.contains(p) ? 0 : 1;
  }
  REQUIRE(outside > 0);
  check_steps(world.topology, world.state, world.params, 60, 10, "moving container");
}

}  // namespace animpak::test
