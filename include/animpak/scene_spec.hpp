// The scene file as parsed and validated by src/io (docs/scene-format.md documents every field).
// Art paths are already resolved against the scene file's folder. Nothing here is built yet.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "animpak/geometry.hpp"
#include "animpak/params.hpp"

namespace animpak {

/// The scene format this program reads: a scene file's optional `"version"` may not be larger. Raised
/// only when an older animpak would misread a newer file (a field whose meaning changes), not when keys
/// are added, since an older program already rejects keys it does not know.
inline constexpr int kSceneFormatVersion = 1;

/// What one scene may build (docs/cli.md, "Limits"), refused before anything is built. Library
/// entries: the examples list at most 5, and each entry is built once, used or not.
inline constexpr int kMaxLibraryElements = 1000;
/// Elements (unguided and guided copies): the largest example has 37; seeding and the placement
/// checks grow faster than linearly with it.
inline constexpr int kMaxSceneElements = 10000;
/// Mesh vertices over every slice of every element and library element: the largest example has
/// 101,200; a packing holds about 0.9 KB per vertex at its peak (measured: 1.16 GB for 1.32 million),
/// so this keeps it under about 9 GB.
inline constexpr double kMaxSceneVertices = 10'000'000;

/// A keyed similarity transform of the whole element, applied about the pivot.
struct TransformKey {
  double t = 0.0;            ///< animation time in [0, 1]
  Vec2 translate{0.0, 0.0};  ///< in art units
  double rotate = 0.0;       ///< degrees, clockwise on screen (y down)
  double scale = 1.0;        ///< uniform, > 0
};

/// A keyed position of one vertex handle.
struct HandleKey {
  double t = 0.0;  ///< animation time in [0, 1]
  Vec2 position;   ///< art coordinates
};

/// A point of the art bound to its nearest slice vertex; its keys drive an ARAP deformation.
struct HandleSpec {
  Vec2 point;  ///< art coordinates of the handle in the undeformed art
  std::vector<HandleKey> keys;
};

enum class AnimationPreset { none, rotate, pulse, swim };

struct AnimationSpec {
  AnimationPreset preset = AnimationPreset::none;
  double turns = 1.0;         ///< rotate: turns per loop; negative turns the other way
  double amplitude = 0.15;    ///< pulse: relative scale change; swim: bend as a fraction of the body length
  int count = 1;              ///< pulse: pulses per loop; swim: waves passing per loop
  double wavelength = 1.0;    ///< swim: wave length as a fraction of the body length
  bool loop = true;           ///< splines are periodic and t = 1 equals t = 0
  std::optional<Vec2> pivot;  ///< art coordinates; default: the centroid of the element's outline
  std::vector<TransformKey> keys;
  std::vector<HandleSpec> handles;
};

struct ContainerSpec {
  std::filesystem::path art;
  std::optional<int> outline;             ///< source index of the outline path; default: the largest path not a hole
  std::optional<std::vector<int>> holes;  ///< source indices; default: `.path` type-7 paths, none for SVG
  /// Its motion as a whole (docs/scene-format.md, "A container that moves"): the `rotate` or `pulse`
  /// preset or transform keys, about `pivot` (container art coordinates; default: the outline's area
  /// centroid); `loop` is the scene's. None: it stands still.
  AnimationSpec animation;
  /// The elements take the container's change of scale into their scripts (a beating container's
  /// elements beat with it); false: they keep their scripted size.
  bool inherit_scale = true;
};

struct LibraryElementSpec {
  std::string name;  ///< unique; defaults to the art file's stem
  std::filesystem::path art;
  /// Selectors of the SVG elements left out of the art, from its outline and its drawing alike
  /// (SvgOptions::exclude; docs/scene-format.md, "Leaving pieces of the art out").
  std::vector<std::string> exclude;
  AnimationSpec animation;
  std::optional<int> count;  ///< exact number of unguided copies; otherwise drawn by weight
  double weight = 1.0;
  /// When each unguided copy's animation starts, as a share of the loop: every copy at `phase`, or with
  /// `random_phase` each at its own slice drawn from the seed (docs/scene-format.md, "Phase").
  double phase = 0.0;
  bool random_phase = false;
  /// Its copies are secondary elements (docs/parameters.md, "Secondary elements"): they keep their start
  /// size while the primary elements grow, give way to them, and grow once they have stopped.
  bool secondary = false;
};

struct TargetSpec {
  double x = 0.0, y = 0.0;      ///< container art coordinates
  double t = 0.0;               ///< in [0, 1]; the first target has t = 0 and the last t = 1
  std::optional<double> scale;  ///< relative to the element's packed size
  std::optional<double> angle;  ///< degrees
};

struct GuidedSpec {
  std::string name;     ///< unique among guided elements
  std::string element;  ///< name of a library element
  std::vector<TargetSpec> targets;
  std::string loop_to;  ///< guided element whose t = 0 slice this one's t = 1 slice meets; empty: itself
  /// `"orient": "path"`: its slices turn to face along the path (docs/scene-format.md, "Facing along the
  /// path"), the art's `facing` direction (degrees, as drawn) along the path's; targets' angles still win.
  bool orient_path = false;
  double facing = 0.0;
};

enum class OrientationMode { random, fixed, field };
enum class FieldKind { constant, radial, tangential };

struct OrientationSpec {
  OrientationMode mode = OrientationMode::random;
  double angle = 0.0;  ///< fixed: degrees; field constant: the field's direction
  FieldKind field = FieldKind::constant;
  Vec2 center{250.0, 250.0};  ///< radial/tangential: container art coordinates
};

/// Mirror symmetry (docs/scene-format.md, "Mirror"): only one side of a vertical or horizontal line is
/// simulated, the line acting as a wall, and the frames draw that side and its reflection.
struct MirrorSpec {
  bool vertical = true;  ///< the line x = `at` (true) or y = `at`
  double at = 0.0;       ///< container art coordinates
  bool keep_low = true;  ///< simulate the side of smaller x (left) or y (top); false: the other side
};

struct SceneSpec {
  std::filesystem::path file;  ///< the scene file itself, for messages
  ContainerSpec container;
  std::vector<LibraryElementSpec> elements;
  std::vector<GuidedSpec> guided;
  OrientationSpec orientation;
  std::optional<MirrorSpec> mirror;  ///< none: the whole container is simulated
  std::optional<int> count;          ///< unguided elements to seed; default: as many as fit ("fill")
  std::uint64_t seed = 1;
  bool loop = true;  ///< loop constraint on: the t = 1 plane meets the t = 0 plane
  Params params;     ///< paper constants with the scene's overrides applied
  /// The scene sets params.initial_scale itself. When it does not and the default crowds the elements
  /// it asks for, build_world starts them smaller (docs/first-scene.md, "When the elements do not fit").
  bool initial_scale_given = false;
};

/// Reads, parses and validates a scene file. Errors are InputError with the file and the field path,
/// e.g. `scene.json: elements[2].animation.keys[0].t: expected a number in [0, 1], got 1.5`.
SceneSpec load_scene(const std::filesystem::path& file);

/// The guided element's path leaves its start and ends there again, within the 1e-6 art units a loop
/// allows; one held in place (every target at its start) does not. Such a path is a closed curve whether
/// or not the scene loops (docs/scene-format.md, "`guided[i]`").
bool ends_where_it_starts(const GuidedSpec& guided);

/// What a scene that parses may still not mean, one line each without "warning: " (build_world adds them
/// to its notes, `check` prints them): a guided element whose path leaves its start and ends there again,
/// within the 1e-6 art units a loop allows, in a scene that does not loop (docs/scene-format.md,
/// "`guided[i]`").
std::vector<std::string> scene_warnings(const SceneSpec& scene);

/// Where an art reference is read from: given the reference as written in the scene and `resolved`, that
/// reference against the base folder, returns the file to read (a packed folder's copy: docs/cli.md,
/// "The output folder").
using ArtLocator =
    std::function<std::filesystem::path(const std::string& written, const std::filesystem::path& resolved)>;

/// Same, from text in memory; relative art paths resolve against `base_dir`, then through `locate` if given.
SceneSpec parse_scene(const std::string& text, const std::filesystem::path& file_for_messages,
                      const std::filesystem::path& base_dir, const ArtLocator& locate = {});

/// The slices of a still reference: nothing moves, so more slices only cost time, and 12 are enough for
/// the collision grid to see each slice's time neighbours (fewer than about 10 are not; `pack` warns).
inline constexpr int still_slices = 12;

/// The still reference of `scene` (whose text is `text`), as scene text: every element's animation and
/// phase removed, each guided element turned into one more ordinary copy of its library element (its
/// count, or the scene's, one higher), and at most 12 slices; everything else, the seed included, as it
/// was (docs/quality.md, "Still reference"). An animated container stands still at its rest place, scaled
/// by `container_scale` about its pivot (the caller's mean of its scale over the loop: ContainerMotion's
/// mean_scale). still_scene.cpp.
std::string still_scene_text(const std::string& text, const SceneSpec& scene, double container_scale = 1.0);

/// The JSON Schema (draft 2020-12) of the scene file, written from the tables the parser checks keys,
/// types and ranges with; docs/scene.schema.json is its output.
std::string scene_json_schema();

}  // namespace animpak
