// Where the animated vector formats put their keys (element_keys): each art path of an element keyed at
// the slices, where the curve between slices needs it (each interval eased or straight), or at the frames
// when held; and the stroke widths' keys. animation_writers.cpp writes them as Lottie and SMIL.
// docs/animation-formats.md, "Keys at the slices, and between them".
#include <algorithm>
#include <cmath>
#include <limits>
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

// How far the player's straight line between two keys may stray from the curve the frames follow: three
// quarters of a pixel of the output picture less the curves' own share (FrameOutput::curve_tolerance,
// docs/animation-formats.md, "Curves"), or 0.3 % of the element's size where that is less. A shape's
// overlap with itself (IoU) falls with the displacement over its size, and a star 30 pixels across, keyed
// to 0.5 % of its size, fell to 0.985 against the PNG frame under rlottie; at 0.3 % it holds 0.99.
constexpr double key_tolerance_px = 0.75;
constexpr double key_tolerance_share = 0.003;
// How far a player's placement of a whole element (its frame's move, turn and scale between keys) may stray:
// a tenth of a pixel, or a quarter of the key tolerance where that is less (keys_of). Detailed art (the
// crossing example's bee, 46 paths, 100 pixels across) overlapped its PNG frames by 0.97 under rlottie with
// every path 0.3 pixels off; the placement's keys are a few numbers.
constexpr double key_placement_px = 0.1;

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

// The share of the way from a to b each candidate between lies at: the least-squares projection of
// `at[c] − at[a]` on `at[b] − at[a]` over all points; false when a and b coincide.
bool shares_along(const std::vector<std::vector<Vec2>>& at, std::size_t a, std::size_t b, std::vector<double>& shares) {
  double along = 0.0;
  for (std::size_t v = 0; v < at[a].size(); ++v) along += dot(at[b][v] - at[a][v], at[b][v] - at[a][v]);
  if (along <= 0.0) return false;
  shares.clear();
  for (std::size_t c = a + 1; c < b; ++c) {
    double share = 0.0;
    for (std::size_t v = 0; v < at[a].size(); ++v) share += dot(at[c][v] - at[a][v], at[b][v] - at[a][v]);
    shares.push_back(share / along);
  }
  return true;
}

// Whether keys at candidates a and b carry a track within `tolerance` of its curve at every candidate
// between (`error(ease)`, the farthest stray with that easing), with straight timing or else with the
// timing curve fitted to the share of the way each candidate lies (`shares`, shares_along), the two
// control values by least squares, kept in [0, 1] as SMIL requires; `ease` is set to the one that does.
template <class Error, class Shares>
bool eased_fits(const std::vector<double>& times, std::size_t a, std::size_t b, double tolerance, Error error,
                Shares shares, Ease& ease) {
  if (error(Ease{}) <= tolerance) {
    ease = Ease{};
    return true;
  }
  if (b < a + 3) return false;  // one candidate between: no fit to speak of
  std::vector<double> share;
  if (!shares(share)) return false;
  // Normal equations of e(s) − s³ = 3(1−s)²s·y1 + 3(1−s)s²·y2 against each candidate's share of the way.
  double m11 = 0, m12 = 0, m22 = 0, r1 = 0, r2 = 0;
  for (std::size_t c = a + 1; c < b; ++c) {
    const double s = (times[c] - times[a]) / (times[b] - times[a]);
    const double f1 = 3 * (1 - s) * (1 - s) * s, f2 = 3 * (1 - s) * s * s, r = share[c - a - 1] - s * s * s;
    m11 += f1 * f1, m12 += f1 * f2, m22 += f2 * f2, r1 += f1 * r, r2 += f2 * r;
  }
  const double det = m11 * m22 - m12 * m12;
  if (std::abs(det) <= 1e-12 * std::max(1.0, m11 * m22)) return false;
  const Ease fitted{ease_decimals(std::clamp((r1 * m22 - r2 * m12) / det, 0.0, 1.0)),
                    ease_decimals(std::clamp((r2 * m11 - r1 * m12) / det, 0.0, 1.0)), false};
  if (error(fitted) > tolerance) return false;
  ease = fitted;
  return true;
}

