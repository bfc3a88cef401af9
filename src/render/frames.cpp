#include <algorithm>
#include <cmath>

#include "animpak/curve.hpp"
#include "animpak/render.hpp"

namespace animpak {

std::vector<double> frame_times(int count, bool loop) {
  std::vector<double> t(count);
  for (int i = 0; i < count; ++i) t[i] = loop ? double(i) / count : (count > 1 ? double(i) / (count - 1) : 0.0);
  return t;
}

std::vector<Vec2> element_tangents(const World& world, const SimState& state, int element) {
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice(), n = lib.slice_count;
  std::vector<Vec2> out(static_cast<std::size_t>(P) * n);
  const int mode = world.params.forces.motion_curve;
  if (mode == curve_linear || n < 2) return out;
  const Topology& topo = world.topology;
  // build_world fills the topology's links and chains (link_curves).
  require_curve_links(topo, "element_tangents");
  const CurveLinks& links = topo.curve;
  if (mode == curve_monotone) {
    for (int s = 0; s < n; ++s)
      for (int v = 0; v < P; ++v) {
        Vec2& m = out[static_cast<std::size_t>(s) * P + v];
        curve_vertex_tangent(topo, links, state, inst.slice_begin + s, v, m.x, m.y);
      }
    return out;
  }
  // The spline: every track of the chain this element's slices lie on, solved in double as the solver
  // solves it in float (include/animpak/curve.hpp, spline_tangents).
  const CurveChains& chains = topo.chains;
  const std::int32_t c = chains.chain[inst.slice_begin], b = chains.begin[c], len = chains.begin[c + 1] - b;
  std::vector<double> mx(len), my(len), cp(len), z(len);
  for (int v = 0; v < P; ++v) {
    const auto vertex = [&](std::int32_t i) { return topo.slice_begin[chains.slice[b + i]] + v; };
    const auto tau = [&](std::int32_t i) {
      return double(state.t[topo.slice_begin[chains.slice[b + i]]]) + double(chains.offset[b + i]);
    };
    const auto x = [&](std::int32_t i) { return double(state.x[vertex(i)]); };
    const auto y = [&](std::int32_t i) { return double(state.y[vertex(i)]); };
    spline_tangents<double>(len, double(chains.period[c]), tau, x, y, mx, my, cp, z);
    for (int s = 0; s < n; ++s) {
      const std::int32_t i = chains.entry[inst.slice_begin + s] - b;
      out[static_cast<std::size_t>(s) * P + v] = {mx[i], my[i]};
    }
  }
  return out;
}

std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf) {
  return element_at(world, state, element, tf, element_tangents(world, state, element));
}

