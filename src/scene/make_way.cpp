// Unguided elements make way for guided ones (docs/parameters.md, "Making way"). The paper (§4) keeps
// every unguided seed off a guided element's whole volume, which for a straight tube is every point the
// traveller ever crosses: the route stays an empty band in every frame. Here seeds cover the whole
// container, and each unguided element starts on a path that steps aside while a traveller passes and
// comes back after: per slice, the crowd is relaxed as discs of the elements' expected full sizes, each
// tied to its seed, pushed out of every traveller's footprint at that time, apart from each other and off
// the wall, warm-started from the slice before and run round the loop until it closes. The crowd moves
// as a whole, as a 2D granular packing or a foam flows round an intruder.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "placement.hpp"

namespace animpak::scene_detail {
namespace {

// Relaxation rounds per slice, and the share of the way back to its seed a disc moves each round: with
// contacts projected fully, a tie of 0.15 lets a push die out within about two or three discs, as the
// disturbance round an intruder does in a 2D granular packing.
constexpr double tie = 0.15;
// A slice interval is crossed in `substeps` steps of `rounds_per_substep` rounds; the first slice settles
// from the seeds in `settle_rounds`.
constexpr int substeps = 6;
constexpr int rounds_per_substep = 30;
constexpr int settle_rounds = 200;
// Projections of the hard limits after every round.
constexpr int hard_sweeps = 3;
constexpr double wall_spare = 1.3;
// The share of a traveller's push that would carry a disc ahead of it which goes sideways instead.
constexpr double sideways = 0.7;
// A traveller's footprint is its outline at this many times the crowd's expected growth: at the same growth
// the crowd closed in round it and the travellers took the squeeze (aquatic-loop's penguins ended at mean g
// 1.13 and 1.76, the other elements' median 2.39; at 1.25, 2.21 and 1.99: docs/results.md, "0.15.0: making
// way for travellers (off by default)").
constexpr double traveller_room = 1.25;
// An element's script dips fully where its disc touches a traveller's footprint, and not at all from
// `dip_reach` disc radii away.
constexpr double dip_reach = 2.0;
// Smoothing passes of the finished paths along t ([1/4, 1/2, 1/4]), so that a disc that slips from one
// side of its neighbour to the other does not jerk the element's start.
constexpr int smoothing_passes = 3;

struct Nearest {
  Vec2 point;
  double distance = std::numeric_limits<double>::infinity();
};

// The point of `ring`'s outline nearest to p (or `best`, when that is nearer), with its distance; where only
// the distance counts, ring_distance (animpak/geometry.hpp) gives the same number.
Nearest nearest_on_ring(const std::vector<Vec2>& ring, Vec2 p, Nearest best = {}) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 q = closest_on_segment(p, ring[i], ring[(i + 1) % ring.size()]);
    if (const double d = norm(p - q); d < best.distance) best = {q, d};
  }
  return best;
}

Nearest nearest_on_wall(const Container& c, Vec2 p) {
  Nearest best = nearest_on_ring(c.outline, p);
  for (const auto& hole : c.holes) best = nearest_on_ring(hole, p, best);
  return best;
}

// Moves `p` out of `ring` (a traveller's footprint) to at least `clearance` from its outline.
Vec2 out_of(const std::vector<Vec2>& ring, Vec2 p, double clearance) {
  const bool inside = ring_contains(ring, p);
  const Nearest n = nearest_on_ring(ring, p);
  if (!inside && n.distance >= clearance) return p;
  if (!(n.distance > 0)) return p;  // on the outline itself: no direction; the next round moves it
  const Vec2 away = (inside ? -1.0 : 1.0) / n.distance * (p - n.point);
  return n.point + clearance * away;
}

// `p` moved to at least `room` from the wall and inside the container, along the wall's normal; `p`
// itself when it is there already, nothing when the wall's normal does not lead there (a concave corner).
std::optional<Vec2> with_room(const Container& c, Vec2 p, double room) {
  const bool inside = c.contains(p);
  const Nearest n = nearest_on_wall(c, p);
  if (inside && n.distance >= room) return p;
  if (!(n.distance > 0)) return std::nullopt;
  const Vec2 q = n.point + room * ((inside ? 1.0 : -1.0) / n.distance * (p - n.point));
  if (c.contains(q) && c.distance_to_boundary(q) >= 0.999 * room) return q;
  return std::nullopt;
}

