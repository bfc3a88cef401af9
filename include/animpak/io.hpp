// Art import: vector art from SVG files and from the RepulsionPak/AnimationPak `.path` format, as
// flattened polylines with their paint, in the art's own coordinates (y down).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animpak/error.hpp"
#include "animpak/geometry.hpp"

namespace animpak {

/// Straight RGBA colour, each channel in [0, 1].
struct Rgba {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
};

/// A fill or a stroke: absent, or one flat colour (gradients are reduced to a representative colour).
struct Paint {
  bool enabled = false;
  Rgba color;
};

enum class FillRule { nonzero, evenodd };
enum class PaintOrder { fill_then_stroke, stroke_then_fill };

/// One flattened subpath.
struct Polyline {
  std::vector<Vec2> points;  ///< the closing segment is implied when closed; the first point is not repeated
  bool closed = true;
};

/// One SVG element a path is drawn through: its tag, id and classes (each may be empty).
struct ArtOrigin {
  std::string tag;
  std::string id;
  std::vector<std::string> classes;
};

/// One drawable path: one or more subpaths painted together under one style.
struct ArtPath {
  std::string id;  ///< SVG id (or "path<N>" for .path files); used in messages
  /// SVG: the elements the path is drawn through, outermost first, from the root's child down to its own
  /// element (a `<use>` is followed by what it draws); empty for .path files. `animpak check` names the
  /// pieces of the art with it and the `exclude` entry that leaves one out.
  std::vector<ArtOrigin> lineage;
  int source_index = 0;  ///< position of the path in its file (0-based), stable for scene references
  int path_type = 0;     ///< `.path` pathType (0 boundary … 7 hole); 0 for SVG
  std::vector<Polyline> polylines;
  Paint fill;
  Paint stroke;
  double stroke_width = 0.0;  ///< in art units, after transforms
  FillRule fill_rule = FillRule::nonzero;
  PaintOrder paint_order = PaintOrder::fill_then_stroke;
};

/// A whole art file. `paths` is in drawing order: paths[0] is painted first (bottom-most).
struct ArtShape {
  std::filesystem::path source;
  std::vector<ArtPath> paths;
  std::vector<std::string> warnings;  ///< one line each: skipped elements, reduced gradients, …
  /// The root <svg>'s viewport in art coordinates, what a browser shows, when the file sets its width
  /// and height or a viewBox; absent for .path files and for SVGs that set neither.
  std::optional<Box> viewport;
  Box bounds() const;  ///< box of every polyline point
};

struct SvgOptions {
  /// Largest distance between a curve and its flattened polyline, in the SVG's user units after
  /// viewBox scaling (pixels at 96 dpi for unit-less documents). Straight runs are thinned within it
  /// (docs/scene-format.md "Large paths").
  double flatten_tolerance = 0.1;
  /// Files larger than this are refused before parsing (an attack or not clip art).
  std::uintmax_t max_file_bytes = 32u << 20;
  /// SVG elements to leave out, each with everything inside it, as if deleted from the file: CSS selectors
  /// as `<style>` rules take them, "#id", ".class", or types, ids and classes joined by spaces or `>`
  /// (docs/scene-format.md, "Leaving pieces of the art out"). Each must match an element (ExcludeError);
  /// a .path file takes none.
  std::vector<std::string> exclude;
};

/// An `exclude` selector (SvgOptions::exclude) that does not parse or matches no element of the file:
/// `index` into the list, the selector as given, and `problem`, the rest of the message (what is wrong and
/// what to do), so that a scene can name its own field instead.
class ExcludeError : public InputError {
 public:
  ExcludeError(const std::string& file, std::size_t at, std::string text, std::string what_is_wrong)
      : InputError(file + ": exclude \"" + text + "\": " + what_is_wrong),
        index(at),
        selector(std::move(text)),
        problem(std::move(what_is_wrong)) {}
  std::size_t index;
  std::string selector;
  std::string problem;
};

/// A name an `exclude` selector can write as it is after `#` or `.`: letters, digits, `-`, `_` and
/// non-ASCII characters, as SVG import's selectors read them (an id such as "Layer 1" cannot be selected).
bool selector_name(const std::string& name);

/// "g#layer1 > path#path3421.shadow": the path's lineage as a selector would write it, each element as its
/// tag, #id and .classes; "path 4" for a path without one (a .path file's).
std::string lineage_text(const ArtPath& path);

/// Reads an SVG document. Throws InputError naming the file and element for malformed or unusable input.
/// Never loads another file: external entities and external references are refused.
ArtShape load_svg(const std::filesystem::path& file, const SvgOptions& options = {});

/// Parses SVG text already in memory; `name` is used in messages.
ArtShape parse_svg(const std::string& text, const std::string& name, const SvgOptions& options = {});

/// Reads the authors' `.path` format (docs/scene-format.md, "The `.path` art format"). Paths come out in drawing order
/// (the file's last path first), each with its source_index and path_type.
ArtShape load_path_file(const std::filesystem::path& file);

/// Parses `.path` text already in memory; `name` stands for the file in messages.
ArtShape parse_path_text(const std::string& text, const std::string& name);

/// `points` with vertices dropped wherever the polyline stays within `tolerance` of what is kept (every
/// dropped point, and every dropped segment, lies within `tolerance` of the kept chord over it); the
/// first and last points are kept. Linear time. The SVG importer thins straight runs with it, the
/// element outline its art (docs/scene-format.md "Large paths").
std::vector<Vec2> thin_polyline(const std::vector<Vec2>& points, double tolerance);

/// Chooses the reader by extension (.svg, .path); anything else is an InputError.
ArtShape load_art(const std::filesystem::path& file, const SvgOptions& options = {});

}  // namespace animpak
