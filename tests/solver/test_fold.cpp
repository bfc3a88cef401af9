// The fold guard (docs/parameters.md, "Folds"): Eq. 2's springs keep a slice triangle's edge lengths, and a
// boundary vertex pressed across the chord of its ear (the triangle it forms with its two neighbours on
// the outline) keeps them too, so nothing in the paper's forces holds the ear open against a neighbour
// that presses on it. The folded ear lies in the dent it leaves, outside the element's outline, and takes
// the art bound in it (§3.1) there. fold_force holds it open.
#include <catch2/catch.hpp>

#include "animpak/reference.hpp"
#include "animpak/scene.hpp"
#include "animpak/simulation.hpp"
#include "scene/tiny_scenes.hpp"
#include "solver/folded_triangles.hpp"

using namespace animpak;
using animpak::test::folded_triangles;

namespace {

// The ears of slice s: outline positions k (local) whose triangle is (k - 1, k, k + 1) in some order.
std::vector<std::int32_t> ears(const Topology& topo, std::int32_t s) {
  const std::int32_t lo = topo.slice_begin[s], n = topo.slice_boundary[s];
  std::vector<std::int32_t> out;
  for (std::int32_t k = 0; k < n; ++k) {
    const std::int32_t v = lo + k, prev = lo + (k + n - 1) % n, next = lo + (k + 1) % n;
    for (std::int32_t j = topo.tri_begin[v]; j < topo.tri_begin[v + 1]; ++j) {
      const std::int32_t i = topo.tri_list[j];
      const std::int32_t a = topo.tri_a[i], b = topo.tri_b[i], c = topo.tri_c[i];
      const bool has_prev = a == prev || b == prev || c == prev, has_next = a == next || b == next || c == next;
      if (has_prev && has_next) out.push_back(k);
    }
  }
  return out;
}

}  // namespace

TEST_CASE(
    "fold guard: a real butterfly's outline vertices pressed across their ears' chords fold the ears over "
    "without the guard, and stay open with it") {
  const std::string scene = R"({"container": {"art": ")" + test::example_file("shapes/heart-container.path") +
                            R"("}, "elements": [{"name": "butterfly", "art": ")" +
                            test::example_file("clipart/butterfly.svg") +
                            R"(", "count": 1}], "seed": 1, "slices": 3, "params": {"growth_rate": 0}})";
  const World w = make_world(parse_scene(scene, "fold.json", "/"));
  REQUIRE(folded_triangles(w.topology, w.state) == 0);
  // A neighbour pressing on the ears' tips: a target spring (Eq. 2, rest length 0) on each ear's tip,
  // pulling it to its mirror image across the chord, on every slice.
  Topology topo = w.topology;
  const std::vector<std::int32_t> tips = ears(topo, 0);
  REQUIRE(tips.size() >= 4);
  for (std::int32_t s = 0; s < topo.slice_count(); ++s) {
    const std::int32_t lo = topo.slice_begin[s], n = topo.slice_boundary[s];
    for (std::size_t e = 0; e < tips.size(); e += 2) {  // every second ear: their chords do not share a tip
      const std::int32_t k = tips[e];
      const std::int32_t v = lo + k, p = lo + (k + n - 1) % n, q = lo + (k + 1) % n;
      const float dx = w.state.x[q] - w.state.x[p], dy = w.state.y[q] - w.state.y[p];
      const float u = ((w.state.x[v] - w.state.x[p]) * dx + (w.state.y[v] - w.state.y[p]) * dy) / (dx * dx + dy * dy);
      const float fx = w.state.x[p] + u * dx, fy = w.state.y[p] + u * dy;
      topo.target[v] = static_cast<std::int32_t>(topo.target_x.size());
      topo.flags[v] |= vertex_anchor;
      topo.target_x.push_back(fx + (fx - w.state.x[v]));
      topo.target_y.push_back(fy + (fy - w.state.y[v]));
      topo.target_t.push_back(w.state.t[v]);
    }
  }
  for (const double k_fold : {0.0, w.params.forces.k_fold}) {
    Params params = w.params;
    params.forces.k_fold = k_fold;
    auto backend = make_reference_backend(topo, w.state, params);
    for (int i = 0; i < 400; ++i) backend->step();
    const int folded = folded_triangles(topo, backend->state());
    INFO("k_fold " << k_fold << ": " << folded << " folded triangles after 400 steps, " << tips.size()
                   << " ears per slice");
    if (k_fold == 0.0)
      CHECK(folded > 0);
    else
      CHECK(folded == 0);
  }
}