double ring_area(const SpacetimeElement& e) {
  std::vector<Vec2> ring(e.slice.vertices.begin(), e.slice.vertices.begin() + e.slice.boundary_count);
  return std::abs(signed_area(ring));
}

using Rings = std::vector<std::vector<Vec2>>;

// The travellers at one time: their footprints at the expected size (soft: the crowd's discs keep out of
// them) and shrunken as placed (hard: the shrunken elements must not meet them), each one's heading and
// its anchor's path point.
struct Travellers {
  Rings grown, shrunken;
  std::vector<Vec2> heading, centre;
};

// Each vertex on the straight line from `a` to `b`, at `u`.
Rings between(const Rings& a, const Rings& b, double u) {
  Rings out = a;
  for (std::size_t k = 0; k < out.size(); ++k)
    for (std::size_t v = 0; v < out[k].size(); ++v) out[k][v] = out[k][v] + u * (b[k][v] - out[k][v]);
  return out;
}

// One pass of [1/4, 1/2, 1/4] along t over a value per slice (round the loop, or held at the ends; a loop's
// last slice is its first), each smoothed value stored as `keep(s, smoothed)` gives it.
template <class T, class Keep>
std::vector<T> smoothed(const std::vector<T>& series, bool loop, Keep keep) {
  const int slices = static_cast<int>(series.size()), period = loop ? slices - 1 : slices;
  std::vector<T> out = series;
  for (int s = 0; s < period; ++s) {
    const int before = s > 0 ? s - 1 : (loop ? period - 1 : 0), after = s + 1 < period ? s + 1 : (loop ? 0 : s);
    out[s] = keep(s, 0.25 * series[before] + 0.5 * series[s] + 0.25 * series[after]);
  }
  if (loop) out[slices - 1] = out[0];
  return out;
}

// The unguided elements as discs of their expected full sizes round their centres `x`, relaxed at one time
// after another (docs/parameters.md, "Making way").
class Crowd {
 public:
  Crowd(const Container& container, double margin) : container_(container), margin_(margin) {}

  void add(Vec2 seed, double radius) {
    seed_.push_back(seed);
    x.push_back(seed);
    radius_.push_back(radius);
    const double from_wall = container_.distance_to_boundary(seed);
    // A disc keeps its full radius from the wall, or its seed's distance where the seed sits nearer: a
    // seed is never pushed off the wall when no traveller is near.
    room_.push_back(std::max(margin_, std::min(radius, from_wall)));
    // The hard limit keeps a little more than the margin where the seed allows: the curve between slices
    // (docs/parameters.md, "Motion between slices") bulges slightly past a path that slides along the wall.
    wall_.push_back(std::max(margin_, std::min(wall_spare * margin_, from_wall)));
  }

  double radius(std::size_t i) const { return radius_[i]; }

  /// `rounds` rounds of the relaxation round the travellers `t`.
  void relax(const Travellers& t, int rounds) {
    const std::size_t n = x.size();
    const double max_step = 0.5 * margin_;
    for (int round = 0; round < rounds; ++round) {
      const std::vector<Vec2> before = x;
      for (std::size_t i = 0; i < n; ++i) x[i] = x[i] + tie * (seed_[i] - x[i]);
      separate([&](std::size_t i, std::size_t j) { return radius_[i] + radius_[j]; });
      // Out of every traveller's way, then the wall's room, then the hard limit: a centre at least `margin`
      // inside, so the shrunken element is. The wall is rigid and a traveller is not (it deforms and
      // shrinks like any element), so between the two a disc keeps its room from the wall and overlaps the
      // traveller's expected footprint instead; pushed against the wall, it keeps the push's share along
      // the wall and slides round the traveller.
      for (std::size_t i = 0; i < n; ++i) {
        Vec2 q = x[i];
        // No disc moves more than `max_step` a round, so none tunnels through a thin traveller or snaps
        // home through the crowd.
        if (const Vec2 step = q - before[i]; norm(step) > max_step) q = before[i] + (max_step / norm(step)) * step;
        for (std::size_t k = 0; k < t.grown.size(); ++k) {
          // Out of the traveller's way, but what would push the disc ahead of it goes to the side the disc
          // is on instead: the crowd flows round an intruder rather than being carried along.
          Vec2 push = out_of(t.grown[k], q, radius_[i]) - q;
          const Vec2 v = t.heading[k], side{-v.y, v.x};
          if (const double ahead = dot(push, v); ahead > 0) {
            const double sign = dot(q - t.centre[k], side) >= 0 ? 1.0 : -1.0;
            push = push - (sideways * ahead) * v + (sign * sideways * ahead) * side;
          }
          q = q + push;
        }
        q = with_room(container_, q, room_[i]).value_or(q);
        if (const std::optional<Vec2> inside = with_room(container_, q, wall_[i])) x[i] = *inside;
      }
      keep_apart(t.shrunken);
    }
  }

