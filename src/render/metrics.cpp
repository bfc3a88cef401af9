// Frame metrics of a World: every element's art replayed exactly as the frames draw it, and the container
// where it is at that time, handed to measure_regions (src/render/quality.cpp) as plain regions.
#include "animpak/render.hpp"

namespace animpak {
namespace {

// How far a stroke band's round joins and caps may lie inside true circles, in container units: far
// below the 0.2 % shares docs/quality.md counts, even for thin strokes.
constexpr double stroke_tolerance = 1e-5;

}  // namespace

Region art_region(const ArtShape& art, const ArtPoints& points, double stroke_scale) {
  Region region;
  for (std::size_t p = 0; p < art.paths.size() && p < points.size(); ++p) {
    const ArtPath& path = art.paths[p];
    std::vector<std::vector<Vec2>> rings =
        painted_region(path, points[p], path.stroke_width * stroke_scale, stroke_tolerance);
    region.rings.insert(region.rings.end(), std::make_move_iterator(rings.begin()),
                        std::make_move_iterator(rings.end()));
  }
  return region;
}

Region container_region(const Container& container, double t) {
  Region region;
  region.rule = FillRule::evenodd;
  region.rings.push_back(container.shown_outline());
  region.rings.insert(region.rings.end(), container.shown_holes().begin(), container.shown_holes().end());
  // A container that moves is measured where it is at t (docs/quality.md, "A container that moves"): its
  // shape at rest carried by the motion, as the solver's containment test carries it. One that does not
  // move keeps its rings as they are, bit for bit.
  if (container.motion.moves()) {
    const Similarity m = container.motion.at(t);
    for (std::vector<Vec2>& ring : region.rings)
      for (Vec2& p : ring) p = m.apply(p);
  }
  return region;
}

FrameMetrics measure_frame(const World& world, const std::vector<ElementArt>& art, double tf, Measures what) {
  std::vector<Region> elements;
  elements.reserve(art.size());
  for (std::size_t i = 0; i < art.size(); ++i)
    elements.push_back(art_region(world.library[world.elements[drawn_source(world, int(i))].library].art.art,
                                  art[i].points, art[i].stroke_scale));
  FrameMetrics m = measure_regions(elements, container_region(world.container, tf), what);
  m.t = tf;
  return m;
}

FrameMetrics measure_frame(const World& world, const SimState& state, double tf, Measures what) {
  return measure_frame(world, frame_art(world, state, tf), tf, what);
}

std::vector<double> between_slice_times(int slices) {
  std::vector<double> t;
  for (int s = 0; s + 1 < slices; ++s)
    for (int q = 1; q <= between_slice_points; ++q)
      t.push_back((s + static_cast<double>(q) / (between_slice_points + 1)) / (slices - 1));
  return t;
}

}  // namespace animpak