// Points keyed straight from key to key (a path's points, a stroke's scale): eased_fits with the points'
// own stray and shares.
bool segment_fits(const std::vector<double>& times, const std::vector<std::vector<Vec2>>& at, std::size_t a,
                  std::size_t b, double tolerance, Ease& ease) {
  return eased_fits(
      times, a, b, tolerance, [&](const Ease& e) { return segment_error(times, at, a, b, e, tolerance); },
      [&](std::vector<double>& share) { return shares_along(at, a, b, share); }, ease);
}

// A track's keys among n candidates: from each key, the farthest candidate that `fits(a, b, ease)` reaches
// becomes the next (found by doubling the reach, then halving the gap between the last that fits and the
// first that does not), never past the next `forced` candidate, so a track that moves straight on, or
// eases along its line, needs no key in between. The first and the last candidates are keys.
template <class Fits>
std::vector<std::pair<std::size_t, Ease>> chosen_keys(std::size_t n, const std::vector<char>& forced, Fits fits) {
  std::vector<std::pair<std::size_t, Ease>> keys{{0, Ease{}}};
  Ease ease;
  for (std::size_t a = 0; a + 1 < n;) {
    std::size_t end = a + 1;
    while (end + 1 < n && !forced[end]) ++end;
    std::size_t good = a + 1, bad = end + 1;
    Ease good_ease;
    for (std::size_t reach = 2; good < end; reach *= 2) {
      const std::size_t b = std::min(a + reach, end);
      if (!fits(a, b, ease)) {
        bad = b;
        break;
      }
      good = b, good_ease = ease;
    }
    while (bad <= end && bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      if (fits(a, mid, ease))
        good = mid, good_ease = ease;
      else
        bad = mid;
    }
    keys.emplace_back(good, good_ease);
    a = good;
  }
  return keys;
}

// A path's keys among the candidate times (with the path's points at each): chosen_keys of its points.
std::vector<std::pair<std::size_t, Ease>> path_keys(const std::vector<double>& times,
                                                    const std::vector<std::vector<Vec2>>& at,
                                                    const std::vector<char>& forced, double tolerance) {
  return chosen_keys(times.size(), forced, [&](std::size_t a, std::size_t b, Ease& ease) {
    return segment_fits(times, at, a, b, tolerance, ease);
  });
}

// The convex hull of `points` (Andrew's monotone chain): a similarity moves no point farther than it moves
// the farthest of the hull's corners, so checking a placement's error at the corners checks every point.
std::vector<Vec2> hull_of(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The similarity that takes the reference points (centred on their mean) closest to `points` by least
// squares (the element's rotation, uniform scale and move at one candidate; with `rigid`, its scale 1);
// `angle_near` picks the turn of the angle nearest the previous candidate's, so that keys between two
// candidates turn the short way.
Placement fitted_placement(const std::vector<Vec2>& reference, const std::vector<Vec2>& points, double angle_near,
                           bool rigid = false) {
  Vec2 mean{0, 0};
  for (Vec2 p : points) mean = mean + p;
  mean = mean * (1.0 / double(points.size()));
  double a = 0.0, b = 0.0, rr = 0.0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Vec2 q = points[v] - mean;
    a += dot(reference[v], q), b += cross(reference[v], q), rr += dot(reference[v], reference[v]);
  }
  Placement placed;
  placed.position = mean;
  if (rr <= 0.0) return placed;
  placed.angle = std::atan2(b, a);
  placed.angle += 2 * M_PI * std::round((angle_near - placed.angle) / (2 * M_PI));
  placed.scale = rigid ? 1.0 : std::hypot(a, b) / rr;
  return placed;
}

