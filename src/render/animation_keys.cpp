// Where the animated vector formats put their keys (element_keys): each art path of an element keyed at
// the slices, where the curve between slices needs it (each interval eased or straight), or at the frames
// when held; and the stroke widths' keys. animation_writers.cpp writes them as Lottie and SMIL.
// docs/animation-formats.md, "Keys at the slices, and between them".
#include <algorithm>
#include <cmath>
#include <utility>

#include "frame_writers.hpp"

namespace animpak::frame_writers {
namespace {

// Half the last decimal kept (--precision) of the element's widest stroke, in stroke-scale units: 0 when it
// strokes nothing.
double stroke_tolerance(const World& world, int element, const FrameOutput& out) {
  const Box box = world.container.shown_bounds();
  const int height = out.style.size;
  const double pixels = fit_to_picture(raster_width(box, height), height, box, 0.02 * height).scale;
  double widest = 0.0;
  for (const ArtPath& path : world.library[world.elements[element].library].art.art.paths)
    if (path.stroke.enabled) widest = std::max(widest, path.stroke_width * pixels);
  return widest > 0 ? 0.5 * std::pow(10.0, -std::clamp(out.precision, 0, 12)) / widest : 0.0;
}

// The stroke scale is the square root of the element's area ratio (element_scale), and the area is quadratic
// between two slices: where straight keys between two slices would miss a frame's stroke width by more than
// the precision kept, that interval's frames are keyed too, so every frame's width is the PNG frame's.
void add_stroke_keys(const World& world, const SimState& state, int element, const std::vector<Vec2>& tangents,
                     const FrameOutput& out, double frames_per_unit, ElementKeys& keys) {
  const double tolerance = stroke_tolerance(world, element, out);
  if (tolerance == 0) return;
  std::vector<double> frames, scales;
  for (std::size_t k = 0; k + 1 < keys.stroke_frames.size(); ++k) {
    frames.push_back(keys.stroke_frames[k]), scales.push_back(keys.stroke_scales[k]);
    const double a = keys.stroke_frames[k], b = keys.stroke_frames[k + 1];
    const double sa = keys.stroke_scales[k], sb = keys.stroke_scales[k + 1];
    std::vector<double> inner_frames, inner_scales;
    bool straight = true;
    for (int i = int(std::floor(a)) + 1; i < b && i < out.count; ++i) {
      const double scale =
          element_scale(world, element, element_at(world, state, element, i / frames_per_unit, tangents));
      straight = straight && std::abs(scale - (sa + (sb - sa) * (i - a) / (b - a))) <= tolerance;
      inner_frames.push_back(i), inner_scales.push_back(scale);
    }
    if (straight) continue;
    frames.insert(frames.end(), inner_frames.begin(), inner_frames.end());
    scales.insert(scales.end(), inner_scales.begin(), inner_scales.end());
  }
  frames.push_back(keys.stroke_frames.back()), scales.push_back(keys.stroke_scales.back());
  keys.stroke_frames = std::move(frames), keys.stroke_scales = std::move(scales);
}

// How far the player's straight line between two keys may stray from the curve the frames follow: three
// quarters of a pixel of the output picture, or 0.3 % of the element's size where that is less. A shape's
// overlap with itself (IoU) falls with the displacement over its size, and a star 30 pixels across, keyed
// to 0.5 % of its size, fell to 0.985 against the PNG frame under rlottie; at 0.3 % it holds 0.99.
constexpr double key_tolerance_px = 0.75;
constexpr double key_tolerance_share = 0.003;

// The number of equal parts of the interval [ta, tb] between two slices in which the curve at the middle
// of every part lies within `tolerance` of the straight line between the part's ends, for every vertex of
// the element: the fewest power of two, at most 64.
int key_parts(const World& world, const SimState& state, int element, const std::vector<Vec2>& tangents, double ta,
              double tb, double tolerance) {
  constexpr int most = 64;
  for (int parts = 1; parts < most; parts *= 2) {
    double worst = 0.0;
    std::vector<Vec2> a = element_at(world, state, element, ta, tangents);
    for (int j = 0; j < parts && worst <= tolerance; ++j) {
      const double t0 = ta + (tb - ta) * j / parts, t1 = ta + (tb - ta) * (j + 1) / parts;
      const std::vector<Vec2> b = element_at(world, state, element, t1, tangents);
      const std::vector<Vec2> m = element_at(world, state, element, 0.5 * (t0 + t1), tangents);
      for (std::size_t v = 0; v < m.size(); ++v)
        worst = std::max(worst, std::hypot(m[v].x - 0.5 * (a[v].x + b[v].x), m[v].y - 0.5 * (a[v].y + b[v].y)));
      a = b;
    }
    if (worst <= tolerance) return parts;
  }
  return most;
}

// The farthest any point of `at` (a path's points at each candidate time) strays, at the candidates
// between a and b, from where a player puts it with keys at a and b and `ease` between them; stops
// counting once past `enough`.
double segment_error(const std::vector<double>& times, const std::vector<std::vector<Vec2>>& at, std::size_t a,
                     std::size_t b, const Ease& ease, double enough) {
  double worst = 0.0;
  for (std::size_t c = a + 1; c < b && worst <= enough; ++c) {
    const double e = ease.at((times[c] - times[a]) / (times[b] - times[a]));
    for (std::size_t v = 0; v < at[c].size(); ++v) {
      const Vec2 line = at[a][v] + (at[b][v] - at[a][v]) * e;
      worst = std::max(worst, std::hypot(at[c][v].x - line.x, at[c][v].y - line.y));
    }
  }
  return worst;
}

// Easing parameters as written (Lottie and SMIL alike take them to four decimals).
double ease_decimals(double y) { return std::round(y * 1e4) / 1e4; }

// Whether keys at candidates a and b carry the path within `tolerance` of its curve at every candidate
// between, with straight timing or else with the timing curve fitted to the share of the way each
// candidate lies along the keys' line (least squares over the path's points, then the two control values
// by least squares, kept in [0, 1] as SMIL requires); `ease` is set to the one that does.
bool segment_fits(const std::vector<double>& times, const std::vector<std::vector<Vec2>>& at, std::size_t a,
                  std::size_t b, double tolerance, Ease& ease) {
  if (segment_error(times, at, a, b, Ease{}, tolerance) <= tolerance) {
    ease = Ease{};
    return true;
  }
  if (b < a + 3) return false;  // one candidate between: no fit to speak of
  double along = 0.0;
  for (std::size_t v = 0; v < at[a].size(); ++v) along += dot(at[b][v] - at[a][v], at[b][v] - at[a][v]);
  if (along <= 0.0) return false;
  // Normal equations of e(s) − s³ = 3(1−s)²s·y1 + 3(1−s)s²·y2 against each candidate's share of the way.
  double m11 = 0, m12 = 0, m22 = 0, r1 = 0, r2 = 0;
  for (std::size_t c = a + 1; c < b; ++c) {
    const double s = (times[c] - times[a]) / (times[b] - times[a]);
    double share = 0.0;
    for (std::size_t v = 0; v < at[a].size(); ++v) share += dot(at[c][v] - at[a][v], at[b][v] - at[a][v]);
    share /= along;
    const double f1 = 3 * (1 - s) * (1 - s) * s, f2 = 3 * (1 - s) * s * s, r = share - s * s * s;
    m11 += f1 * f1, m12 += f1 * f2, m22 += f2 * f2, r1 += f1 * r, r2 += f2 * r;
  }
  const double det = m11 * m22 - m12 * m12;
  if (std::abs(det) <= 1e-12 * std::max(1.0, m11 * m22)) return false;
  const Ease fitted{ease_decimals(std::clamp((r1 * m22 - r2 * m12) / det, 0.0, 1.0)),
                    ease_decimals(std::clamp((r2 * m11 - r1 * m12) / det, 0.0, 1.0)), false};
  if (segment_error(times, at, a, b, fitted, tolerance) > tolerance) return false;
  ease = fitted;
  return true;
}

// A path's keys among the candidate times (increasing, with the path's points at each): from each key, the
// farthest candidate that segment_fits reaches becomes the next (found by doubling the reach, then halving
// the gap between the last that fits and the first that does not), so a path that moves straight on, or
// eases along its line, needs no key in between. The first and the last candidates are keys.
std::vector<std::pair<std::size_t, Ease>> path_keys(const std::vector<double>& times,
                                                    const std::vector<std::vector<Vec2>>& at, double tolerance) {
  const std::size_t n = times.size();
  std::vector<std::pair<std::size_t, Ease>> keys{{0, Ease{}}};
  Ease ease;
  for (std::size_t a = 0; a + 1 < n;) {
    std::size_t good = a + 1, bad = n;
    Ease good_ease;
    for (std::size_t reach = 2; good + 1 < n; reach *= 2) {
      const std::size_t b = std::min(a + reach, n - 1);
      if (!segment_fits(times, at, a, b, tolerance, ease)) {
        bad = b;
        break;
      }
      good = b, good_ease = ease;
    }
    while (bad < n && bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      if (segment_fits(times, at, a, mid, tolerance, ease))
        good = mid, good_ease = ease;
      else
        bad = mid;
    }
    keys.emplace_back(good, good_ease);
    a = good;
  }
  return keys;
}

}  // namespace

ElementKeys still_keys(const ArtPoints& points) {
  ElementKeys keys;
  for (const auto& lines : points) keys.paths.push_back({{0.0}, {lines}, {}});
  keys.stroke_frames = {0.0}, keys.stroke_scales = {1.0};
  return keys;
}

// Frame i shows t = i / N when looping, i / (N − 1) otherwise (frame_times). Every art point is a fixed
// barycentric combination of three vertices of one triangle (replay_art), and the art follows the
// vertices' curve between slices (element_at): each path is keyed where its points need it for the
// player's line between keys, with the key's easing, to stay within the tolerance of the curve
// (path_keys). With straight lines between slices (motion_curve 0) the keys at the slices are the motion
// itself, shared by every path.
// The first slice is at t = 0 and the last at t = 1 (the end-to-end constraint), so linear keys span the
// document, the last at frame N when looping.
ElementKeys element_keys(const World& world, const SimState& state, int element, const FrameOutput& out) {
  ElementKeys keys;
  // A key of every path, and of the stroke, at `frame`.
  auto add = [&](double frame, const ElementArt& art) {
    keys.paths.resize(art.points.size());
    for (std::size_t p = 0; p < art.points.size(); ++p) {
      PathKeys& path = keys.paths[p];
      if (!path.frames.empty()) path.ease.emplace_back();
      path.frames.push_back(frame), path.lines.push_back(art.points[p]);
    }
    keys.stroke_frames.push_back(frame), keys.stroke_scales.push_back(art.stroke_scale);
  };
  const int frames = out.count;
  if (out.interpolation == Interpolation::hold || frames == 1) {
    const std::vector<double> times = frame_times(frames, world.loop);
    const std::vector<Vec2> tangents = element_tangents(world, state, element);
    for (int i = 0; i < frames; ++i)
      add(i, element_art(world, element, element_at(world, state, element, times[i], tangents)));
    return keys;
  }
  const ElementInstance& inst = world.elements[element];
  const SpacetimeElement& lib = world.library[inst.library];
  const int P = lib.vertices_per_slice();
  const double frames_per_unit = world.loop ? frames : frames - 1, steps = std::pow(10.0, key_decimals);
  const auto frame_of = [&](double t) { return std::round(t * frames_per_unit * steps) / steps; };
  const Box box = world.container.shown_bounds();
  const double pixels =
      fit_to_picture(raster_width(box, out.style.size), out.style.size, box, 0.02 * out.style.size).scale;
  const bool cubic = world.params.forces.motion_curve != curve_linear;
  const std::vector<Vec2> tangents = element_tangents(world, state, element);
  double tolerance = key_tolerance_px / pixels;
  if (cubic) {
    const std::vector<Vec2> start = element_at(world, state, element, 0.0, tangents);
    double x0 = start.front().x, x1 = x0, y0 = start.front().y, y1 = y0;
    for (const Vec2& p : start)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    tolerance = std::min(tolerance, key_tolerance_share * std::max(x1 - x0, y1 - y0));
  }
  // The candidate times: every slice, and with the curve, between two slices the steps of twice the parts
  // in which chords stay within the tolerance (key_parts; at least 8), so that checking the candidates
  // checks the curve.
  std::vector<double> times;
  std::vector<ElementArt> art;  // the art at each candidate
  std::vector<char> slice;      // whether the candidate is a slice
  std::vector<Vec2> positions(P);
  for (int s = 0; s < lib.slice_count; ++s) {
    const int first = inst.vertex_begin + s * P;
    const double t = state.t[first];
    // Time springs keep slices apart; two at one time would be a jump, which no pair of keys draws.
    if (!times.empty() && frame_of(t) <= frame_of(times.back())) continue;
    if (cubic && !times.empty()) {
      const double before = times.back();
      const int candidates = std::max(8, 2 * key_parts(world, state, element, tangents, before, t, tolerance));
      for (int j = 1; j < candidates; ++j) {
        const double tj = before + (t - before) * j / candidates;
        if (frame_of(tj) > frame_of(times.back()) && frame_of(tj) < frame_of(t)) {
          times.push_back(tj), slice.push_back(0);
          art.push_back(element_art(world, element, element_at(world, state, element, tj, tangents)));
        }
      }
    }
    for (int v = 0; v < P; ++v) positions[v] = {state.x[first + v], state.y[first + v]};
    times.push_back(t), slice.push_back(1), art.push_back(element_art(world, element, positions));
  }
  if (!cubic) {
    for (std::size_t k = 0; k < times.size(); ++k) add(frame_of(times[k]), art[k]);
  } else {
    keys.paths.resize(art.front().points.size());
    for (std::size_t p = 0; p < keys.paths.size(); ++p) {
      std::vector<std::vector<Vec2>> at(times.size());
      for (std::size_t k = 0; k < times.size(); ++k)
        for (const auto& line : art[k].points[p]) at[k].insert(at[k].end(), line.begin(), line.end());
      PathKeys& path = keys.paths[p];
      for (const auto& [k, ease] : path_keys(times, at, tolerance)) {
        if (!path.frames.empty()) path.ease.push_back(ease);
        path.frames.push_back(frame_of(times[k])), path.lines.push_back(art[k].points[p]);
      }
    }
    for (std::size_t k = 0; k < times.size(); ++k)
      if (slice[k]) keys.stroke_frames.push_back(frame_of(times[k])), keys.stroke_scales.push_back(art[k].stroke_scale);
  }
  // A document that does not loop shows its last slice through its last frame, up to op = N.
  if (keys.stroke_frames.back() < frames) add(frames, art.back());
  add_stroke_keys(world, state, element, tangents, out, frames_per_unit, keys);
  return keys;
}

ElementKeys drawn_keys(const World& world, const SimState& state, int drawn, const FrameOutput& out) {
  ElementKeys keys = element_keys(world, state, drawn_source(world, drawn), out);
  if (drawn >= int(world.elements.size()))
    for (PathKeys& path : keys.paths)
      for (auto& key : path.lines)
        for (auto& line : key)
          for (Vec2& p : line) p = world.container.mirror->reflect(p);
  return keys;
}

}  // namespace animpak::frame_writers