  /// Whether element i's centre at `q` keeps the hard limits against `others` (the other centres at the
  /// same time) and the shrunken travellers `small`.
  bool allowed(std::size_t i, Vec2 q, const std::vector<Vec2>& others, const Rings& small) const {
    for (std::size_t j = 0; j < others.size(); ++j)
      if (j != i && norm(q - others[j]) < 2.0 * margin_) return false;
    for (const std::vector<Vec2>& ring : small)
      if (ring_contains(ring, q) || ring_distance(ring, q) < margin_) return false;
    return container_.contains(q) && container_.distance_to_boundary(q) >= margin_;
  }

  std::vector<Vec2> x;  ///< the centres now

 private:
  // Every overlapping pair pushed apart, each by half the overlap, in index order.
  template <class Reach>
  void separate(Reach reach) {
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = i + 1; j < x.size(); ++j) {
        const Vec2 d = x[j] - x[i];
        const double dist = norm(d), overlap = reach(i, j) - dist;
        if (!(overlap > 0) || !(dist > 0)) continue;
        const Vec2 push = (0.5 * overlap / dist) * d;
        x[i] = x[i] - push;
        x[j] = x[j] + push;
      }
  }

  // The hard limits, projected in turn: shrunken elements apart (`margin` holds any of them round its
  // centroid), out of the shrunken travellers, inside.
  void keep_apart(const Rings& small) {
    for (int sweep = 0; sweep < hard_sweeps; ++sweep) {
      separate([&](std::size_t, std::size_t) { return 2.0 * margin_; });
      for (std::size_t i = 0; i < x.size(); ++i) {
        Vec2 q = x[i];
        for (const std::vector<Vec2>& ring : small) q = out_of(ring, q, margin_);
        if (const std::optional<Vec2> inside = with_room(container_, q, wall_[i])) x[i] = *inside;
      }
    }
  }

  const Container& container_;
  const double margin_;
  std::vector<Vec2> seed_;
  std::vector<double> radius_, room_, wall_;
};

// How deep `q` lies in `grown` footprints for a disc of radius r: the most by which it is nearer one than r.
double depth(const Rings& grown, Vec2 q, double r) {
  double d = 0.0;
  for (const std::vector<Vec2>& ring : grown)
    d = std::max(d, ring_contains(ring, q) ? r + ring_distance(ring, q) : r - ring_distance(ring, q));
  return d;
}

}  // namespace

