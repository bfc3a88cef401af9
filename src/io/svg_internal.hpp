// Pieces of the SVG importer that do not need svgpp, shared by svg.cpp (the only svgpp translation
// unit, slow to compile) with svg_flatten.cpp and svg_document.cpp.
#pragma once

#include <libxml/tree.h>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "animpak/io.hpp"

namespace animpak::svg {

/// 2D affine map [a c e; b d f] as in SVG's matrix(a b c d e f).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  double det() const { return a * d - b * c; }
};
/// The map that applies `inner` first, then `outer`.
Affine compose(const Affine& outer, const Affine& inner);

/// Turns one element's path events (user units) into polylines in art units, within `tolerance`
/// measured after `transform`, so a scaled-up curve gets proportionally more points.
class PathFlattener {
 public:
  PathFlattener(const Affine& transform, double tolerance) : m_(transform), tol_(tolerance) {}
  void move_to(Vec2 p);
  void line_to(Vec2 p);
  void quadratic_to(Vec2 c, Vec2 p);
  void cubic_to(Vec2 c1, Vec2 c2, Vec2 p);
  void arc_to(double rx, double ry, double x_axis_rotation_deg, bool large_arc, bool sweep, Vec2 p);
  void close();
  Vec2 current() const { return cur_; }
  /// Finished subpaths, straight runs thinned (docs/scene-format.md "Large paths"); subpaths with fewer
  /// than two distinct points are dropped (they draw nothing) and counted in dropped().
  std::vector<Polyline> take();
  /// Points emitted before thinning: the measure of the work the input asked for.
  size_t point_count() const { return points_; }
  size_t dropped() const { return dropped_; }

 private:
  void emit(Vec2 art_point, bool straight);
  void end_subpath(bool closed);
  void cubic_art(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, int depth);
  Affine m_;
  double tol_;
  Vec2 start_{}, cur_{};  // user units, for the next relative command and for close()
  Polyline open_;
  std::vector<bool> straight_;  // straight_[i]: open_.points[i] is reached from its predecessor by a line
  bool has_open_ = false;
  std::vector<Polyline> done_;
  size_t points_ = 0;
  size_t dropped_ = 0;
};

/// The points of a subpath with every vertex between two straight segments dropped where the polyline
/// stays within `tolerance` of what is kept; vertices next to a curve, the first and the last are kept.
/// `straight[i]` says whether the segment that ends at points[i] is straight. Linear time.
std::vector<Vec2> thin_straight_runs(const std::vector<Vec2>& points, const std::vector<bool>& straight,
                                     double tolerance);

/// A parsed document kept alive for the traversal, with every element by id.
class Document {
 public:
  /// Reads `text` with external entities and network access refused; throws InputError.
  Document(const std::string& text, const std::string& name);
  ~Document();
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  xmlNode* root() const { return root_; }
  xmlNode* find(const std::string& id) const;
  const std::string& name() const { return name_; }
  /// What the document itself could not apply, as (element, problem) warnings.
  const std::vector<std::pair<std::string, std::string>>& notes() const { return notes_; }
  /// Leaves out every element `selectors` match, with everything inside it (SvgOptions::exclude); throws
  /// ExcludeError for a selector that does not parse or matches no element.
  void exclude(const std::vector<std::string>& selectors);
  /// Whether the element was left out, itself or by an element it lies in.
  bool excluded(const xmlNode* node) const { return excluded_.contains(node); }

 private:
  void index(xmlNode* node, int depth);
  void apply_class_styles();
  void resolve_auto_radii(xmlNode* ellipse);
  std::string name_;
  xmlDoc* doc_ = nullptr;
  xmlNode* root_ = nullptr;
  xmlNs* svg_ns_ = nullptr;
  std::map<std::string, xmlNode*> by_id_;
  std::vector<std::pair<std::string, std::string>> notes_;
  std::set<const xmlNode*> excluded_;
};

/// The warning for path data `d` that svgpp's grammar read up to offset `stop` only: the character to
/// blame (counted from 1) and the text there, and that the path is drawn up to it (SVG 2, "Error handling
/// in path data").
std::string path_data_error(const std::string& d, size_t stop);
/// The warning for a `points` list that svgpp read only in part: an odd coordinate dropped, or where the
/// data stops being numbers.
std::string points_error(const std::string& points);

/// A CSS length unit (empty or px, in, cm, mm, q, pt, pc) applied to `value`, in px (user units); nullopt
/// for relative units (em, ex, %, …).
std::optional<double> length_in_px(const std::string& unit, double value);
/// A length attribute's value in user units, percentages of `percent_of`; nullopt when it is not one.
std::optional<double> parse_length(const std::string& text, double percent_of);
/// The `transform` attribute or CSS property (both spellings taken in either place, as browsers do);
/// nullopt with `error` set when it does not parse. "none" is the identity.
std::optional<Affine> parse_transform(const std::string& text, std::string& error);
/// `transform-origin` in user units, keywords and percentages resolved against a box of the given size at
/// the user-space origin (CSS Transforms 1, transform-box view-box); nullopt with `error` set when invalid.
std::optional<Vec2> parse_transform_origin(const std::string& text, double box_width, double box_height,
                                           std::string& error);
/// `path` (in art units) cut to the intersection of the convex `clips` (art units): unchanged when it lies
/// inside, else its fill inside the clip and its stroke (round joins and caps, within `tolerance`) as a
/// filled band inside the clip, in paint order; empty when nothing of it is inside.
std::vector<ArtPath> clip_to_viewports(ArtPath path, const std::vector<std::vector<Vec2>>& clips, double tolerance);

/// `<name>: <what>: <problem>; <fix>` as every importer message reads.
std::string message(const std::string& file, const std::string& what, const std::string& problem,
                    const std::string& fix);
/// "tag#id" when the element has one, else "<tag> at line N".
std::string describe(const xmlNode* node);
/// An attribute's value, or empty (libxml2's strings freed here).
std::string attribute(const xmlNode* node, const char* name, const char* ns_href = nullptr);
/// The element's reference: xlink:href (SVG 1.1), else plain href (SVG 2); empty when neither is set.
std::string href(const xmlNode* node);

}  // namespace animpak::svg