// A player's placement between keys pa and pb at share e of the way: each part straight on its own.
Placement placement_between(const Placement& pa, const Placement& pb, double e) {
  return {pa.position + (pb.position - pa.position) * e, pa.angle + (pb.angle - pa.angle) * e,
          pa.scale + (pb.scale - pa.scale) * e};
}

// All points of one path of an element's art, its polylines one after another.
std::vector<Vec2> path_points(const ElementArt& art, std::size_t p) {
  std::vector<Vec2> points;
  for (const auto& line : art.points[p]) points.insert(points.end(), line.begin(), line.end());
  return points;
}

// `flat` cut back into the polylines of `like`.
std::vector<std::vector<Vec2>> as_lines(const std::vector<Vec2>& flat, const std::vector<std::vector<Vec2>>& like) {
  std::vector<std::vector<Vec2>> lines;
  std::size_t at = 0;
  for (const auto& line : like) {
    lines.emplace_back(flat.begin() + std::ptrdiff_t(at), flat.begin() + std::ptrdiff_t(at + line.size()));
    at += line.size();
  }
  return lines;
}

// The element's points at the first candidate less their mean: its frame's own shape, which
// fitted_placement places at each candidate.
std::vector<Vec2> reference_of(const std::vector<Vec2>& first) {
  Vec2 mean{0, 0};
  for (Vec2 p : first) mean = mean + p;
  mean = mean * (1.0 / double(first.size()));
  std::vector<Vec2> reference;
  for (Vec2 p : first) reference.push_back(p - mean);
  return reference;
}

// The element's placement keys among the candidates (docs/animation-formats.md, "The element's frame"):
// the least-squares similarity at each candidate (`fitted`), keyed where a player's straight (or eased)
// move of its parts from key to key strays from it by more than `tolerance` at any hull corner of the art.
void add_placement_keys(const std::vector<double>& frames, const std::vector<Vec2>& reference,
                        const std::vector<Placement>& fitted, const std::vector<char>& forced, double tolerance,
                        std::vector<double>& key_frames, std::vector<Placement>& placements, std::vector<Ease>& eases) {
  const std::vector<Vec2> hull = hull_of(reference);
  std::vector<std::vector<Vec2>> corners(fitted.size());  // the hull's corners where each fit puts them
  for (std::size_t c = 0; c < fitted.size(); ++c)
    for (Vec2 h : hull) corners[c].push_back(fitted[c].to_world(h));
  const auto fits = [&](std::size_t a, std::size_t b, Ease& ease) {
    const auto error = [&](const Ease& e) {
      double worst = 0.0;
      for (std::size_t c = a + 1; c < b && worst <= tolerance; ++c) {
        const Placement shown =
            placement_between(fitted[a], fitted[b], e.at((frames[c] - frames[a]) / (frames[b] - frames[a])));
        for (std::size_t h = 0; h < hull.size(); ++h)
          worst = std::max(worst, norm(shown.to_world(hull[h]) - corners[c][h]));
      }
      return worst;
    };
    return eased_fits(
        frames, a, b, tolerance, error, [&](std::vector<double>& share) { return shares_along(corners, a, b, share); },
        ease);
  };
  for (const auto& [k, ease] : chosen_keys(frames.size(), forced, fits)) {
    if (!key_frames.empty()) eases.push_back(ease);
    key_frames.push_back(frames[k]), placements.push_back(fitted[k]);
  }
}

