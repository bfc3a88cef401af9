// Internal to src/scene: where every instance goes, before the topology is assembled.
#pragma once

#include <vector>

#include "animpak/scene.hpp"

namespace animpak::scene_detail {

/// Per-slice similarity transform of one instance: p' = offset[s] + scale[s] · R(angle[s]) · (p − pivot).
struct Placement {
  int library = 0;
  std::string name;
  bool guided = false;
  Vec2 pivot;  ///< the library element's rest centroid (unit element coordinates)
  std::vector<Vec2> offset;
  std::vector<double> scale, angle;
  int anchor = -1;         ///< slice vertex pulled to the targets (guided only)
  std::vector<Vec2> path;  ///< the anchor's initial position per slice (guided only)
  /// A target acting on one slice (paper §4): the anchor's target point, and whether the target gives
  /// an angle that the slice's orientation is held to.
  struct Key {
    int slice = 0;
    Vec3f point;
    bool hold_angle = false;
  };
  std::vector<Key> keys;   ///< one per target, in slice order (guided only)
  int loop_partner = -1;   ///< instance whose first slice this one's last slice meets
  int phase = 0;           ///< slices by which its animation is ahead round the loop (unguided only)
  bool secondary = false;  ///< a secondary element (unguided only; docs/parameters.md, "Secondary elements")
  Vec2 seed;               ///< where its rest centroid was seeded (unguided only; `offset` may step aside)
};

Vec2 apply(const Placement& p, int slice, Vec2 q);

/// Slice vertex v of instance p at slice s: its library element's animated vertex `phase` slices on
/// round the loop (slice n - 1 is slice 0 again), placed by `apply`.
Vec2 placed(const Placement& p, const SpacetimeElement& e, int s, int v);

/// Area centroid of the boundary ring of the rest slice.
Vec2 rest_centroid(const SpacetimeElement& e);

/// Guided placements, in scene order. InputError for a target outside the container or in a hole, or
/// two targets on one slice; a note warns when the straight path between two targets leaves it.
std::vector<Placement> place_guided(const SceneSpec& scene, const Container& container,
                                    const std::vector<SpacetimeElement>& library, std::vector<std::string>& notes);

/// Unguided placements on blue-noise seeds, avoiding the guided elements' trajectories.
std::vector<Placement> place_unguided(const SceneSpec& scene, const Container& container,
                                      const std::vector<SpacetimeElement>& library,
                                      const std::vector<Placement>& guided, Rng& rng, std::vector<std::string>& notes);

/// Unguided elements make way for guided ones (docs/parameters.md, "Making way"): each one's offsets
/// become a path that steps aside while a traveller passes, periodic in a looping scene, its rest
/// centroid never nearer the wall than `margin`. Nothing changes without guided elements or with
/// params.make_way 0. make_way.cpp.
void make_way(const SceneSpec& scene, const Container& container, const std::vector<SpacetimeElement>& library,
              const std::vector<Placement>& guided, std::vector<Placement>& unguided, double margin);

/// A scene that sets no initial_scale and crowds the default starts at this share of the largest that places
/// (docs/first-scene.md, "When the elements do not fit").
inline constexpr double kPickedScaleShare = 0.9;

/// For a scene that does not set params.initial_scale and whose unguided elements do not all place at the
/// default: kPickedScaleShare × the largest initial_scale at which they do (rounded down to three significant digits,
/// and placing), searched on the placement itself. Empty when the scene sets initial_scale, seeds as many
/// as fit, places at its initial_scale already, or places at no initial_scale in the parameter's range.
std::optional<double> picked_initial_scale(const SceneSpec& scene, const Container& container,
                                           const std::vector<SpacetimeElement>& library, const Rng& unguided_rng);

/// Throws InputError naming the elements and slice where two shrunken elements overlap or one leaves
/// the container (for a guided element: on a slice of one of its targets). When unguided elements overlap
/// in a scene that asks for a number of them, the error says how many fit instead: it places fewer from
/// `unguided_rng` (the generator place_unguided was given, as it was then) until they do.
void check_placements(const SceneSpec& scene, const Container& container, const std::vector<SpacetimeElement>& library,
                      const std::vector<Placement>& placements, const Rng& unguided_rng);

}  // namespace animpak::scene_detail
