// svgpp contexts of the SVG importer; included by svg.cpp only (it needs svgpp's tags). One context
// lives per element while svgpp walks it; children copy their parent's, which is CSS inheritance.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "animpak/error.hpp"
#include "svg_internal.hpp"

namespace animpak::svg {

namespace tag = svgpp::tag;
using Color = svgpp::factory::color::default_factory::color_type;

/// Whole-document bookkeeping: output, warnings, the `use` chain and the work budget.
struct State {
  State(const Document& d, const SvgOptions& o, ArtShape& a) : doc(d), options(o), out(a) {}
  const Document& doc;
  const SvgOptions& options;
  ArtShape& out;
  struct Pending {
    std::string problem;
    std::vector<std::string> elements;  // as describe() names them, each once
  };
  std::vector<Pending> pending;
  std::map<std::string, size_t> problems;           // problem text → index in pending
  std::set<std::pair<size_t, std::string>> warned;  // (problem, element) pairs already counted
  std::vector<std::string> gradients;               // ids reduced to one colour, reported once at the end
  std::vector<const xmlNode*> use_chain;
  size_t elements = 0;
  size_t points = 0;

  std::set<const xmlNode*> faulted;  // elements whose data error was already reported

  /// One warning about one element; the same problem met on several elements is one line at the end.
  void warn(const std::string& what, const std::string& problem) {
    const auto [it, fresh] = problems.emplace(problem, pending.size());
    if (fresh) pending.push_back({problem, {}});
    if (warned.emplace(it->second, what).second) pending[it->second].elements.push_back(what);
  }
  /// The collected warnings into out.warnings, in the order first met: "file: path#a: problem" for one
  /// element, "file: 11 elements (path#a, path#b, path#c and 8 more): problem" for several.
  void flush_warnings() {
    for (const Pending& p : pending) {
      std::string line = doc.name() + ": ";
      if (p.elements.size() == 1) {
        line += p.elements.front();
      } else {
        line += std::to_string(p.elements.size()) + " elements (";
        const size_t shown = std::min<size_t>(p.elements.size(), 3);
        for (size_t i = 0; i < shown; ++i) line += (i ? ", " : "") + p.elements[i];
        if (p.elements.size() > shown) line += " and " + std::to_string(p.elements.size() - shown) + " more";
        line += ")";
      }
      out.warnings.push_back(line + ": " + p.problem);
    }
    pending.clear();
    problems.clear();
    warned.clear();
  }
  // `use` can multiply elements exponentially; a hard budget keeps every file under a second.
  void spend(const xmlNode* node, size_t new_elements, size_t new_points) {
    elements += new_elements;
    points += new_points;
    if (elements > 200000 || points > 4000000) {
      throw InputError(message(doc.name(), describe(node),
                               "more than 200000 elements or 4000000 points after "
                               "expanding <use> references",
                               "simplify the art or raise flatten_tolerance"));
    }
  }
};

struct PaintSpec {
  enum class Kind { none, color, current_color, url };
  PaintSpec() = default;
  explicit PaintSpec(Kind k, Rgba c = {}, std::string id = {}) : kind(k), color(c), iri(std::move(id)) {}
  Kind kind = Kind::none;
  Rgba color;
  std::string iri;
  Kind fallback_kind = Kind::none;  // what a url() falls back to when it cannot be used
  Rgba fallback_color;
};

inline Rgba to_rgba(Color c) { return {((c >> 16) & 255) / 255.0, ((c >> 8) & 255) / 255.0, (c & 255) / 255.0, 1.0}; }

// svgpp's paint events, one overload per form `fill`/`stroke` can take.
inline void assign(PaintSpec& p, tag::value::none) { p = {}; }
inline void assign(PaintSpec& p, tag::value::currentColor) { p = PaintSpec(PaintSpec::Kind::current_color); }
inline void assign(PaintSpec&, tag::value::inherit) {}
inline void assign(PaintSpec& p, Color c) { p = PaintSpec(PaintSpec::Kind::color, to_rgba(c)); }
template <class Icc>
void assign(PaintSpec& p, Color c, const Icc&) {
  assign(p, c);
}
template <class R>
void assign(PaintSpec& p, tag::iri_fragment, const R& id) {
  p = PaintSpec(PaintSpec::Kind::url, {}, std::string(boost::begin(id), boost::end(id)));
}
template <class R, class... Fallback>
void assign(PaintSpec& p, tag::iri_fragment, const R& id, const Fallback&... fallback) {
  PaintSpec f;
  assign(f, fallback...);
  assign(p, tag::iri_fragment(), id);
  p.fallback_kind = f.kind;
  p.fallback_color = f.color;
}
// A url() into another file is never loaded: the fallback (or none) is used, as for a missing one.
template <class R, class... Fallback>
void assign(PaintSpec& p, const R&, const Fallback&... fallback) {
  PaintSpec f;
  if constexpr (sizeof...(Fallback) > 0) assign(f, fallback...);
  p = f;
}

struct Style {
  PaintSpec fill = PaintSpec(PaintSpec::Kind::color);
  PaintSpec stroke;
  double stroke_width = 1.0;
  double fill_opacity = 1.0;
  double stroke_opacity = 1.0;
  Rgba current_color;
  FillRule fill_rule = FillRule::nonzero;
  PaintOrder paint_order = PaintOrder::fill_then_stroke;
  bool visible = true;
};

size_t path_error_offset(const std::string& d);
std::string css_property(const xmlNode* node, const char* name);
std::optional<Rgba> gradient_color(struct State& state, xmlNode* node);

/// What every context offers svgpp's error policy: somewhere to warn, and the element to name.
class Reporter {
 public:
  Reporter(State& state, xmlNode* node) : state_(&state), node_(node) {}
  State& state() const { return *state_; }
  std::string what() const { return node_ ? describe(node_) : "gradient"; }
  const xmlNode* node() const { return node_; }