// The stroke scale is the square root of the element's area ratio (element_scale), and the area is quadratic
// between two slices, while a player scales the stroke with the placement's scale (placement_at). The
// stroke keys are the ratio of the two, at the candidates and every frame between the first and the
// last, keyed as a path's points are (path_keys) to within the precision kept, so every frame's width is
// the PNG frame's.
void add_stroke_keys(const World& world, const SimState& state, int element, const std::vector<Vec2>& tangents,
                     const FrameOutput& out, double frames_per_unit, const std::vector<double>& candidate_frames,
                     const std::vector<ElementArt>& art, ElementKeys& keys) {
  const double tolerance = stroke_tolerance(world, element, out);
  if (tolerance == 0) {
    keys.stroke_frames = {0.0}, keys.stroke_scales = {1.0};
    return;
  }
  std::vector<std::pair<double, double>> samples;  // (frame, stroke scale)
  for (std::size_t k = 0; k < candidate_frames.size(); ++k)
    samples.emplace_back(candidate_frames[k], art[k].stroke_scale);
  for (int i = int(std::floor(candidate_frames.front())) + 1; i < candidate_frames.back() && i < out.count; ++i)
    if (std::none_of(candidate_frames.begin(), candidate_frames.end(),
                     [&](double f) { return std::abs(f - i) < 1e-9; }))
      samples.emplace_back(
          i, element_scale(world, element, element_at(world, state, element, i / frames_per_unit, tangents)));
  std::sort(samples.begin(), samples.end());
  std::vector<double> frames;
  std::vector<std::vector<Vec2>> ratio;
  double largest = 0.0;
  for (const auto& [frame, scale] : samples) {
    const double shown = placement_at(keys, frame).scale;
    largest = std::max(largest, shown);
    frames.push_back(frame), ratio.push_back({Vec2{scale / shown, 0.0}});
  }
  for (const auto& [k, ease] : path_keys(frames, ratio, std::vector<char>(frames.size(), 0), tolerance / largest)) {
    if (!keys.stroke_frames.empty()) keys.stroke_ease.push_back(ease);
    keys.stroke_frames.push_back(frames[k]), keys.stroke_scales.push_back(ratio[k][0].x);
  }
}

}  // namespace

ElementKeys still_keys(const ArtPoints& points) {
  ElementKeys keys;
  for (const auto& lines : points) {
    PathKeys& path = keys.paths.emplace_back();
    path.frames = {0.0}, path.lines = {lines};
  }
  keys.stroke_frames = {0.0}, keys.stroke_scales = {1.0};
  return keys;
}

Placement placement_at(const std::vector<double>& frames, const std::vector<Placement>& placements,
                       const std::vector<Ease>& ease, double frame) {
  if (frames.empty()) return {};
  const std::size_t next = std::size_t(std::upper_bound(frames.begin(), frames.end(), frame) - frames.begin());
  if (next == 0) return placements.front();
  if (next == frames.size()) return placements.back();
  const double a = frames[next - 1], b = frames[next];
  return placement_between(placements[next - 1], placements[next], ease[next - 1].at((frame - a) / (b - a)));
}