std::vector<Vec2> element_at(const World& world, const SimState& state, int element, double tf,
                             const std::vector<Vec2>& tangents) {
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice(), n = lib.slice_count;
  auto slice_t = [&](int s) { return double(state.t[inst.vertex_begin + s * P]); };
  // Slices stay ordered (time springs) and flat (simultaneity), so the first vertex's t is the slice's.
  int s = 0;
  while (s < n - 2 && slice_t(s + 1) < tf) ++s;
  std::vector<Vec2> out(P);
  if (n < 2) {
    for (int v = 0; v < P; ++v) out[v] = {state.x[inst.vertex_begin + v], state.y[inst.vertex_begin + v]};
    return out;
  }
  const double t0 = slice_t(s), t1 = slice_t(s + 1);
  const double w = t1 > t0 ? std::clamp((tf - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  // The curve the overlap test walks (include/animpak/curve.hpp), in double, with the tangents at this
  // interval's two slices.
  const CurveBasis<double> basis = curve_basis(w, t1 - t0, world.params.forces.motion_curve);
  for (int v = 0; v < P; ++v) {
    const int a = inst.vertex_begin + s * P + v, b = a + P;
    const Vec2 ma = tangents[static_cast<std::size_t>(s) * P + v],
               mb = tangents[static_cast<std::size_t>(s + 1) * P + v];
    out[v] = {curve_value<double>(state.x[a], state.x[b], ma.x, mb.x, basis),
              curve_value<double>(state.y[a], state.y[b], ma.y, mb.y, basis)};
  }
  return out;
}

double element_scale(const World& world, int element, const std::vector<Vec2>& positions) {
  const SliceMesh& rest = world.library[world.elements[element].library].slice;
  const int B = rest.boundary_count;
  const std::vector<Vec2> now(positions.begin(), positions.begin() + B),
      before(rest.vertices.begin(), rest.vertices.begin() + B);
  return std::sqrt(std::abs(signed_area(now)) / std::max(std::abs(signed_area(before)), 1e-300));
}

int raster_width(const Box& box, int height) {
  return std::max(1, static_cast<int>(std::lround(height * box.width() / std::max(box.height(), 1e-9))));
}

ElementArt element_art(const World& world, int element, const std::vector<Vec2>& positions) {
  const SpacetimeElement& lib = world.library[world.elements[element].library];
  return {replay_art(lib.binding, lib.slice, positions), element_scale(world, element, positions)};
}

Vec2 art_centroid(const ElementArt& art) {
  Vec2 sum;
  std::size_t n = 0;
  for (const auto& path : art.points)
    for (const auto& line : path)
      for (const Vec2& p : line) sum = sum + p, ++n;
  return n > 0 ? sum * (1.0 / double(n)) : sum;
}

std::vector<Vec2> element_path(const World& world, const SimState& state, int element,
                               const std::vector<double>& times) {
  const std::vector<Vec2> tangents = element_tangents(world, state, element);
  std::vector<Vec2> path;
  path.reserve(times.size());
  for (double t : times)
    path.push_back(art_centroid(element_art(world, element, element_at(world, state, element, t, tangents))));
  return path;
}

std::vector<std::vector<Vec2>> frame_tangents(const World& world, const SimState& state) {
  std::vector<std::vector<Vec2>> tangents(world.elements.size());
  for (std::size_t i = 0; i < world.elements.size(); ++i) tangents[i] = element_tangents(world, state, int(i));
  return tangents;
}

std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf,
                                  const std::vector<std::vector<Vec2>>& tangents) {
  const std::size_t n = world.elements.size();
  std::vector<ElementArt> art(drawn_count(world));
  for (std::size_t i = 0; i < n; ++i)
    art[i] = element_art(world, int(i), element_at(world, state, int(i), tf, tangents[i]));
  // Mirror symmetry: each element's art reflected across the line (docs/scene-format.md, "Mirror").
  if (const std::optional<MirrorLine>& line = world.container.mirror)
    for (std::size_t i = 0; i < n; ++i) {
      art[n + i] = art[i];
      for (auto& path : art[n + i].points)
        for (auto& polyline : path)
          for (Vec2& p : polyline) p = line->reflect(p);
    }
  return art;
}

std::vector<ElementArt> frame_art(const World& world, const SimState& state, double tf) {
  return frame_art(world, state, tf, frame_tangents(world, state));
}

ArtPoints own_points(const ArtShape& art) {
  ArtPoints points(art.paths.size());
  for (std::size_t p = 0; p < art.paths.size(); ++p)
    for (const Polyline& line : art.paths[p].polylines) points[p].push_back(line.points);
  return points;
}

Picture draw_frame(const World& world, const std::vector<ElementArt>& art, const FrameStyle& style) {
  const Box box = world.container.shown_bounds();
  const int height = style.size;
  const int width = raster_width(box, height);
  Picture pic(width, height, box, style.background, 0.02 * style.size);
  if (style.container == ContainerDrawing::fill) pic.draw_art(world.container.art, own_points(world.container.art));
  for (std::size_t i = 0; i < art.size(); ++i)
    pic.draw_art(world.library[world.elements[drawn_source(world, int(i))].library].art.art, art[i].points, 1.0,
                 art[i].stroke_scale);
  if (style.container == ContainerDrawing::outline) {
    const double w = std::max(1.0, style.size / 400.0);
    pic.draw_ring(world.container.shown_outline(), {0.55, 0.55, 0.55, 1}, w);
    for (const auto& hole : world.container.shown_holes()) pic.draw_ring(hole, {0.55, 0.55, 0.55, 1}, w);
  }
  return pic;
}

Picture draw_frame(const World& world, const SimState& state, double tf, const FrameStyle& style) {
  return draw_frame(world, frame_art(world, state, tf), style);
}

}  // namespace animpak
