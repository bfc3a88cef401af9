// A fixed tiny world for the rendering tests: three rotating stars in the heart container, 4 slices,
// built in memory from the example art with a fixed seed and no simulation steps, so that every
// picture of it depends only on set-up and drawing.
#pragma once

#include <string>

#include "animpak/animation.hpp"
#include "animpak/scene.hpp"

inline animpak::World tiny_star_world(int slices = 4, double initial_scale = 0.22) {
  using namespace animpak;
  const std::string examples = std::string(ANIMPAK_SOURCE_DIR) + "/examples";
  SceneSpec scene;
  scene.file = "tiny-star-world";
  scene.container.art = examples + "/shapes/heart-container.path";
  scene.seed = 7;
  scene.params.element.slices = slices;
  scene.params.placement.initial_scale = initial_scale;
  LibraryElementSpec star;
  star.name = "star";
  star.art = examples + "/default/star.svg";
  star.animation.preset = AnimationPreset::rotate;
  star.count = 3;
  scene.elements.push_back(star);
  return make_world(scene);
}
