// Synthetic benchmark worlds: many copies of one element in a square, as close as a uniform
// blue-noise placement allows, so that the repulsion grid has real neighbours at every size.
#include <algorithm>
#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/synthetic.hpp"
#include "animpak/error.hpp"
#include "placement.hpp"

namespace animpak {
namespace {

// A 500-unit square (the authors' artboard size); normalization maps it onto the unit square.
ArtShape square_art() {
  ArtPath path;
  path.id = "square";
  path.polylines.push_back({{{0, 0}, {500, 0}, {500, 500}, {0, 500}}, true});
  path.fill = {true, {0.9, 0.9, 0.9, 1}};
  ArtShape art;
  art.source = "synthetic-square";
  art.paths.push_back(path);
  return art;
}

}  // namespace

SyntheticWorld make_synthetic_world(const SyntheticSpec& spec) {
  SceneSpec scene;
  scene.file = "synthetic-" + std::to_string(spec.target_vertices);
  scene.container.art = "synthetic-square";
  scene.seed = spec.seed;
  scene.params.slices = spec.slices;

  LibraryElementSpec element;
  element.name = spec.element_art.stem().string();
  element.art = spec.element_art;
  element.animation.preset = AnimationPreset::rotate;
  std::vector<SpacetimeElement> library;
  library.push_back(build_element(element.name, load_art(spec.element_art, {scene.params.flatten_tolerance}),
                                  element.animation, scene.params, element_seed(scene.seed, 0)));
  const SpacetimeElement& e = library.front();

  const int count = std::max(1, static_cast<int>(std::lround(double(spec.target_vertices) / e.vertex_count())));
  element.count = count;
  scene.elements.push_back(element);

  double scale = spec.element_scale;
  const Container container = make_container(square_art(), scene.container);
  for (int attempt = 0;; ++attempt) {
    scene.params.initial_scale = scale;
    try {
      return {build_world(scene, container, library), count, scale};
    } catch (const InputError&) {
      // Blue-noise seeds land a little unevenly; a slightly smaller start always fits eventually.
      if (attempt == 20) throw;
      scale *= 0.9;
    }
  }
}

}  // namespace animpak