void make_way(const SceneSpec& scene, const Container& container, const std::vector<SpacetimeElement>& library,
              const std::vector<Placement>& guided, std::vector<Placement>& unguided, double margin) {
  const double share = scene.params.placement.make_way;
  if (!(share > 0) || guided.empty() || unguided.empty()) return;
  const int slices = static_cast<int>(unguided.front().offset.size());
  const int intervals = slices - 1;
  const double s0 = scene.params.placement.initial_scale;

  // The growth g at which the elements' outlines (channel included) would cover `share` of the container.
  double area = 0.0;
  for (const Placement& p : guided) area += ring_area(library[p.library]) * p.scale.front() * p.scale.front();
  for (const Placement& p : unguided) area += ring_area(library[p.library]) * s0 * s0;
  if (!(area > 0)) return;
  const double g = std::min(std::sqrt(share * container.area() / area), scene.params.growth.max_growth);

  const std::size_t n = unguided.size();
  Crowd crowd(container, margin);
  for (const Placement& p : unguided)
    crowd.add(p.offset.front(), s0 * g * std::sqrt(ring_area(library[p.library]) / std::numbers::pi));

  // The travellers at every slice: each one's placed outline, grown by traveller_room · g about its anchor's
  // path point and as placed, and its heading over the interval that starts there (the last one's for the last slice).
  std::vector<Travellers> at(slices);
  for (int s = 0; s < slices; ++s)
    for (const Placement& p : guided) {
      const SpacetimeElement& e = library[p.library];
      std::vector<Vec2> grown, shrunken;
      for (int v = 0; v < e.slice.boundary_count; ++v) {
        const Vec2 q = placed(p, e, s, v);
        grown.push_back(p.path[s] + traveller_room * g * (q - p.path[s]));
        shrunken.push_back(q);
      }
      at[s].grown.push_back(std::move(grown));
      at[s].shrunken.push_back(std::move(shrunken));
      const int a = std::min(s, slices - 2);
      const Vec2 d = p.path[a + 1] - p.path[a];
      at[s].heading.push_back(norm(d) > 0 ? (1.0 / norm(d)) * d : Vec2{0.0, 0.0});
      at[s].centre.push_back(p.path[s]);
    }
  // Between slices s and s + 1 at u, each footprint vertex on the straight line between them.
  const auto at_time = [&](int s, double u) {
    return Travellers{between(at[s].grown, at[s + 1].grown, u), between(at[s].shrunken, at[s + 1].shrunken, u),
                      at[s].heading, at[s].centre};
  };

  // From slice to slice in substeps, so that a traveller never jumps over a disc in its way: the disc is
  // pushed aside, and its start never crosses the traveller's between two slices. Round the loop twice,
  // the second time warm-started from the end of the first, so that the last slice leads into the first;
  // without a loop, once from the seeds.
  std::vector<std::vector<Vec2>> path(slices);  // [slice] → centres
  crowd.relax(at[0], settle_rounds);
  for (int pass = scene.loop ? 0 : 1; pass < 2; ++pass) {
    path[0] = crowd.x;
    for (int s = 0; s < intervals; ++s) {
      for (int k = 1; k <= substeps; ++k) crowd.relax(at_time(s, double(k) / substeps), rounds_per_substep);
      path[s + 1] = crowd.x;
    }
  }
  if (scene.loop) path[slices - 1] = path[0];

  // Smoothed along t, element after element against the others' latest: a smoothed point must keep the
  // hard limits and lie no deeper in a traveller's way.
  for (int pass = 0; pass < smoothing_passes; ++pass)
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<Vec2> mine(slices);
      for (int s = 0; s < slices; ++s) mine[s] = path[s][i];
      mine = smoothed(mine, scene.loop, [&](int s, Vec2 q) {
        const double r = crowd.radius(i);
        const bool keeps = crowd.allowed(i, q, path[s], at[s].shrunken) &&
                           depth(at[s].grown, q, r) <= std::max(0.0, depth(at[s].grown, path[s][i], r));
        return keeps ? q : path[s][i];
      });
      for (int s = 0; s < slices; ++s) path[s][i] = mine[s];
    }

  // A size that gives way (params.make_way_dip): where a traveller's footprint comes within `dip_reach`
  // disc radii of an element's disc, the element's script is scaled down, by 1 / make_way_dip where they
  // touch, so that the slices it would be squeezed at no longer hold the whole loop small (growth_ratio
  // holds every slice's g to its smallest). The dip is smoothed along t (never below its own value).
  const double dip = scene.params.placement.make_way_dip;
  for (std::size_t i = 0; i < n; ++i) {
    for (int s = 0; s < slices; ++s) unguided[i].offset[s] = path[s][i];
    if (!(dip > 1.0)) continue;
    const double r = crowd.radius(i);
    std::vector<double> closeness(slices, 0.0);
    for (int s = 0; s < slices; ++s)
      for (const std::vector<Vec2>& ring : at[s].grown) {
        const double d = ring_contains(ring, path[s][i]) ? 0.0 : ring_distance(ring, path[s][i]);
        closeness[s] = std::max(closeness[s], std::clamp((dip_reach * r - d) / ((dip_reach - 1.0) * r), 0.0, 1.0));
      }
    for (int pass = 0; pass < smoothing_passes; ++pass)
      closeness = smoothed(closeness, scene.loop, [&](int s, double c) { return std::max(closeness[s], c); });
    for (int s = 0; s < slices; ++s) unguided[i].scale[s] = s0 / (1.0 + (dip - 1.0) * closeness[s]);
  }
}

}  // namespace animpak::scene_detail