 protected:
  State* state_;
  xmlNode* node_;
};

class BaseContext : public Reporter {
 public:
  using length_factory_type = svgpp::factory::length::unitless<>;

  /// The root <svg>: percentages resolve against its viewBox (or 100 × 100 user units without one,
  /// as there is no enclosing window to measure).
  BaseContext(State& state, xmlNode* node) : Reporter(state, node) {
    std::string vb = attribute(node, "viewBox");
    std::replace(vb.begin(), vb.end(), ',', ' ');
    std::istringstream in(vb);
    double x = 0, y = 0, w = 0, h = 0;
    if (in >> x >> y >> w >> h && w > 0 && h > 0)
      set_percent_box(w, h);
    else
      set_percent_box(100, 100);
    disabled_ = state.doc.excluded(node);
    read_paint_order();
    apply_own_transform();
  }
  BaseContext(BaseContext& parent, xmlNode* node)
      : Reporter(*parent.state_, node),
        style_(parent.style_),
        transform_(parent.transform_),
        opacity_(parent.opacity_),
        lengths_(parent.lengths_),
        box_width_(parent.box_width_),
        box_height_(parent.box_height_),
        clips_(parent.clips_),
        ref_width_(parent.use_width_),
        ref_height_(parent.use_height_),
        lineage_(std::make_shared<const Lineage>(Lineage{node, parent.lineage_})) {
    state_->spend(node, 1, 0);
    // What the scene's `exclude` leaves out draws nothing, as if deleted from the file.
    disabled_ = state_->doc.excluded(node);
    if (parent.is_switch_) {
      // <switch> draws its first child whose conditions hold; we support no extensions, which is
      // how Illustrator's <foreignObject requiredExtensions=…> gives way to the plain SVG copy.
      disabled_ = disabled_ || parent.switch_chosen_ || !attribute(node, "requiredExtensions").empty();
      if (!disabled_) parent.switch_chosen_ = true;
    }
    is_switch_ = xmlStrEqual(node->name, BAD_CAST "switch");
    read_paint_order();
    apply_own_transform();
  }

  const length_factory_type& length_factory() const { return lengths_; }
  bool descend() const { return rendered(); }
  bool next_child() const { return !(is_switch_ && switch_chosen_); }
  void on_exit_element() {}
  template <class Range>
  void set_text(const Range&) {}  // character data is never drawn (text elements are skipped)

  void transform_matrix(const boost::array<double, 6>& m);
  void set_viewport(double x, double y, double w, double h) {
    set_percent_box(w, h);
    if (node_ != state_->doc.root()) clip_to_viewport(x, y, w, h);
    // The root's viewport is the picture a browser draws; without width, height or viewBox it is the
    // browser window's, which only the user knows.
    const bool sized = !attribute(node_, "width").empty() || !attribute(node_, "height").empty() ||
                       !attribute(node_, "viewBox").empty();
    if (node_ == state_->doc.root() && !state_->out.viewport && sized) {
      Box box;
      box.add(transform_.apply({x, y}));
      box.add(transform_.apply({x + w, y + h}));
      state_->out.viewport = box;
    }
  }
  void set_viewbox_size(double w, double h) { set_percent_box(w, h); }
  // The viewport of an <svg> or <symbol> that a <use> draws: the use's width and height where given, else
  // (SVG 2) the symbol's own, else 100 %.
  void get_reference_viewport_size(double& w, double& h) const {
    const bool symbol = xmlStrEqual(node_->name, BAD_CAST "symbol");
    if (ref_width_)
      w = *ref_width_;
    else if (symbol)
      w = parse_length(attribute(node_, "width"), box_width_).value_or(w);
    if (ref_height_)
      h = *ref_height_;
    else if (symbol)
      h = parse_length(attribute(node_, "height"), box_height_).value_or(h);
  }
  void disable_rendering() { display_ = false; }

