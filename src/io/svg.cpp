// svgpp glue: the only translation unit that includes svgpp, whose templates are slow to compile. svgpp walks
// the libxml2 tree, parses attributes, CSS `style`, paths, shapes, transforms and viewports; the
// contexts below keep the inherited style, compose transforms and emit flattened ArtPaths.
#include <libxml/tree.h>
// libxml2's headers must precede svgpp's libxml2 policy (docs/architecture.md, "Dependencies").
#include <svgpp/policy/xml/libxml2.hpp>
#include <svgpp/svgpp.hpp>

#include <boost/mpl/fold.hpp>
#include <boost/mpl/insert.hpp>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>

#include "animpak/error.hpp"
#include "svg_context.hpp"
#include "svg_internal.hpp"

namespace animpak::svg {
namespace {

namespace tag = svgpp::tag;
namespace mpl = boost::mpl;

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

using RenderedElements =
    mpl::set<tag::element::svg, tag::element::g, tag::element::a, tag::element::switch_, tag::element::use_,
             tag::element::path, tag::element::rect, tag::element::circle, tag::element::ellipse, tag::element::line,
             tag::element::polyline, tag::element::polygon>::type;
using SkippedElements =
    mpl::vector<tag::element::text, tag::element::image, tag::element::mask, tag::element::clipPath,
                tag::element::pattern, tag::element::marker, tag::element::filter, tag::element::foreignObject>;
using ProcessedElements = mpl::fold<SkippedElements, RenderedElements, mpl::insert<mpl::_1, mpl::_2>>::type;
// What a `use` may point at: anything rendered, plus `symbol`, which is drawn only through `use`.
using ReferencedElements =
    mpl::insert<mpl::fold<SkippedElements, mpl::erase_key<RenderedElements, tag::element::a>::type,
                          mpl::insert<mpl::_1, mpl::_2>>::type,
                tag::element::symbol>::type;

// `transform` is not among them: the CSS property outranks the attribute and svgpp reads only the
// attribute, so BaseContext::apply_own_transform reads both.
using StyleAttributes =
    mpl::vector<tag::attribute::fill, tag::attribute::stroke, tag::attribute::stroke_width, tag::attribute::fill_rule,
                tag::attribute::opacity, tag::attribute::fill_opacity, tag::attribute::stroke_opacity,
                tag::attribute::display, tag::attribute::visibility, tag::attribute::color, tag::attribute::clip_path,
                tag::attribute::mask, tag::attribute::filter>;
using ViewportAttributes = mpl::vector<
    mpl::pair<tag::element::svg, tag::attribute::x>, mpl::pair<tag::element::svg, tag::attribute::y>,
    mpl::pair<tag::element::svg, tag::attribute::width>, mpl::pair<tag::element::svg, tag::attribute::height>,
    mpl::pair<tag::element::svg, tag::attribute::viewBox>,
    mpl::pair<tag::element::svg, tag::attribute::preserveAspectRatio>,
    mpl::pair<tag::element::symbol, tag::attribute::viewBox>,
    mpl::pair<tag::element::symbol, tag::attribute::preserveAspectRatio>,
    mpl::pair<tag::element::use_, tag::attribute::x>, mpl::pair<tag::element::use_, tag::attribute::y>,
    mpl::pair<tag::element::use_, tag::attribute::width>, mpl::pair<tag::element::use_, tag::attribute::height>>;
using ProcessedAttributes = mpl::fold<
    ViewportAttributes,
    mpl::fold<StyleAttributes, svgpp::traits::shapes_attributes_by_element, mpl::insert<mpl::_1, mpl::_2>>::type,
    mpl::insert<mpl::_1, mpl::_2>>::type;

// Which context type each element gets; all construct from (parent context, xmlNode*).
template <class Parent, class Element>
struct ChildContext {
  using type = svgpp::factory::context::on_stack_with_xml_element<GroupContext>;
};
template <class Parent, class Element>
requires mpl::has_key<svgpp::traits::shape_elements, Element>::value struct ChildContext<Parent, Element> {
  using type = svgpp::factory::context::on_stack_with_xml_element<ShapeContext>;
};
template <class Parent>
struct ChildContext<Parent, tag::element::use_> {
  using type = svgpp::factory::context::on_stack_with_xml_element<UseContext>;
};
template <class Parent, class Element>
requires mpl::contains<SkippedElements, Element>::value struct ChildContext<Parent, Element> {
  using type = svgpp::factory::context::on_stack_with_xml_element<SkippedContext>;
};
template <class Parent>
struct ChildContext<Parent, tag::element::stop> {
  using type = svgpp::factory::context::on_stack_with_xml_element<StopContext>;
};
struct ContextFactories {
  template <class Parent, class Element>
  struct apply : ChildContext<Parent, Element> {};
};

// Invalid input must never abort the walk half-way with a bare `false`: unknown and misplaced
// elements are skipped, unknown attributes ignored, and only unparsable geometry is an error.
struct LenientErrors {
  using context_type = Reporter;
  struct NeverThrown {};
  using intercepted_exception_type = NeverThrown;
  template <class C, class X, class N>
  static bool unknown_element(const C&, const X&, const N&) {
    return true;
  }
  template <class C, class X>
  static bool unexpected_element(const C&, const X&) {
    return true;
  }
  template <class C, class... A>
  static bool unknown_attribute(const C&, const A&...) {
    return true;
  }
  template <class C, class... A>
  static bool unexpected_attribute(const C&, const A&...) {
    return true;
  }
  template <class C, class T>
  static bool required_attribute_not_found(const C&, T) {
    return true;
  }
  template <class C, class T>
  static bool negative_value(const C& c, T) {
    c.state().faulted.insert(c.node());
    c.state().warn(c.what(), std::string("negative ") + svgpp::attribute_name<char>::get<T>() + " ignored");
    return true;
  }
  template <class C, class T, class V>
  static bool parse_failed(const C& c, T, const V& value) {
    const std::string text(boost::begin(value), boost::end(value));
    if constexpr (std::is_same_v<T, tag::attribute::rx> || std::is_same_v<T, tag::attribute::ry>) {
      // SVG 2's `auto` radius is an absent one to svgpp: a rect's takes the other radius (both auto: square
      // corners). An ellipse's was given the other radius by Document, so one still here had a percentage
      // opposite it, or both were auto.
      if (trimmed(text) == "auto") {
        if (xmlStrEqual(c.node()->name, BAD_CAST "ellipse")) {
          c.state().faulted.insert(c.node());
          c.state().warn(c.what(),
                         "rx and ry auto, or auto opposite a percentage, is not supported; nothing "
                         "drawn (give rx or ry a length)");
        }
        return true;
      }
    }
    // SVG 2 ("Error handling in path data", the `points` attribute): draw what came before the error.
    // svgpp has already delivered those segments to the context when it reports the failure.
    if constexpr (std::is_same_v<T, tag::attribute::d>) {
      c.state().faulted.insert(c.node());
      c.state().warn(c.what(), path_data_error(text, path_error_offset(text)));
    } else if constexpr (std::is_same_v<T, tag::attribute::points>) {
      c.state().faulted.insert(c.node());
      c.state().warn(c.what(), points_error(text));
    } else {
      c.state().warn(c.what(), std::string("invalid ") + svgpp::attribute_name<char>::get<T>() + " \"" +
                                   text.substr(0, 40) + "\" ignored");
    }
    return true;
  }
  template <class X>
  static bool add_element_info(intercepted_exception_type&, const X&) {
    throw;
  }
};

struct TraversalControl {
  template <class C>
  static bool proceed_to_element_content(C& c) {
    return c.descend();
  }
  template <class C>
  static bool proceed_to_next_child(C& c) {
    return c.next_child();
  }
  template <class C, class X>
  static bool process_child(C&, X&) {
    return true;
  }
};

using Traversal = svgpp::document_traversal<
    svgpp::processed_elements<ProcessedElements>, svgpp::processed_attributes<ProcessedAttributes>,
    svgpp::context_factories<ContextFactories>, svgpp::error_policy<LenientErrors>,
    svgpp::viewport_policy<svgpp::policy::viewport::as_transform>,
    svgpp::length_policy<svgpp::policy::length::forward_to_method<BaseContext>>,
    svgpp::document_traversal_control_policy<TraversalControl>>;  // paths: svgpp's default no_shorthands

using GradientTraversal = svgpp::document_traversal<
    svgpp::processed_elements<
        mpl::set<tag::element::linearGradient, tag::element::radialGradient, tag::element::stop>::type>,
    svgpp::processed_attributes<mpl::set<tag::attribute::stop_color, tag::attribute::stop_opacity>::type>,
    svgpp::context_factories<ContextFactories>, svgpp::error_policy<LenientErrors>>;

// A sink that accepts every path event, to find where svgpp's path grammar stops on bad data.
struct NullPath {
  template <class... A>
  void path_move_to(const A&...) {}
  template <class... A>
  void path_line_to(const A&...) {}
  template <class... A>
  void path_line_to_ortho(const A&...) {}
  template <class... A>
  void path_cubic_bezier_to(const A&...) {}
  template <class... A>
  void path_quadratic_bezier_to(const A&...) {}
  template <class... A>
  void path_elliptical_arc_to(const A&...) {}
  void path_close_subpath() {}
  void path_exit() {}
};

}  // namespace

size_t path_error_offset(const std::string& d) {
  using Grammar = svgpp::path_data_grammar<std::string::const_iterator, NullPath, double>;
  static const Grammar grammar;
  NullPath sink;
  auto it = d.begin();
  boost::spirit::qi::phrase_parse(it, d.end(), grammar(boost::phoenix::ref(sink)), Grammar::skipper_type());
  return static_cast<size_t>(it - d.begin());
}

namespace {
// The value the `style` attribute declares for `name`: the last declaration wins, after the class rules
// Document put first.
std::optional<std::string> declared_style(const xmlNode* node, const char* name) {
  const std::string style = attribute(node, "style");
  std::optional<std::string> value;
  for (svgpp::css_style_iterator<std::string::const_iterator> it(style.begin(), style.end()); !it.eof(); ++it)
    if (std::string(it->first.begin(), it->first.end()) == name) value.emplace(it->second.begin(), it->second.end());
  return value;
}
}  // namespace

std::string css_property(const xmlNode* node, const char* name) {
  const std::optional<std::string> value = declared_style(node, name);
  return value ? *value : attribute(node, name);
}

void BaseContext::apply_own_transform() {
  // CSS Transforms 1 makes `transform` a property with the attribute its presentation attribute, so a style
  // rule or the style attribute wins over the attribute, as in browsers (rsvg-convert 2.54 lets the
  // attribute win; docs/scene-format.md, "SVG structure"). An invalid declaration is dropped, as CSS drops it,
  // and the attribute applies.
  const std::optional<std::string> declared = declared_style(node_, "transform");
  const std::string own = trimmed(attribute(node_, "transform"));
  std::string error;
  std::optional<Affine> m;
  if (declared) {
    const std::string css = trimmed(*declared);
    m = css == "initial" || css == "unset" ? Affine{} : parse_transform(css, error);
    if (!m)
      state_->warn(what(), "invalid CSS transform \"" + css.substr(0, 40) + "\" (" + error + ") ignored" +
                               (own.empty() ? "" : "; the transform attribute is used"));
  }
  if (!m && !own.empty()) {
    m = parse_transform(own, error);
    if (!m) state_->warn(what(), "invalid transform \"" + own.substr(0, 40) + "\" (" + error + ") ignored");
  }
  if (!m) return;
  const std::string origin_text = trimmed(css_property(node_, "transform-origin"));
  Vec2 origin{0, 0};  // SVG elements' initial transform-origin (CSS Transforms 1, the UA style sheet)
  if (!origin_text.empty() && origin_text != "inherit" && origin_text != "initial") {
    // Percentages and keywords against the nearest viewport (transform-box view-box, the initial value).
    if (const auto o = parse_transform_origin(origin_text, box_width_, box_height_, error)) {
      origin = *o;
      const std::string box = trimmed(css_property(node_, "transform-box"));
      if (!box.empty() && box != "view-box")
        state_->warn(what(), "transform-box " + box + " is not supported; transform-origin " + origin_text +
                                 " is taken against the viewport (view-box)");
    } else {
      state_->warn(what(), "invalid transform-origin \"" + origin_text.substr(0, 40) + "\" (" + error +
                               "); the transform is applied about 0 0");
    }
  }
  transform_ = compose(transform_, compose(Affine{1, 0, 0, 1, origin.x, origin.y},
                                           compose(*m, Affine{1, 0, 0, 1, -origin.x, -origin.y})));
}

void BaseContext::clip_to_viewport(double x, double y, double w, double h) {
  const bool nested = xmlStrEqual(node_->name, BAD_CAST "svg") || xmlStrEqual(node_->name, BAD_CAST "symbol");
  const std::string overflow = trimmed(css_property(node_, "overflow"));
  // The UA style sheet hides the overflow of every viewport but the outermost (SVG 1.1 14.3.3).
  if (!nested || overflow == "visible" || overflow == "auto") return;
  auto clips = clips_ ? std::make_shared<std::vector<std::vector<Vec2>>>(*clips_)
                      : std::make_shared<std::vector<std::vector<Vec2>>>();
  clips->push_back({transform_.apply({x, y}), transform_.apply({x + w, y}), transform_.apply({x + w, y + h}),
                    transform_.apply({x, y + h})});
  clips_ = std::move(clips);
}

bool load_reference(xmlNode* target, UseContext& use) {
  return Traversal::load_referenced_element<svgpp::referencing_element<tag::element::use_>,
                                            svgpp::expected_elements<ReferencedElements>>::load(target, use);
}

std::optional<Rgba> gradient_color(State& state, xmlNode* node) {
  // Inkscape keeps the stops in one gradient and points the used one at it with href.
  for (int hop = 0; node && hop < 8; ++hop) {
    const bool linear = xmlStrEqual(node->name, BAD_CAST "linearGradient");
    if (!linear && !xmlStrEqual(node->name, BAD_CAST "radialGradient")) return std::nullopt;
    GradientContext gradient(state, node);
    if (linear)
      GradientTraversal::load_expected_element(node, gradient, tag::element::linearGradient());
    else
      GradientTraversal::load_expected_element(node, gradient, tag::element::radialGradient());
    if (auto c = gradient.average()) return c;
    const std::string ref = href(node);
    node = ref.size() > 1 && ref[0] == '#' ? state.doc.find(ref.substr(1)) : nullptr;
  }
  return std::nullopt;
}

void BaseContext::transform_matrix(const boost::array<double, 6>& m) {
  transform_ = compose(transform_, Affine{m[0], m[1], m[2], m[3], m[4], m[5]});
}

Paint ShapeContext::resolve(const PaintSpec& spec, double opacity) {
  PaintSpec::Kind kind = spec.kind;
  Rgba color = kind == PaintSpec::Kind::current_color ? style_.current_color : spec.color;
  if (kind == PaintSpec::Kind::url) {
    xmlNode* server = state_->doc.find(spec.iri);
    const std::optional<Rgba> gradient = server ? gradient_color(*state_, server) : std::nullopt;
    if (gradient) {
      if (std::find(state_->gradients.begin(), state_->gradients.end(), spec.iri) == state_->gradients.end())
        state_->gradients.push_back(spec.iri);
      color = *gradient;
    } else {
      state_->warn(what(), (server ? "paint server url(#" + spec.iri + ") is not a gradient with stops"
                                   : "url(#" + spec.iri + ") refers to no element") +
                               "; its fallback colour (or none) is used");
      kind = spec.fallback_kind;
      color = kind == PaintSpec::Kind::current_color ? style_.current_color : spec.fallback_color;
    }
  }
  Paint paint;
  if (kind == PaintSpec::Kind::none) return paint;
  paint.enabled = true;
  paint.color = color;
  paint.color.a *= opacity * opacity_;
  return paint;
}

void ShapeContext::on_exit_element() {
  if (!rendered() || !style_.visible) return;
  PathFlattener flat(transform_, state_->options.flatten_tolerance);
  const double* v = values_.data();
  for (const Seg kind : kinds_) {
    switch (kind) {
      case Seg::move:
        flat.move_to({v[0], v[1]}), v += 2;
        break;
      case Seg::line:
        flat.line_to({v[0], v[1]}), v += 2;
        break;
      case Seg::quad:
        flat.quadratic_to({v[0], v[1]}, {v[2], v[3]}), v += 4;
        break;
      case Seg::cubic:
        flat.cubic_to({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}), v += 6;
        break;
      case Seg::arc:
        flat.arc_to(v[0], v[1], v[2], v[3] != 0.0, v[4] != 0.0, {v[5], v[6]}), v += 7;
        break;
      case Seg::close:
        flat.close();
        break;
    }
  }
  state_->spend(node_, 0, flat.point_count());
  ArtPath path;
  path.polylines = flat.take();
  path.fill = resolve(style_.fill, style_.fill_opacity);
  path.stroke = resolve(style_.stroke, style_.stroke_opacity);
  path.stroke_width = style_.stroke_width * std::sqrt(std::abs(transform_.det()));
  if (path.stroke_width <= 0.0) path.stroke.enabled = false;
  // Unpainted geometry draws nothing, so it is not part of the art.
  if (!path.fill.enabled && !path.stroke.enabled) return;
  // A closed subpath without area paints no fill and, unstroked, nothing at all.
  size_t zero_area = 0;
  if (!path.stroke.enabled) {
    std::erase_if(path.polylines, [&](const Polyline& line) {
      Box box;
      for (Vec2 p : line.points) box.add(p);
      const double extent = std::max(box.width(), box.height());
      const bool flat_ring = std::abs(signed_area(line.points)) <= 1e-9 * extent * extent;
      zero_area += flat_ring;
      return flat_ring;
    });
  }
  if (!state_->faulted.contains(node_)) {
    const std::string why = degenerate(path.polylines, flat.dropped(), zero_area);
    if (!why.empty()) state_->warn(what(), why);
  }
  if (path.polylines.empty()) return;
  path.id = attribute(node_, "id");
  for (const Lineage* l = lineage_.get(); l; l = l->parent.get()) {
    ArtOrigin& origin = path.lineage.emplace_back();
    origin.tag = reinterpret_cast<const char*>(l->node->name);
    origin.id = attribute(l->node, "id");
    std::istringstream classes(attribute(l->node, "class"));
    for (std::string c; classes >> c;) origin.classes.push_back(c);
  }
  std::reverse(path.lineage.begin(), path.lineage.end());
  path.fill_rule = style_.fill_rule;
  path.paint_order = style_.paint_order;
  // What a nested viewport clips away entirely is not drawn, and nothing is said of its stroke.
  std::vector<ArtPath> pieces;
  if (clips_) pieces = clip_to_viewports(path, *clips_, state_->options.flatten_tolerance);
  if (path.stroke.enabled && (!clips_ || !pieces.empty())) {
    warn_stretched_stroke(path.stroke_width);
    warn_reduced_stroke(path.polylines);
  }
  if (!clips_) pieces.push_back(std::move(path));
  for (ArtPath& piece : pieces) {
    piece.source_index = static_cast<int>(state_->out.paths.size());
    state_->out.paths.push_back(std::move(piece));
  }
}

std::string ShapeContext::degenerate(const std::vector<Polyline>& kept, size_t dropped, size_t zero_area) const {
  const std::string tag = reinterpret_cast<const char*>(node_->name);
  if (kinds_.empty()) {
    // svgpp emits no geometry for the sizes SVG says disable rendering (and for absent data).
    if (tag == "rect") return "width or height is 0; nothing drawn (dropped)";
    if (tag == "circle") return "r is 0; nothing drawn (dropped)";
    if (tag == "ellipse") return "rx or ry is 0; nothing drawn (dropped)";
    if (tag == "path") return "no path data; nothing drawn (dropped)";
    return "no points; nothing drawn (dropped)";
  }
  if (dropped + zero_area == 0) return {};
  const size_t total = kept.size() + dropped + zero_area;
  std::string kinds;
  if (dropped > 0) kinds = "a single point or only zero-length segments";
  if (zero_area > 0) kinds += std::string(kinds.empty() ? "" : ", or ") + "no area (collinear points) and no stroke";
  if (kept.empty())
    return (total == 1 ? "its geometry is " : "all its subpaths are ") + kinds + "; nothing drawn (dropped)";
  return std::to_string(dropped + zero_area) + " of its " + std::to_string(total) + " subpaths " +
         (dropped + zero_area == 1 ? "is " : "are ") + kinds + "; those dropped";
}

void ShapeContext::warn_stretched_stroke(double width) {
  // A browser strokes with the pen stretched by the transform: as wide as the stroke width times each
  // singular value, depending on the direction. One width (their geometric mean) is what we keep.
  const Affine& m = transform_;
  const double sum = m.a * m.a + m.b * m.b + m.c * m.c + m.d * m.d, det = std::abs(m.det());
  const double root = std::sqrt(std::max(0.0, sum * sum - 4.0 * det * det));
  const double most = std::sqrt(0.5 * (sum + root)), least = std::sqrt(std::max(0.0, 0.5 * (sum - root)));
  if (!(most > 1.01 * least)) return;
  std::ostringstream text;
  text.precision(3);
  text << "stroke under a non-uniform scale is drawn " << width << " wide everywhere; a browser draws it "
       << style_.stroke_width * least << " to " << style_.stroke_width * most << " wide by direction";
  state_->warn(what(), text.str());
}

// The stroke is drawn, and taken into the outline, solid with round joins and caps (src/element/outline.cpp);
// SVG's default miter joins and butt caps differ at corners and open ends, and a dash pattern leaves gaps,
// so say where they were asked for.
void ShapeContext::warn_reduced_stroke(const std::vector<Polyline>& lines) {
  const auto inherited = [&](const char* name, const char* initial) {
    for (const xmlNode* n = node_; n && n->type == XML_ELEMENT_NODE; n = n->parent) {
      const std::string value = css_property(n, name);
      if (!value.empty() && value != "inherit") return value;
    }
    return std::string(initial);
  };
  const std::string join = inherited("stroke-linejoin", "miter"), cap = inherited("stroke-linecap", "butt");
  const bool open = std::any_of(lines.begin(), lines.end(), [](const Polyline& l) { return !l.closed; });
  if (join != "round") state_->warn(what(), "stroke-linejoin " + join + " is drawn round");
  if (open && cap != "round") state_->warn(what(), "stroke-linecap " + cap + " is drawn round");
  // A list that sums to zero draws solid, as "none" does (SVG 1.1, 11.4); so does one with a negative
  // length, an error that renderers draw as "none".
  const std::string dashes = inherited("stroke-dasharray", "none");
  std::string lengths = dashes;
  std::replace(lengths.begin(), lengths.end(), ',', ' ');
  std::istringstream in(lengths);
  bool gaps = false, valid = true;
  for (double length; in >> length; in.ignore(std::numeric_limits<std::streamsize>::max(), ' ')) {
    gaps = gaps || length > 0.0;
    valid = valid && length >= 0.0;
  }
  if (gaps && valid) state_->warn(what(), "stroke-dasharray " + dashes + " is drawn solid");
}

void UseContext::on_exit_element() {
  if (!rendered()) return;
  const std::string href = svg::href(node_);
  if (href.empty()) return;
  if (href[0] != '#') {
    state_->warn(what(), "<use> of \"" + href.substr(0, 80) +
                             "\" refused (another file is never read); copy that art into this file");
    return;
  }
  xmlNode* target = state_->doc.find(href.substr(1));
  if (!target) {
    state_->warn(what(), "<use> refers to missing " + href + "; nothing drawn for it");
    return;
  }
  auto& chain = state_->use_chain;
  bool cycle = target == node_;
  for (const xmlNode* n = node_; n && !cycle; n = n->parent) cycle = n == target;  // use inside its target
  cycle = cycle || std::find(chain.begin(), chain.end(), target) != chain.end();
  if (cycle || chain.size() >= 32) {
    state_->warn(what(), "<use> of " + href + " refers back to itself; the cycle is drawn once");
    return;
  }
  transform_ = compose(transform_, Affine{1, 0, 0, 1, x_, y_});
  chain.push_back(target);
  load_reference(target, *this);
  chain.pop_back();
}

ArtShape run_traversal(const std::string& text, const std::string& name, const SvgOptions& options) {
  Document doc(text, name);
  doc.exclude(options.exclude);
  ArtShape out;
  out.source = name;
  State state(doc, options, out);
  for (const auto& [what, problem] : doc.notes()) state.warn(what, problem);
  GroupContext root(state, doc.root());
  try {
    Traversal::load_document(doc.root(), root);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(message(name, "document", e.what(), "simplify the file in an editor and save it as plain SVG"));
  }
  state.flush_warnings();
  if (!state.gradients.empty()) {
    std::string ids;
    for (const auto& id : state.gradients) ids += (ids.empty() ? "" : ", ") + id;
    out.warnings.push_back(name + ": gradients reduced to their average stop colour: " + ids);
  }
  if (out.paths.empty()) {
    // The warnings usually say why (a pattern fill, text only), so the first one travels along.
    const std::string why = out.warnings.empty() ? ""
                                                 : "; first of " + std::to_string(out.warnings.size()) +
                                                       " warnings: " + out.warnings.front();
    throw InputError(message(name, "<svg>",
                             "no drawable geometry (no filled or stroked path or shape is rendered" + why + ")",
                             "convert text and images to paths and make sure something is visible"));
  }
  return out;
}

}  // namespace animpak::svg

namespace animpak {

ArtShape parse_svg(const std::string& text, const std::string& name, const SvgOptions& options) {
  return svg::run_traversal(text, name, options);
}

ArtShape load_svg(const std::filesystem::path& file, const SvgOptions& options) {
  const std::string name = file.string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(svg::message(name, "file", "cannot be read (" + ec.message() + ")", "check the path"));
  if (size > options.max_file_bytes) {
    throw InputError(svg::message(
        name, "file", std::to_string(size) + " bytes is over the limit of " + std::to_string(options.max_file_bytes),
        "simplify the art, or raise the limit if the file is trusted"));
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(svg::message(name, "file", "cannot be opened", "check the path and its permissions"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(svg::message(name, "file", "read failed", "check the disk and the file"));
  return parse_svg(text, name, options);
}

}  // namespace animpak
