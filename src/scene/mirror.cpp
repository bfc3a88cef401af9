// Mirror symmetry (docs/scene-format.md, "Mirror"; the paper's Fig. 14 simulates half of the lion's mane and
// reflects it): the container is cut along the line, one side is simulated with the line as one of its
// walls, and the frames show that side and its reflection. Polygon clipping with Clipper, in integers of
// 1e-9 unit (the container spans [0, 1]).
#include <polyclipping/clipper.hpp>

#include <cmath>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/scene.hpp"

namespace animpak {
namespace {

namespace cl = ClipperLib;
constexpr double clipper_scale = 1e9;

cl::Path to_path(const std::vector<Vec2>& ring) {
  cl::Path path;
  for (Vec2 p : ring)
    path.push_back({static_cast<cl::cInt>(std::llround(p.x * clipper_scale)),
                    static_cast<cl::cInt>(std::llround(p.y * clipper_scale))});
  return path;
}

std::vector<Vec2> to_ring(const cl::Path& path) {
  std::vector<Vec2> ring;
  for (const cl::IntPoint& p : path) ring.push_back({double(p.X) / clipper_scale, double(p.Y) / clipper_scale});
  return ring;
}

cl::Paths rings_of(const std::vector<Vec2>& outline, const std::vector<std::vector<Vec2>>& holes) {
  cl::Paths paths{to_path(outline)};
  for (const auto& h : holes) paths.push_back(to_path(h));
  return paths;
}

// One outer ring and its holes from a tree Clipper made; InputError naming the scene otherwise.
void single_region(const cl::PolyTree& tree, const std::string& what, std::vector<Vec2>& outline,
                   std::vector<std::vector<Vec2>>& holes) {
  if (tree.ChildCount() != 1) {
    std::ostringstream message;
    message << what << " is "
            << (tree.ChildCount() == 0 ? "empty" : std::to_string(tree.ChildCount()) + " separate pieces")
            << "; animpak packs one connected container: move the mirror line so that the kept side is one piece";
    throw InputError(message.str());
  }
  const cl::PolyNode* outer = tree.Childs[0];
  outline = to_ring(outer->Contour);
  holes.clear();
  for (const cl::PolyNode* hole : outer->Childs) {
    if (hole->ChildCount() != 0)
      throw InputError(what + " has an island inside a hole; animpak's container is one outline with holes");
    holes.push_back(to_ring(hole->Contour));
  }
}

}  // namespace

Container mirror_container(const Container& whole, const MirrorSpec& spec, const std::string& scene_name) {
  const Vec2 on_line = whole.frame.to_unit({spec.at, spec.at});
  MirrorLine line{spec.vertical, spec.vertical ? on_line.x : on_line.y};
  const Box box = whole.bounds();
  const double lo = spec.vertical ? box.min.x : box.min.y, hi = spec.vertical ? box.max.x : box.max.y;
  const std::string name = scene_name + ": mirror: the line " + (spec.vertical ? "x = " : "y = ") + [&] {
    std::ostringstream s;
    s << spec.at;
    return s.str();
  }();
  if (!(line.at > lo && line.at < hi)) {
    const Vec2 art_lo = whole.frame.to_art(box.min), art_hi = whole.frame.to_art(box.max);
    std::ostringstream message;
    message << name << " misses the container, which spans " << (spec.vertical ? "x " : "y ")
            << (spec.vertical ? art_lo.x : art_lo.y) << " to " << (spec.vertical ? art_hi.x : art_hi.y)
            << " in its art's coordinates; put the line across the container";
    throw InputError(message.str());
  }
  // The kept side as a half-plane, as a box far larger than the unit square.
  const double far = 4.0;
  std::vector<Vec2> side;
  if (spec.vertical)
    side = spec.keep_low ? std::vector<Vec2>{{-far, -far}, {line.at, -far}, {line.at, far}, {-far, far}}
                         : std::vector<Vec2>{{line.at, -far}, {far, -far}, {far, far}, {line.at, far}};
  else
    side = spec.keep_low ? std::vector<Vec2>{{-far, -far}, {far, -far}, {far, line.at}, {-far, line.at}}
                         : std::vector<Vec2>{{-far, line.at}, {far, line.at}, {far, far}, {-far, far}};
  Container half = whole;
  {
    cl::Clipper clipper;
    clipper.AddPaths(rings_of(whole.outline, whole.holes), cl::ptSubject, true);
    clipper.AddPath(to_path(side), cl::ptClip, true);
    cl::PolyTree tree;
    clipper.Execute(cl::ctIntersection, tree, cl::pftEvenOdd, cl::pftNonZero);
    single_region(tree, name + ": the kept side of the container", half.outline, half.holes);
  }
  // What the frames show: the kept side and its reflection (the whole container when it is symmetric).
  {
    std::vector<Vec2> outline_image;
    for (auto it = half.outline.rbegin(); it != half.outline.rend(); ++it) outline_image.push_back(line.reflect(*it));
    cl::Paths both = rings_of(half.outline, half.holes);
    cl::Paths images{to_path(outline_image)};
    for (const auto& h : half.holes) {
      std::vector<Vec2> image;
      for (auto it = h.rbegin(); it != h.rend(); ++it) image.push_back(line.reflect(*it));
      images.push_back(to_path(image));
    }
    cl::Clipper clipper;
    clipper.AddPaths(both, cl::ptSubject, true);
    clipper.AddPaths(images, cl::ptClip, true);
    cl::PolyTree tree;
    clipper.Execute(cl::ctUnion, tree, cl::pftEvenOdd, cl::pftEvenOdd);
    single_region(tree, name + ": the kept side with its reflection", half.whole_outline, half.whole_holes);
  }
  half.mirror = line;
  return half;
}

int drawn_count(const World& world) { return int(world.elements.size()) * (world.container.mirror ? 2 : 1); }

int drawn_source(const World& world, int drawn) {
  const int n = int(world.elements.size());
  return drawn >= n ? drawn - n : drawn;
}

std::string drawn_name(const World& world, int drawn) {
  std::string name = world.elements[drawn_source(world, drawn)].name;
  if (drawn >= int(world.elements.size())) name.append(" mirrored");
  return name;
}

}  // namespace animpak