  template <class... A>
  void set(tag::attribute::fill, const A&... a) {
    assign(style_.fill, a...);
  }
  template <class... A>
  void set(tag::attribute::stroke, const A&... a) {
    assign(style_.stroke, a...);
  }
  void set(tag::attribute::stroke_width, double w) { style_.stroke_width = std::max(0.0, w); }
  void set(tag::attribute::fill_rule, tag::value::nonzero) { style_.fill_rule = FillRule::nonzero; }
  void set(tag::attribute::fill_rule, tag::value::evenodd) { style_.fill_rule = FillRule::evenodd; }
  void set(tag::attribute::opacity, double v) { opacity_ *= std::clamp(v, 0.0, 1.0); }
  void set(tag::attribute::fill_opacity, double v) { style_.fill_opacity = std::clamp(v, 0.0, 1.0); }
  void set(tag::attribute::stroke_opacity, double v) { style_.stroke_opacity = std::clamp(v, 0.0, 1.0); }
  void set(tag::attribute::display, tag::value::none) { display_ = false; }
  void set(tag::attribute::visibility, tag::value::visible) { style_.visible = true; }
  void set(tag::attribute::visibility, tag::value::hidden) { style_.visible = false; }
  void set(tag::attribute::visibility, tag::value::collapse) { style_.visible = false; }
  void set(tag::attribute::color, Color c) { style_.current_color = to_rgba(c); }
  template <class R>
  void set(tag::attribute::clip_path, tag::iri_fragment, const R&) {
    unsupported("clip-path", "drawn unclipped");
  }
  template <class R>
  void set(tag::attribute::mask, tag::iri_fragment, const R&) {
    unsupported("mask", "drawn unmasked");
  }
  template <class R>
  void set(tag::attribute::filter, tag::iri_fragment, const R&) {
    unsupported("filter", "drawn unfiltered");
  }
  // Everything else svgpp reports (inherit, other display values, attributes we only pass through).
  template <class Tag, class... A>
  void set(Tag, const A&...) {}

 protected:
  bool rendered() const { return display_ && !disabled_; }
  void unsupported(const char* what, const char* effect) {
    state_->warn(describe(node_), std::string(what) + " is not supported; " + effect);
  }
  void read_paint_order() {
    std::istringstream in(css_property(node_, "paint-order"));
    std::string token;
    std::vector<std::string> tokens;
    while (in >> token) tokens.push_back(token);
    if (tokens.empty() || tokens[0] == "inherit") return;
    const auto fill = std::find(tokens.begin(), tokens.end(), "fill");
    const auto stroke = std::find(tokens.begin(), tokens.end(), "stroke");
    style_.paint_order =
        stroke != tokens.end() && stroke < fill ? PaintOrder::stroke_then_fill : PaintOrder::fill_then_stroke;
  }

  /// The element's own `transform` (the CSS property, else the attribute) about its `transform-origin`,
  /// composed onto the parent's.
  void apply_own_transform();
  /// Clips what this nested <svg> or <symbol> draws to its viewport, unless its overflow is visible.
  void clip_to_viewport(double x, double y, double w, double h);
  void set_percent_box(double w, double h) {
    lengths_.set_viewport_size(w, h);
    box_width_ = w;
    box_height_ = h;
  }

  Style style_;
  Affine transform_;
  double opacity_ = 1.0;  // group opacities multiplied down the tree, folded into the paint alpha
  length_factory_type lengths_;
  double box_width_ = 100.0, box_height_ = 100.0;  // what percentages resolve against, as in lengths_
  // The viewports of the nested <svg>s and <symbol>s this element is drawn in, convex quads in art units.
  std::shared_ptr<const std::vector<std::vector<Vec2>>> clips_;
  bool display_ = true;
  bool disabled_ = false;
  bool is_switch_ = false;
  bool switch_chosen_ = false;
  std::optional<double> use_width_, use_height_;  // set by <use>, read by the <svg>/<symbol> it draws
  std::optional<double> ref_width_, ref_height_;
  // The elements this one is drawn through, innermost first (itself, its parent or the <use> that draws
  // it, …), the root left out: what ArtPath::lineage lists outermost first.
  struct Lineage {
    const xmlNode* node;
    std::shared_ptr<const Lineage> parent;
  };
  std::shared_ptr<const Lineage> lineage_;
};

using GroupContext = BaseContext;

/// Elements we do not import (text, images, masks, …): one warning, nothing drawn, children unvisited.
class SkippedContext : public BaseContext {
 public:
  SkippedContext(BaseContext& parent, xmlNode* node) : BaseContext(parent, node) {}
  bool descend() const { return false; }
  void on_exit_element() {
    if (rendered())
      state_->warn(what(), std::string("<") + reinterpret_cast<const char*>(node_->name) +
                               "> is not imported and was skipped; convert it to paths in an editor");
  }
};

class ShapeContext : public BaseContext {
 public:
  ShapeContext(BaseContext& parent, xmlNode* node) : BaseContext(parent, node) {}

