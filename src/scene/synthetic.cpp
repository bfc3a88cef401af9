// Synthetic benchmark worlds: many copies of one element in a square, as close as a uniform
// blue-noise placement allows, so that the repulsion grid has real neighbours at every size.
#include <algorithm>
#include <cmath>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "animpak/synthetic.hpp"
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
  scene.params.element.slices = spec.slices;
  // The series were calibrated on random blue-noise subsets (their neighbour visits per vertex: docs/benchmark.md).
  scene.params.placement.seed_spread = 0;

  LibraryElementSpec element;
  element.name = spec.element_art.stem().string();
  element.art = spec.element_art;
  element.animation.preset = AnimationPreset::rotate;
  const ArtShape art = load_art(spec.element_art, {scene.params.art.flatten_tolerance});
  std::vector<SpacetimeElement> library;
  library.push_back(build_element(element.name, art, element.animation, scene.params, element_seed(scene.seed, 0)));

  int count = std::max(1, static_cast<int>(std::lround(double(spec.target_vertices) / library.front().vertex_count())));
  double scale = spec.element_scale;
  if (spec.density == SyntheticDensity::constant) {
    // The world of `count` copies is the reference world (constant_density_copies at element_scale,
    // the default cell, spec.slices) in a container √(count / reference) times wider, seen in unit
    // space: every length shrinks by f = √(reference / count), the copies' scale and the grid's cell
    // alike. Cells are cubes, so the slice gap in t shrinks by f too (more slices): a vertex's 5×5×5
    // block of cells then covers the same share of the same neighbourhood at every size.
    const double reference = std::max(1, spec.constant_density_copies);
    auto slices_for = [&](int n) {
      return std::max(2, 1 + static_cast<int>(std::lround((spec.slices - 1) * std::sqrt(n / reference))));
    };
    const int per_slice = library.front().vertices_per_slice();
    auto miss = [&](int n) { return std::abs(double(n) * per_slice * slices_for(n) - spec.target_vertices); };
    // Vertices grow with n·slices_for(n), monotone: the nearest count lies below twice the target.
    count = 1;
    for (int n = 2; double(n) * per_slice * slices_for(n) <= 2.0 * spec.target_vertices; ++n)
      if (miss(n) < miss(count)) count = n;
    const double f = std::sqrt(reference / count);
    scale *= f;
    scene.params.forces.cell_size = std::min(1.0, scene.params.forces.cell_size * f);
    scene.params.element.slices = slices_for(count);
    library.front() = build_element(element.name, art, element.animation, scene.params, element_seed(scene.seed, 0));
  }
  element.count = count;
  scene.elements.push_back(element);

  const Container container = make_container(square_art(), scene.container);
  for (int attempt = 0;; ++attempt) {
    scene.params.placement.initial_scale = scale;
    scene.initial_scale_given = true;  // this loop picks the start itself
    try {
      return {build_world(scene, container, library), count, scale, scene.params.element.slices};
    } catch (const InputError&) {
      // Blue-noise seeds land a little unevenly; a slightly smaller start always fits eventually.
      if (attempt == 20) throw;
      scale *= 0.9;
    }
  }
}

}  // namespace animpak
