#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"

namespace animpak {
namespace {

std::string where(const ArtShape& art, int index) { return art.source.string() + ": path " + std::to_string(index); }

const ArtPath* find_source(const ArtShape& art, int index) {
  for (const ArtPath& p : art.paths)
    if (p.source_index == index) return &p;
  return nullptr;
}

// The largest closed polyline of a path: a container path is one ring.
std::vector<Vec2> ring_of(const ArtShape& art, const ArtPath& path) {
  const Polyline* best = nullptr;
  for (const Polyline& l : path.polylines)
    if (!best || std::abs(signed_area(l.points)) > std::abs(signed_area(best->points))) best = &l;
  if (!best || best->points.size() < 3 || std::abs(signed_area(best->points)) <= 0.0)
    throw InputError(where(art, path.source_index) + " (" + path.id +
                     "): has no area; a container outline or hole must be a closed shape with at least 3 points");
  return best->points;
}

}  // namespace

bool Container::contains(Vec2 p) const {
  if (!ring_contains(outline, p)) return false;
  return std::none_of(holes.begin(), holes.end(), [&](const auto& h) { return ring_contains(h, p); });
}

double Container::distance_to_boundary(Vec2 p) const {
  double d = ring_distance(outline, p);
  for (const auto& h : holes) d = std::min(d, ring_distance(h, p));
  return d;
}

Box Container::bounds() const {
  Box box;
  for (Vec2 p : outline) box.add(p);
  return box;
}

Box Container::shown_bounds() const {
  Box box;
  for (Vec2 p : shown_outline()) box.add(p);
  return box;
}

double Container::area() const {
  double a = std::abs(signed_area(outline));
  for (const auto& h : holes) a -= std::abs(signed_area(h));
  return a;
}

Container make_container(const ArtShape& art, const ContainerSpec& spec) {
  std::vector<int> hole_indices;
  if (spec.holes) {
    hole_indices = *spec.holes;
  } else {
    for (const ArtPath& p : art.paths)
      if (p.path_type == 7) hole_indices.push_back(p.source_index);
  }
  std::vector<std::vector<Vec2>> hole_rings;
  for (int h : hole_indices) {
    const ArtPath* path = find_source(art, h);
    if (!path) throw InputError(where(art, h) + ": container.holes names a path the file does not have");
    hole_rings.push_back(ring_of(art, *path));
  }

  std::vector<Vec2> outline;
  int outline_path = -1;
  if (spec.outline) {
    const ArtPath* path = find_source(art, *spec.outline);
    if (!path) throw InputError(where(art, *spec.outline) + ": container.outline names a path the file does not have");
    outline = ring_of(art, *path);
    outline_path = *spec.outline;
  } else {
    double best = 0.0;
    for (const ArtPath& p : art.paths) {
      if (std::find(hole_indices.begin(), hole_indices.end(), p.source_index) != hole_indices.end()) continue;
      for (const Polyline& l : p.polylines)
        if (l.closed && l.points.size() >= 3 && std::abs(signed_area(l.points)) > best)
          best = std::abs(signed_area(l.points)), outline = l.points, outline_path = p.source_index;
    }
    if (outline.empty())
      throw InputError(
          art.source.string() +
          ": no closed path to use as the container outline; draw a closed shape or set container.outline");
  }

  Box box;
  for (Vec2 p : outline) box.add(p);
  Container c;
  c.frame.art_origin = box.min;
  c.frame.scale = 1.0 / std::max(box.width(), box.height());
  c.frame.unit_origin = {0.5 * (1.0 - box.width() * c.frame.scale), 0.5 * (1.0 - box.height() * c.frame.scale)};
  for (Vec2 p : outline) c.outline.push_back(c.frame.to_unit(p));
  c.outline_path = outline_path;
  c.hole_paths = hole_indices;
  for (std::size_t i = 0; i < hole_rings.size(); ++i) {
    std::vector<Vec2> ring;
    for (Vec2 p : hole_rings[i]) ring.push_back(c.frame.to_unit(p));
    if (!std::all_of(ring.begin(), ring.end(), [&](Vec2 p) { return ring_contains(c.outline, p); }))
      throw InputError(where(art, hole_indices[i]) + ": the hole is not inside the container outline");
    c.holes.push_back(std::move(ring));
  }
  c.art = art;
  for (ArtPath& path : c.art.paths) {
    for (Polyline& line : path.polylines)
      for (Vec2& p : line.points) p = c.frame.to_unit(p);
    path.stroke_width *= c.frame.scale;
  }
  c.art.viewport.reset();
  return c;
}

void animate_container(Container& container, const SceneSpec& scene) {
  container.inherit_scale = scene.container.inherit_scale;
  const AnimationSpec& spec = scene.container.animation;
  if (spec.preset == AnimationPreset::none && spec.keys.empty() && spec.handles.empty()) return;
  if (scene.mirror)
    throw InputError(scene.file.string() +
                     ": container.animation: a mirrored scene's container cannot move (its mirror line stands "
                     "still); remove `mirror` or the container's animation");
  // The outline's area centroid, as an element's pivot defaults to its outline's (animate.cpp).
  double a = 0.0, cx = 0.0, cy = 0.0;
  const std::vector<Vec2>& ring = container.outline;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % n];
    const double c = cross(p, q);
    a += c;
    cx += (p.x + q.x) * c;
    cy += (p.y + q.y) * c;
  }
  const Vec2 pivot = spec.pivot ? container.frame.to_unit(*spec.pivot) : Vec2{cx / (3.0 * a), cy / (3.0 * a)};
  try {
    container.motion = ContainerMotion(spec, pivot, container.frame.scale, scene.loop);
  } catch (const InputError& e) {
    throw InputError(scene.file.string() + ": " + e.what());
  }
}

}  // namespace animpak
