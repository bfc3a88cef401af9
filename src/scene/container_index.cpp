// The container query's index (include/animpak/state.hpp, ContainerIndex; docs/architecture.md, "The
// far field and the container query"), built once with the world: per row of a cell grid the segments
// the even–odd ray can cross, per cell the segments that can be nearest to a point in it. The bounds
// are computed in double and grown by a margin, so the lists are supersets and a query answers exactly
// as brute force does.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "animpak/scene.hpp"

namespace animpak {

namespace {

// Segment–point distance in double, for the index's bounds only.
double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double u = len2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  return std::hypot(px - (ax + u * dx), py - (ay + u * dy));
}

// Whether segments ab and cd meet, touching included (unlike the solver's segments_cross_properly): an
// index bound must count a segment that only touches a cell.
bool segments_meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
  const auto orient = [](double px, double py, double qx, double qy, double rx, double ry) {
    return (qx - px) * (ry - py) - (qy - py) * (rx - px);
  };
  const double o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
  const double o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
  const auto opposite = [](double a, double b) { return (a <= 0.0 && b >= 0.0) || (a >= 0.0 && b <= 0.0); };
  return opposite(o1, o2) && opposite(o3, o4);
}

// Distance from a segment to a box [x0, x1] × [y0, y1] (0 when they meet), in double.
double box_segment_distance(double x0, double y0, double x1, double y1, double ax, double ay, double bx, double by) {
  const auto in_box = [&](double px, double py) { return px >= x0 && px <= x1 && py >= y0 && py <= y1; };
  if (in_box(ax, ay) || in_box(bx, by)) return 0.0;
  const double cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    const int m = (k + 1) % 4;
    if (segments_meet(ax, ay, bx, by, cx[k], cy[k], cx[m], cy[m])) return 0.0;
    best = std::min(best, segment_distance(cx[k], cy[k], ax, ay, bx, by));
    best = std::min(best, segment_distance(ax, ay, cx[k], cy[k], cx[m], cy[m]));
    best = std::min(best, segment_distance(bx, by, cx[k], cy[k], cx[m], cy[m]));
  }
  return best;
}

}  // namespace

void index_container(ContainerGeometry& box, std::int32_t cells) {
  ContainerIndex& ix = box.index;
  ix = ContainerIndex{};
  const std::size_t segments = box.ax.size();
  if (segments == 0 || cells < 1) return;
  float lo_x = box.ax[0], hi_x = box.ax[0], lo_y = box.ay[0], hi_y = box.ay[0];
  for (std::size_t i = 0; i < segments; ++i) {
    lo_x = std::min({lo_x, box.ax[i], box.bx[i]}), hi_x = std::max({hi_x, box.ax[i], box.bx[i]});
    lo_y = std::min({lo_y, box.ay[i], box.by[i]}), hi_y = std::max({hi_y, box.ay[i], box.by[i]});
  }
  const float extent = std::max(hi_x - lo_x, hi_y - lo_y);
  if (!(extent > 0.0f) || !std::isfinite(extent)) return;
  ix.x0 = lo_x, ix.y0 = lo_y;
  ix.cell = extent / static_cast<float>(cells);
  ix.nx = std::max<std::int32_t>(1, static_cast<std::int32_t>(std::ceil((hi_x - lo_x) / ix.cell)));
  ix.ny = std::max<std::int32_t>(1, static_cast<std::int32_t>(std::ceil((hi_y - lo_y) / ix.cell)));
  std::vector<std::int32_t>& d = ix.data;

  // Bands: every segment in each row its y range meets, by the same float cell function as the query,
  // so a y inside a segment's range always finds it (floor of a monotone expression is monotone).
  std::vector<std::vector<std::int32_t>> band(ix.ny);
  for (std::size_t i = 0; i < segments; ++i) {
    const std::int32_t j0 = grid_axis_cell(std::min(box.ay[i], box.by[i]) - ix.y0, ix.cell, ix.ny);
    const std::int32_t j1 = grid_axis_cell(std::max(box.ay[i], box.by[i]) - ix.y0, ix.cell, ix.ny);
    for (std::int32_t j = j0; j <= j1; ++j) band[j].push_back(static_cast<std::int32_t>(i));
  }
  d.assign(ix.ny + 1, 0);
  for (std::int32_t j = 0; j < ix.ny; ++j) d[j + 1] = d[j] + static_cast<std::int32_t>(band[j].size());
  ix.band_segments = static_cast<std::int32_t>(d.size());
  for (const auto& b : band) d.insert(d.end(), b.begin(), b.end());

  // Cells: the segments that can be nearest to a point of the cell, grown by a margin far above float
  // rounding so a point the float cell function puts in the cell is covered.
  const double margin = 1e-5 * ix.cell + 1e-6;
  std::vector<std::vector<std::int32_t>> near(static_cast<std::size_t>(ix.nx) * ix.ny);
  std::vector<double> lower(segments);
  for (std::int32_t j = 0; j < ix.ny; ++j) {
    for (std::int32_t i = 0; i < ix.nx; ++i) {
      const double x0 = ix.x0 + static_cast<double>(i) * ix.cell - margin, x1 = ix.x0 + (i + 1.0) * ix.cell + margin;
      const double y0 = ix.y0 + static_cast<double>(j) * ix.cell - margin, y1 = ix.y0 + (j + 1.0) * ix.cell + margin;
      double upper = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < segments; ++k) {
        double far = 0.0;  // the segment's largest distance to the cell: at a corner (distance is convex)
        for (const double cx : {x0, x1})
          for (const double cy : {y0, y1})
            far = std::max(far, segment_distance(cx, cy, box.ax[k], box.ay[k], box.bx[k], box.by[k]));
        upper = std::min(upper, far);
        lower[k] = box_segment_distance(x0, y0, x1, y1, box.ax[k], box.ay[k], box.bx[k], box.by[k]);
      }
      auto& list = near[static_cast<std::size_t>(j) * ix.nx + i];
      for (std::size_t k = 0; k < segments; ++k)
        if (lower[k] <= upper + margin) list.push_back(static_cast<std::int32_t>(k));
    }
  }
  ix.cell_start = static_cast<std::int32_t>(d.size());
  d.push_back(0);
  for (const auto& list : near) d.push_back(d.back() + static_cast<std::int32_t>(list.size()));
  ix.cell_segments = static_cast<std::int32_t>(d.size());
  for (const auto& list : near) d.insert(d.end(), list.begin(), list.end());
}

}  // namespace animpak