  void path_move_to(double x, double y, tag::coordinate::absolute) { add(Seg::move, {x, y}); }
  void path_line_to(double x, double y, tag::coordinate::absolute) { add(Seg::line, {x, y}); }
  void path_quadratic_bezier_to(double x1, double y1, double x, double y, tag::coordinate::absolute) {
    add(Seg::quad, {x1, y1, x, y});
  }
  void path_cubic_bezier_to(double x1, double y1, double x2, double y2, double x, double y, tag::coordinate::absolute) {
    add(Seg::cubic, {x1, y1, x2, y2, x, y});
  }
  void path_elliptical_arc_to(double rx, double ry, double rot, bool large, bool sweep, double x, double y,
                              tag::coordinate::absolute) {
    add(Seg::arc, {rx, ry, rot, large ? 1.0 : 0.0, sweep ? 1.0 : 0.0, x, y});
  }
  void path_close_subpath() { add(Seg::close, {}); }
  void path_exit() {}
  void on_exit_element();

 private:
  // Recorded in user units and flattened at the end, when the element's own transform is known
  // whatever the order of its attributes.
  // One flat array of numbers rather than a vector per segment: a million-point path costs 17 MB here,
  // not the 100 MB of a million small allocations.
  enum class Seg { move, line, quad, cubic, arc, close };
  void add(Seg kind, std::initializer_list<double> v) {
    kinds_.push_back(kind);
    values_.insert(values_.end(), v);
  }
  Paint resolve(const PaintSpec& spec, double opacity);
  /// Why the element's geometry draws nothing or less than written, or empty when it draws all of it.
  std::string degenerate(const std::vector<Polyline>& kept, size_t dropped, size_t zero_area) const;
  void warn_stretched_stroke(double width);
  void warn_reduced_stroke(const std::vector<Polyline>& lines);
  std::vector<Seg> kinds_;
  std::vector<double> values_;
};

class UseContext : public BaseContext {
 public:
  UseContext(BaseContext& parent, xmlNode* node) : BaseContext(parent, node) {}
  void set(tag::attribute::x, double v) { x_ = v; }
  void set(tag::attribute::y, double v) { y_ = v; }
  void set(tag::attribute::width, double v) { use_width_ = v; }
  void set(tag::attribute::height, double v) { use_height_ = v; }
  using BaseContext::set;
  void on_exit_element();

 private:
  double x_ = 0.0, y_ = 0.0;
};

bool load_reference(xmlNode* target, UseContext& use);

/// Collects a gradient's stops to reduce it to one representative colour.
class GradientContext : public Reporter {
 public:
  GradientContext(State& state, xmlNode* node) : Reporter(state, node) {}
  template <class Tag, class... A>
  void set(Tag, const A&...) {}
  void add_stop(Rgba c) { stops_.push_back(c); }
  std::optional<Rgba> average() const {
    if (stops_.empty()) return std::nullopt;
    Rgba sum{0, 0, 0, 0};
    for (const Rgba& s : stops_) sum = {sum.r + s.r, sum.g + s.g, sum.b + s.b, sum.a + s.a};
    const double n = static_cast<double>(stops_.size());
    return Rgba{sum.r / n, sum.g / n, sum.b / n, sum.a / n};
  }

 private:
  std::vector<Rgba> stops_;
};

class StopContext : public Reporter {
 public:
  StopContext(GradientContext& parent, xmlNode* node) : Reporter(parent.state(), node), parent_(&parent) {}
  void set(tag::attribute::stop_color, Color c) { color_ = to_rgba(c); }
  template <class Icc>
  void set(tag::attribute::stop_color, Color c, const Icc&) {
    color_ = to_rgba(c);
  }
  void set(tag::attribute::stop_opacity, double v) { opacity_ = std::clamp(v, 0.0, 1.0); }
  template <class Tag, class... A>
  void set(Tag, const A&...) {}
  bool descend() const { return false; }
  bool next_child() const { return true; }
  void on_exit_element() { parent_->add_stop({color_.r, color_.g, color_.b, opacity_}); }

 private:
  GradientContext* parent_;
  Rgba color_;
  double opacity_ = 1.0;
};

}  // namespace animpak::svg