namespace {

// The farthest any point at a candidate, in a frame placed by `shown` there, lies from where `fixed` puts
// it (world units): how far writing the points once would draw them from the frames.
double stray(const std::vector<Placement>& shown, const std::vector<std::vector<Vec2>>& local,
             const std::vector<Vec2>& fixed) {
  double worst = 0.0;
  for (std::size_t k = 0; k < local.size(); ++k)
    for (std::size_t v = 0; v < fixed.size(); ++v)
      worst = std::max(worst, shown[k].scale * norm(local[k][v] - fixed[v]));
  return worst;
}

// About the bytes one key writes, for choosing between a path keyed in its element's frame and one with a
// frame of its own: a point of a Lottie shape key ("[x,y]" and two zero tangents), and a turn-and-move key
// (its position and angle keyframes).
constexpr std::size_t point_key_cost = 26, place_key_cost = 140;

// Every path's polylines at its keys as cubic Béziers (fit_beziers) within `tolerance_px` pixels when one
// world unit is `pixels` pixels: the points are local to the element's frame (and a path's own), so the
// tolerance in their units is the pixels over the largest scale the placements give them.
void add_curves(const ArtShape& art, double pixels, double tolerance_px, ElementKeys& keys) {
  double element_scale = 0.0;
  for (const Placement& at : keys.placements) element_scale = std::max(element_scale, at.scale);
  for (std::size_t p = 0; p < keys.paths.size(); ++p) {
    PathKeys& path = keys.paths[p];
    double own_scale = 1.0;
    for (const Placement& at : path.placements) own_scale = std::max(own_scale, at.scale);
    const double tolerance = tolerance_px / (pixels * element_scale * own_scale);
    path.curves.assign(path.lines.size(), {});
    for (std::size_t q = 0; q < art.paths[p].polylines.size(); ++q) {
      std::vector<std::vector<Vec2>> at_keys;
      for (const auto& lines : path.lines) at_keys.push_back(lines[q]);
      const std::vector<BezierLine> fitted = fit_beziers(at_keys, art.paths[p].polylines[q].closed, tolerance);
      for (std::size_t k = 0; k < fitted.size(); ++k) path.curves[k].push_back(fitted[k]);
    }
  }
}

// Element `element`'s keys, its art reflected across the container's mirror when `reflected` (a drawn
// mirror image): element_keys and drawn_keys.
ElementKeys keys_of(const World& world, const SimState& state, int element, const FrameOutput& out, bool reflected) {
  const auto art_at = [&](const std::vector<Vec2>& positions) {
    ElementArt art = element_art(world, element, positions);
    if (reflected)
      for (auto& lines : art.points)
        for (auto& line : lines)
          for (Vec2& p : line) p = world.container.mirror->reflect(p);
    return art;
  };
  ElementKeys keys;
  // A key of every path, and of the stroke, at `frame`, the art's world points (no placement).
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
    for (int i = 0; i < frames; ++i) add(i, art_at(element_at(world, state, element, times[i], tangents)));
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
  double tolerance = (key_tolerance_px - std::clamp(out.curve_tolerance, 0.0, 0.5)) / pixels;
  {
    const std::vector<Vec2> start = element_at(world, state, element, 0.0, tangents);
    double x0 = start.front().x, x1 = x0, y0 = start.front().y, y1 = y0;
    for (const Vec2& p : start)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    tolerance = std::min(tolerance, key_tolerance_share * std::max(x1 - x0, y1 - y0));
  }
  // The candidate times: every slice, and between two slices the steps of twice the parts in which
  // chords stay within the tolerance (key_parts; at least 8), so that checking the candidates checks the
  // curve and the element's turn and scale between slices (straight lines between slices turn a shape
  // along the chords, which no single similarity key pair draws), and every frame, so that each frame the
  // PNG frames draw is checked.
  std::vector<double> times;
  std::vector<ElementArt> art;  // the art at each candidate
  std::vector<char> slice;      // whether the candidate is a slice
  std::vector<Vec2> positions(P);
  for (int s = 0; s < lib.slice_count; ++s) {
    const int first = inst.vertex_begin + s * P;
    const double t = state.t[first];
    // Time springs keep slices apart; two at one time would be a jump, which no pair of keys draws.
    if (!times.empty() && frame_of(t) <= frame_of(times.back())) continue;
    if (!times.empty()) {
      const double before = times.back();
      const int candidates = std::max(8, 2 * key_parts(world, state, element, tangents, before, t, tolerance));
      std::vector<double> between;
      for (int j = 1; j < candidates; ++j) between.push_back(before + (t - before) * j / candidates);
      for (int i = int(std::floor(before * frames_per_unit)) + 1; i < t * frames_per_unit; ++i)
        between.push_back(i / frames_per_unit);
      std::sort(between.begin(), between.end());
      for (const double tj : between)
        if (frame_of(tj) > frame_of(times.back()) && frame_of(tj) < frame_of(t)) {
          times.push_back(tj), slice.push_back(0);
          art.push_back(art_at(element_at(world, state, element, tj, tangents)));
        }
    }
    for (int v = 0; v < P; ++v) positions[v] = {state.x[first + v], state.y[first + v]};
    times.push_back(t), slice.push_back(1), art.push_back(art_at(positions));
  }
  std::vector<double> key_frames;
  for (double t : times) key_frames.push_back(frame_of(t));
  // With straight lines between slices every slice is a corner of the motion: a key for every track.
  std::vector<char> forced(times.size(), 0);
  if (!cubic) forced = slice;
  const std::size_t paths = art.front().points.size();
  std::vector<std::vector<Vec2>> all(times.size());  // every point of the element at each candidate
  for (std::size_t k = 0; k < times.size(); ++k)
    for (std::size_t p = 0; p < paths; ++p) {
      const std::vector<Vec2> points = path_points(art[k], p);
      all[k].insert(all[k].end(), points.begin(), points.end());
    }
  keys.paths.resize(paths);
  if (all[0].empty()) {
    for (std::size_t k = 0; k < times.size(); ++k)
      if (slice[k]) add(key_frames[k], art[k]);
  } else {
    const std::vector<Vec2> reference = reference_of(all[0]);
    std::vector<Placement> fitted;
    for (const auto& at : all)
      fitted.push_back(fitted_placement(reference, at, fitted.empty() ? 0.0 : fitted.back().angle));
    // The placement's keys are cheap (a few numbers each, whatever the art): they keep the element within a
    // tenth of a pixel of where the fits place it, or a quarter of the tolerance where that is less, so
    // that a path moving with it is written once (the rest of the tolerance is its own) and still drawn
    // where the frames draw it.
    const double placement_tolerance = std::min(0.25 * tolerance, key_placement_px / pixels);
    add_placement_keys(key_frames, reference, fitted, forced, placement_tolerance, keys.frames, keys.placements,
                       keys.ease);
    std::vector<Placement> shown;  // the placement a player shows at each candidate
    double largest = 0.0;
    for (double f : key_frames) shown.push_back(placement_at(keys, f)), largest = std::max(largest, shown.back().scale);
    std::vector<char> strokes;
    for (const ArtPath& path : lib.art.art.paths) strokes.push_back(path.stroke.enabled && path.stroke_width > 0);
    for (std::size_t p = 0; p < paths; ++p) {
      std::vector<std::vector<Vec2>> local(times.size());
      std::vector<Vec2> mean;
      for (std::size_t k = 0; k < times.size(); ++k) {
        for (Vec2 q : path_points(art[k], p)) local[k].push_back(shown[k].to_local(q));
        mean.resize(local[k].size(), Vec2{0, 0});
        for (std::size_t v = 0; v < mean.size(); ++v) mean[v] = mean[v] + local[k][v] * (1.0 / double(times.size()));
      }
      PathKeys& path = keys.paths[p];
      if (stray(shown, local, mean) <= tolerance) {
        path.frames.push_back(0.0), path.lines.push_back(as_lines(mean, art[0].points[p]));
        continue;
      }
      // Keyed in the element's frame, or given a frame of its own that turns, moves and, unless it is
      // stroked (its stroke widths follow the element's scale alone), scales within it (a part of a
      // bending element), keyed in that where it still changes shape: whichever writes fewer numbers.
      const auto keyed = path_keys(key_frames, local, forced, tolerance / largest);
      PathKeys own;
      std::vector<std::vector<Vec2>> in_own;
      std::size_t own_cost = std::numeric_limits<std::size_t>::max();
      if (mean.size() >= 8) {
        const std::vector<Vec2> shape = reference_of(mean);
        std::vector<Placement> fitted_own;
        for (const auto& at : local)
          fitted_own.push_back(
              fitted_placement(shape, at, fitted_own.empty() ? 0.0 : fitted_own.back().angle, strokes[p]));
        add_placement_keys(key_frames, shape, fitted_own, forced, placement_tolerance / largest, own.place_frames,
                           own.placements, own.place_ease);
        std::vector<Vec2> own_mean(mean.size(), Vec2{0, 0});
        std::vector<Placement> own_shown;
        for (std::size_t k = 0; k < times.size(); ++k) {
          const Placement at = placement_at(own.place_frames, own.placements, own.place_ease, key_frames[k]);
          own_shown.push_back({at.position, at.angle, at.scale * shown[k].scale});
          in_own.emplace_back();
          for (Vec2 q : local[k]) in_own.back().push_back(at.to_local(q));
          for (std::size_t v = 0; v < mean.size(); ++v)
            own_mean[v] = own_mean[v] + in_own.back()[v] * (1.0 / double(times.size()));
        }
        if (stray(own_shown, in_own, own_mean) <= tolerance) {
          own.frames.push_back(0.0), own.lines.push_back(as_lines(own_mean, art[0].points[p]));
        } else {
          for (const auto& [k, ease] : path_keys(key_frames, in_own, forced, tolerance / largest)) {
            if (!own.frames.empty()) own.ease.push_back(ease);
            own.frames.push_back(key_frames[k]), own.lines.push_back(as_lines(in_own[k], art[k].points[p]));
          }
        }
        own_cost = own.place_frames.size() * place_key_cost + own.frames.size() * mean.size() * point_key_cost;
      }
      if (own_cost < keyed.size() * mean.size() * point_key_cost) {
        path = std::move(own);
        continue;
      }
      for (const auto& [k, ease] : keyed) {
        if (!path.frames.empty()) path.ease.push_back(ease);
        path.frames.push_back(key_frames[k]), path.lines.push_back(as_lines(local[k], art[k].points[p]));
      }
    }
    add_stroke_keys(world, state, element, tangents, out, frames_per_unit, key_frames, art, keys);
  }
  // A document that does not loop shows its last slice through its last frame, up to op = N.
  if (key_frames.back() < frames) {
    if (keys.frames.empty()) {
      add(frames, art.back());
    } else {
      keys.frames.push_back(frames), keys.placements.push_back(keys.placements.back()), keys.ease.emplace_back();
      for (PathKeys& path : keys.paths) {
        if (path.frames.size() > 1)
          path.frames.push_back(frames), path.lines.push_back(path.lines.back()), path.ease.emplace_back();
        if (path.place_frames.size() > 1)
          path.place_frames.push_back(frames), path.placements.push_back(path.placements.back()),
              path.place_ease.emplace_back();
      }
      if (keys.stroke_frames.size() > 1)
        keys.stroke_frames.push_back(frames), keys.stroke_scales.push_back(keys.stroke_scales.back()),
            keys.stroke_ease.emplace_back();
    }
  }
  if (!keys.frames.empty() && out.curve_tolerance > 0)
    add_curves(lib.art.art, pixels, std::min(out.curve_tolerance, 0.5), keys);
  return keys;
}

}  // namespace

// Frame i shows t = i / N when looping, i / (N − 1) otherwise (frame_times). Every art point is a fixed
// barycentric combination of three vertices of one triangle (replay_art), and the art follows the
// vertices' curve between slices (element_at): the element is placed where a similarity fitted to all its
// points puts it, keyed where a player's move from key to key needs it, and each path is written once in
// that frame when it moves with it, keyed where its change of shape needs it otherwise (keys_of).
// The first slice is at t = 0 and the last at t = 1 (the end-to-end constraint), so linear keys span the
// document, the last at frame N when looping.
ElementKeys element_keys(const World& world, const SimState& state, int element, const FrameOutput& out) {
  return keys_of(world, state, element, out, false);
}

ElementKeys drawn_keys(const World& world, const SimState& state, int drawn, const FrameOutput& out) {
  return keys_of(world, state, drawn_source(world, drawn), out, drawn >= int(world.elements.size()));
}

}  // namespace animpak::frame_writers
