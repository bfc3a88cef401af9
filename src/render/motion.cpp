// Motion metrics of a packing (docs/quality.md, "Motion"): how smoothly the elements' art moves from frame
// to frame, whether the slices show, and how closely each element's size follows its script. Measured on
// the frames' art and the packed slices' geometry, never on the solver's own statistics.
#include <algorithm>
#include <cmath>
#include <limits>

#include "animpak/render.hpp"

namespace animpak {

namespace {

double polygon_area(const std::vector<float>& x, const std::vector<float>& y, std::int32_t lo, std::int32_t count) {
  double a = 0.0;
  for (std::int32_t i = 0; i < count; ++i) {
    const std::int32_t j = i + 1 == count ? 0 : i + 1;
    a += double(x[lo + i]) * y[lo + j] - double(x[lo + j]) * y[lo + i];
  }
  return std::abs(0.5 * a);
}

}  // namespace

std::vector<LoopNeighbours> loop_neighbours(const World& world) {
  const Topology& topo = world.topology;
  std::vector<LoopNeighbours> n(world.elements.size());
  for (std::size_t e = 0; e < n.size(); ++e) n[e] = {int(e), int(e)};
  // One entry per loop pair of vertices: every pair of two elements names the same two.
  for (std::size_t i = 0; i < topo.loop_end.size(); ++i) {
    const int from = topo.element[topo.loop_end[i]], to = topo.element[topo.loop_start[i]];
    n[std::size_t(from)].into = to, n[std::size_t(to)].from = from;
  }
  return n;
}

MotionMetrics measure_motion(const World& world, const SimState& state, const std::vector<std::vector<Vec2>>& centroids,
                             const std::vector<double>& times) {
  MotionMetrics m;
  const Topology& topo = world.topology;
  const std::size_t n = times.size();
  // Across a looping scene's seam an element continues as the element it loops into (§5.2's loop pairs:
  // two guided elements that swap places), so frame N − 1's next frame is that element's frame 0, and
  // frame 0's previous frame is frame N − 1 of the element that loops into this one.
  std::vector<std::size_t> loops_into(centroids.size()), loops_from(centroids.size());
  const std::vector<LoopNeighbours> loops = loop_neighbours(world);
  for (std::size_t e = 0; e < centroids.size(); ++e) {
    const LoopNeighbours loop = e < loops.size() ? loops[e] : LoopNeighbours{int(e), int(e)};
    loops_into[e] = std::size_t(loop.into) < centroids.size() ? std::size_t(loop.into) : e;
    loops_from[e] = std::size_t(loop.from) < centroids.size() ? std::size_t(loop.from) : e;
  }
  std::vector<double> all, at_slice, elsewhere;
  m.frame_peak.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t e = 0; e < centroids.size() && n >= 3; ++e) {
    const ElementInstance& inst = world.elements[e];
    const int first = inst.slice_begin, slices = topo.element_slice_begin[e + 1] - first;
    const double step = n > 1 ? std::abs(times[1] - times[0]) : 1.0;
    for (std::size_t i = world.loop ? 0 : 1; i < (world.loop ? n : n - 1); ++i) {
      const Vec2 a = i == 0 ? centroids[loops_from[e]][n - 1] : centroids[e][i - 1], b = centroids[e][i],
                 c = i + 1 == n ? centroids[loops_into[e]][0] : centroids[e][i + 1];
      const double value = std::hypot(a.x - 2.0 * b.x + c.x, a.y - 2.0 * b.y + c.y);
      all.push_back(value);
      if (!(m.frame_peak[i] >= value)) m.frame_peak[i] = value;
      // Frame i bends at a slice when one of the element's slice times lies within a frame of it.
      bool near = false;
      for (int s = 0; s < slices && !near; ++s) {
        const double ts = state.t[topo.slice_begin[first + s]];
        near = std::abs(times[i] - ts) < step || (world.loop && std::abs(std::abs(times[i] - ts) - 1.0) < step);
      }
      (near ? at_slice : elsewhere).push_back(value);
    }
  }
  if (!all.empty()) {
    std::sort(all.begin(), all.end());
    m.acceleration_median = all[all.size() / 2];
    m.acceleration_p99 = all[std::min(all.size() - 1, static_cast<std::size_t>(0.99 * double(all.size() - 1) + 0.5))];
  }
  const auto mean = [](const std::vector<double>& v) {
    double s = 0.0;
    for (const double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
  };
  if (!at_slice.empty() && mean(elsewhere) > 0.0) m.slice_ratio = mean(at_slice) / mean(elsewhere);
  // How far each element moves: its centroid's largest distance from its mean place, and its path per
  // loop (across the seam into the element it loops into, as the acceleration goes). Both in the
  // container's frame (docs/quality.md, "A container that moves"): each centroid taken back by the
  // container's motion at its frame time, so that an element the container carries without moving in it
  // neither strays nor travels. A container that does not move leaves the centroids as they are.
  std::vector<std::vector<Vec2>> in_container;
  if (world.container.motion.moves()) {
    in_container = centroids;
    for (std::vector<Vec2>& c : in_container)
      for (std::size_t i = 0; i < c.size() && i < n; ++i) c[i] = world.container.motion.at(times[i]).inverse(c[i]);
  }
  const std::vector<std::vector<Vec2>>& placed = in_container.empty() ? centroids : in_container;
  for (std::size_t e = 0; e < placed.size(); ++e) {
    const std::vector<Vec2>& c = placed[e];
    Vec2 mean_place{0.0, 0.0};
    for (const Vec2 p : c) mean_place = mean_place + p;
    if (!c.empty()) mean_place = (1.0 / double(c.size())) * mean_place;
    double detour = 0.0, length = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      detour = std::max(detour, std::hypot(c[i].x - mean_place.x, c[i].y - mean_place.y));
      if (i + 1 < c.size())
        length += std::hypot(c[i + 1].x - c[i].x, c[i + 1].y - c[i].y);
      else if (world.loop && !placed[loops_into[e]].empty())
        length += std::hypot(placed[loops_into[e]][0].x - c[i].x, placed[loops_into[e]][0].y - c[i].y);
    }
    m.detour.push_back(detour);
    m.path_length.push_back(length);
    m.guided.push_back(e < world.elements.size() && world.elements[e].guided);
    m.dip.push_back(e < world.elements.size() ? world.elements[e].dip : 1.0);
  }
  // Size over script at every slice: the boundary's area over the rest copy's, the element as scripted
  // (shrunk and placed as at the start; docs/parameters.md, "Growth").
  for (std::size_t e = 0; e < world.elements.size(); ++e) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (std::int32_t s = topo.element_slice_begin[e]; s < topo.element_slice_begin[e + 1]; ++s) {
      const std::int32_t first = topo.slice_begin[s], count = topo.slice_boundary[s];
      const double scripted = polygon_area(topo.rest_copy_x, topo.rest_copy_y, first, count);
      if (!(scripted > 0.0)) continue;
      const double ratio = polygon_area(state.x, state.y, first, count) / scripted;
      lo = std::min(lo, ratio), hi = std::max(hi, ratio);
    }
    m.size_over_script.push_back(hi > 0.0 && lo > 0.0 ? hi / lo : 1.0);
  }
  return m;
}

}  // namespace animpak
