// Safe parsing of untrusted SVG text with libxml2, the id index `use` and `url(#…)` need, and
// Illustrator's class stylesheets folded into `style` attributes so svgpp sees them.
#include <libxml/parser.h>
#include <libxml/xmlerror.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>

#include "animpak/error.hpp"
#include "json_fields.hpp"
#include "svg_internal.hpp"

namespace animpak::svg {

namespace {

// Elements nested deeper than this are not clip art; refusing them bounds every recursion below.
constexpr int kMaxDepth = 256;

// Untrusted input must never read another file or the network: every external entity or DTD
// fails to load, whatever its URL.
xmlParserInputPtr refuse_external(const char*, const char*, xmlParserCtxtPtr) { return nullptr; }

class LoaderGuard {
 public:
  LoaderGuard() : previous_(xmlGetExternalEntityLoader()) { xmlSetExternalEntityLoader(refuse_external); }
  ~LoaderGuard() { xmlSetExternalEntityLoader(previous_); }
  LoaderGuard(const LoaderGuard&) = delete;
  LoaderGuard& operator=(const LoaderGuard&) = delete;

 private:
  xmlExternalEntityLoader previous_;
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

bool is_svg_element(const xmlNode* n, const char* tag) {
  return n->type == XML_ELEMENT_NODE && xmlStrEqual(n->name, BAD_CAST tag);
}

}  // namespace

std::string message(const std::string& file, const std::string& what, const std::string& problem,
                    const std::string& fix) {
  return file + ": " + what + ": " + problem + "; " + fix;
}

std::string attribute(const xmlNode* node, const char* name, const char* ns_href) {
  xmlChar* v = ns_href ? xmlGetNsProp(node, BAD_CAST name, BAD_CAST ns_href) : xmlGetNoNsProp(node, BAD_CAST name);
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

std::string href(const xmlNode* node) {
  std::string value = attribute(node, "href", "http://www.w3.org/1999/xlink");
  return value.empty() ? attribute(node, "href") : value;
}

std::string describe(const xmlNode* node) {
  const std::string id = attribute(node, "id");
  if (!id.empty()) return reinterpret_cast<const char*>(node->name) + ("#" + id);
  std::string text = "<";
  text.append(reinterpret_cast<const char*>(node->name)).append("> at line ");
  return text.append(std::to_string(xmlGetLineNo(node)));
}

Document::Document(const std::string& text, const std::string& name) : name_(name) {
  if (text.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
    throw InputError(message(name, "file", "too large for the XML parser", "simplify the art"));
  xmlParserCtxtPtr ctxt = xmlNewParserCtxt();
  if (!ctxt) throw InputError(message(name, "document", "out of memory starting the XML parser", "retry"));
  // libxml2 caps one attribute at 10,000,000 characters unless told HUGE, and a traced path of a million
  // points is longer (docs/scene-format.md "Large paths"). HUGE also lifts the limits that stop entity
  // bombs, so it is only given to documents that declare no entity: without a declaration nothing can
  // expand, and the file size limit bounds everything else.
  const bool declares_entities = text.find("<!ENTITY") != std::string::npos;
  {
    const LoaderGuard guard;
    // NOENT expands Illustrator's internal entities (xmlns="&ns_svg;"); external ones hit the loader
    // above and NONET forbids the network.
    doc_ = xmlCtxtReadMemory(ctxt, text.data(), static_cast<int>(text.size()), name.c_str(), nullptr,
                             XML_PARSE_NONET | XML_PARSE_NOENT | XML_PARSE_NOERROR | XML_PARSE_NOWARNING |
                                 (declares_entities ? 0 : XML_PARSE_HUGE));
  }
  const xmlError* err = xmlCtxtGetLastError(ctxt);
  std::string problem;
  int line = 0;
  if (err && err->level >= XML_ERR_ERROR) {
    problem = err->message ? trim(err->message) : "malformed XML";
    line = err->line;
  }
  xmlFreeParserCtxt(ctxt);
  if (!doc_ || !problem.empty()) {
    if (doc_) xmlFreeDoc(doc_);
    doc_ = nullptr;
    const bool maybe_long = declares_entities && text.size() > 10000000;
    throw InputError(message(name, "line " + std::to_string(line), "not well-formed XML (" + problem + ")",
                             maybe_long ? "in a file that declares entities (<!ENTITY>) one attribute may hold at "
                                          "most 10000000 characters; expand the entities and remove the "
                                          "declarations, or split the longest path"
                                        : "check that the file is an SVG saved as plain XML"));
  }
  root_ = xmlDocGetRootElement(doc_);
  if (!root_ || !is_svg_element(root_, "svg")) {
    const std::string tag = root_ ? reinterpret_cast<const char*>(root_->name) : "(empty)";
    xmlFreeDoc(doc_);
    throw InputError(message(name, "<" + tag + ">", "the root element is not <svg>",
                             "give an SVG file (its outermost element must be <svg>)"));
  }
  // Old Inkscape files declare only xmlns:svg and leave their elements un-namespaced; editors
  // still draw them, so they are read as SVG rather than refused as empty.
  if (!root_->ns) svg_ns_ = xmlNewNs(root_, BAD_CAST "http://www.w3.org/2000/svg", nullptr);
  index(root_, 0);
  apply_class_styles();
}

Document::~Document() { xmlFreeDoc(doc_); }

xmlNode* Document::find(const std::string& id) const {
  const auto it = by_id_.find(id);
  return it == by_id_.end() ? nullptr : it->second;
}

void Document::index(xmlNode* node, int depth) {
  if (depth > kMaxDepth) {
    throw InputError(message(name_, describe(node), "elements nested deeper than " + std::to_string(kMaxDepth),
                             "flatten the groups in an editor"));
  }
  if (!node->ns && svg_ns_) xmlSetNs(node, svg_ns_);
  if (is_svg_element(node, "ellipse")) resolve_auto_radii(node);
  const std::string id = attribute(node, "id");
  if (!id.empty()) by_id_.emplace(id, node);  // the first element with an id wins, as in browsers
  for (xmlNode* c = node->children; c; c = c->next)
    if (c->type == XML_ELEMENT_NODE) index(c, depth + 1);
}

void Document::resolve_auto_radii(xmlNode* ellipse) {
  // SVG 2: an ellipse's rx or ry that is auto (or absent) takes the other's value, as svgpp cannot (it
  // reads SVG 1.1, where both are required). A percentage is of the other axis, so it is left for the
  // importer to report.
  const std::string rx = trim(attribute(ellipse, "rx")), ry = trim(attribute(ellipse, "ry"));
  const auto is_auto = [](const std::string& v) { return v.empty() || v == "auto"; };
  const auto is_length = [&](const std::string& v) { return !is_auto(v) && v.find('%') == std::string::npos; };
  if (is_auto(rx) && is_length(ry)) xmlSetProp(ellipse, BAD_CAST "rx", BAD_CAST ry.c_str());
  if (is_auto(ry) && is_length(rx)) xmlSetProp(ellipse, BAD_CAST "ry", BAD_CAST rx.c_str());
}

namespace {

std::vector<std::string> classes_of(const xmlNode* n) {
  std::istringstream in(attribute(n, "class"));
  std::vector<std::string> classes;
  for (std::string c; in >> c;) classes.push_back(c);
  return classes;
}

bool selector_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) || c == '-' || c == '_' || u >= 0x80;
}

// One compound selector: an optional type (or *), then #ids and .classes.
struct Compound {
  std::string type;  // empty: any element
  std::vector<std::string> ids, classes;
  bool parse(const std::string& text) {
    size_t i = 0;
    const auto ident = [&] {
      const size_t start = i;
      while (i < text.size() && selector_char(text[i])) ++i;
      return text.substr(start, i - start);
    };
    if (i < text.size() && text[i] == '*')
      ++i;
    else
      type = ident();
    while (i < text.size()) {
      const char c = text[i++];
      if (c != '.' && c != '#') return false;
      const std::string name = ident();
      if (name.empty()) return false;
      (c == '.' ? classes : ids).push_back(name);
    }
    return !text.empty();
  }
  bool matches(const xmlNode* n) const {
    if (!n || n->type != XML_ELEMENT_NODE) return false;
    if (!type.empty() && !xmlStrEqual(n->name, BAD_CAST type.c_str())) return false;
    for (const std::string& id : ids)
      if (attribute(n, "id") != id) return false;
    if (classes.empty()) return true;
    const std::vector<std::string> own = classes_of(n);
    for (const std::string& c : classes)
      if (std::find(own.begin(), own.end(), c) == own.end()) return false;
    return true;
  }
};

// Compound selectors joined by descendant (space) and child (>) combinators.
struct Selector {
  std::vector<Compound> parts;
  std::vector<char> joins;  // joins[k] between parts[k] and parts[k + 1]: ' ' or '>'
  bool parse(const std::string& text) {
    std::string token;
    char join = 0;
    const auto flush = [&] {
      if (token.empty()) return true;
      Compound c;
      if (!c.parse(token)) return false;
      if (!parts.empty()) joins.push_back(join ? join : ' ');
      parts.push_back(c);
      token.clear();
      join = 0;
      return true;
    };
    for (char c : text) {
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '>') {
        if (!flush()) return false;
        if (c == '>') {
          if (parts.empty() || join == '>') return false;
          join = '>';
        }
      } else {
        token += c;
      }
    }
    return flush() && join == 0 && !parts.empty();
  }
  // The element and its ancestors, nearest first: at[k][i] says parts[0..k] match with parts[k] on chain[i].
  // One pass per part over the chain (at most kMaxDepth long), so no selector costs more than that.
  bool matches(const xmlNode* n) const {
    std::vector<const xmlNode*> chain;
    for (const xmlNode* a = n; a && a->type == XML_ELEMENT_NODE; a = a->parent) chain.push_back(a);
    const size_t len = chain.size();
    std::vector<char> prev(len + 1, 0), cur(len + 1, 0);
    for (size_t k = 0; k < parts.size(); ++k) {
      // any_above[i]: the previous part matched somewhere at chain[i] or farther out.
      std::vector<char> any_above(len + 2, 0);
      for (size_t i = len; i-- > 0;) any_above[i] = any_above[i + 1] || prev[i];
      for (size_t i = 0; i < len; ++i) {
        const bool before = k == 0 || (joins[k - 1] == '>' ? prev[i + 1] != 0 : any_above[i + 1] != 0);
        cur[i] = before && parts[k].matches(chain[i]);
      }
      cur[len] = 0;
      std::swap(prev, cur);
    }
    return prev[0] != 0;
  }
  // CSS specificity (ids, classes, types) as one comparable number.
  long specificity() const {
    long total = 0;
    for (const Compound& c : parts)
      total += static_cast<long>(c.ids.size()) * 1000000 + static_cast<long>(c.classes.size()) * 1000 +
               (c.type.empty() ? 0 : 1);
    return total;
  }
};

struct Rule {
  Selector selector;
  size_t order;
  std::string declarations;
};

// Declarations that change what is drawn; a rule the importer cannot apply is reported only if it has one.
bool draws(const std::string& declarations) {
  static const char* const properties[] = {"fill",  "stroke",      "opacity", "transform", "display", "visibility",
                                           "color", "paint-order", "clip",    "mask",      "filter",  "overflow"};
  for (const char* p : properties)
    if (declarations.find(p) != std::string::npos) return true;
  return false;
}

// Elements that draw or hold what draws: what an `exclude` selector is meant to name.
bool draws_art(const xmlNode* n) {
  static const char* const tags[] = {"path", "rect", "circle", "ellipse", "line",   "polyline", "polygon",
                                     "g",    "use",  "svg",    "a",       "switch", "symbol"};
  return std::any_of(std::begin(tags), std::end(tags), [&](const char* t) { return is_svg_element(n, t); });
}

// What to say of an `exclude` selector that matches nothing: the id or class it most likely meant, else
// the ids and classes of the elements that draw, the first few of each.
std::string exclude_hint(const std::string& selector, const std::vector<xmlNode*>& all) {
  std::vector<std::string> ids, classes;
  for (const xmlNode* n : all) {
    // The root is all of the art, never a piece of it.
    if (!draws_art(n) || n == all.front()) continue;
    const std::string id = attribute(n, "id");
    if (selector_name(id)) ids.push_back("#" + id);
    for (const std::string& c : classes_of(n))
      if (std::find(classes.begin(), classes.end(), "." + c) == classes.end() && selector_name(c))
        classes.push_back("." + c);
  }
  std::vector<std::string_view> names(ids.begin(), ids.end());
  names.insert(names.end(), classes.begin(), classes.end());
  const std::string near = io_detail::closest_name(selector, names);
  if (!near.empty()) return "did you mean \"" + near + "\"?";
  if (names.empty())
    return "no element of it that draws has an id or a class; give the piece an id in your editor and exclude "
           "\"#that-id\"";
  const auto listed = [](const std::vector<std::string>& v) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(v.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + v[i];
    if (v.size() > shown) text += " and " + std::to_string(v.size() - shown) + " more";
    return text;
  };
  const std::string what =
      ids.empty() ? "the elements that draw have no ids; their classes are " + listed(classes)
      : classes.empty()
          ? "the ids of the elements that draw are " + listed(ids) + "; they have no classes"
          : "the ids of the elements that draw are " + listed(ids) + "; their classes are " + listed(classes);
  return what + " (`animpak check` names the pieces of the art and how to leave each out)";
}

}  // namespace

void Document::exclude(const std::vector<std::string>& selectors) {
  if (selectors.empty()) return;
  std::vector<xmlNode*> all;  // every element, in document order
  std::vector<xmlNode*> stack{root_};
  while (!stack.empty()) {
    xmlNode* n = stack.back();
    stack.pop_back();
    all.push_back(n);
    std::vector<xmlNode*> children;
    for (xmlNode* c = n->children; c; c = c->next)
      if (c->type == XML_ELEMENT_NODE) children.push_back(c);
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  for (std::size_t k = 0; k < selectors.size(); ++k) {
    const std::string text = trim(selectors[k]);
    Selector selector;
    if (!selector.parse(text))
      throw ExcludeError(name_, k, selectors[k],
                         "not a selector; give \"#id\" or \".class\" (or types, #ids and .classes joined by spaces "
                         "or >, as a <style> rule takes them)");
    bool matched = false;
    for (xmlNode* n : all) {
      if (!selector.matches(n)) continue;
      matched = true;
      // Everything inside it goes too, so that a <use> of something inside draws nothing either.
      std::vector<const xmlNode*> inside{n};
      while (!inside.empty()) {
        const xmlNode* m = inside.back();
        inside.pop_back();
        if (!excluded_.insert(m).second) continue;
        for (const xmlNode* c = m->children; c; c = c->next)
          if (c->type == XML_ELEMENT_NODE) inside.push_back(c);
      }
    }
    if (!matched)
      throw ExcludeError(name_, k, selectors[k], "matches no element of the file; " + exclude_hint(text, all));
  }
}

void Document::apply_class_styles() {
  // Exporters write `<style>.st0{fill:#F00;}</style>` and class="st0" (Illustrator), or type and id
  // rules. A rule outranks presentation attributes and loses to the inline style; among rules, the more
  // specific wins, then the later (CSS 2.1, 6.4.3). Prefixing the `style` attribute with the matching
  // rules in that order puts each declaration exactly there. Compound selectors of a type, ids and classes,
  // joined by descendant and child combinators, are applied; sibling combinators, attribute selectors and
  // pseudo-classes are not, and are reported.
  std::vector<Rule> rules;
  std::vector<xmlNode*> stack{root_};
  std::vector<xmlNode*> elements;
  while (!stack.empty()) {
    xmlNode* n = stack.back();
    stack.pop_back();
    if (is_svg_element(n, "style")) {
      xmlChar* content = xmlNodeGetContent(n);
      std::string css = content ? reinterpret_cast<const char*>(content) : "";
      xmlFree(content);
      for (auto c = css.find("/*"); c != std::string::npos; c = css.find("/*")) {
        const auto e = css.find("*/", c + 2);
        css.erase(c, e == std::string::npos ? std::string::npos : e + 2 - c);
      }
      std::istringstream in(css);
      std::string block;
      while (std::getline(in, block, '}')) {
        const auto brace = block.find('{');
        if (brace == std::string::npos) continue;
        const std::string decls = trim(block.substr(brace + 1));
        // A statement at-rule before the selectors (`@import url(x);`) ends at its semicolon.
        std::string prelude = block.substr(0, brace);
        if (const auto semicolon = prelude.rfind(';'); semicolon != std::string::npos) prelude.erase(0, semicolon + 1);
        std::istringstream selectors(prelude);
        std::string sel;
        while (std::getline(selectors, sel, ',')) {
          sel = trim(sel);
          if (sel.empty()) continue;
          if (sel[0] == '@') {
            // @font-face and the like hold no art styles, and @import is never loaded; the rules inside
            // @media or @supports are not applied, and that is said when they would draw.
            if ((sel.rfind("@media", 0) == 0 || sel.rfind("@supports", 0) == 0) && draws(decls))
              notes_.push_back({"<style> at line " + std::to_string(xmlGetLineNo(n)),
                                sel.substr(0, sel.find(' ')) + " rules are not applied; their styles are ignored"});
            continue;
          }
          Selector parsed;
          if (parsed.parse(sel)) {
            rules.push_back({parsed, rules.size(), decls});
          } else if (draws(decls)) {
            notes_.push_back({"<style> at line " + std::to_string(xmlGetLineNo(n)),
                              "CSS selector \"" + sel.substr(0, 60) +
                                  "\" is not supported (only types, #ids and .classes, joined by spaces or >); "
                                  "its rule is ignored"});
          }
        }
      }
    }
    elements.push_back(n);
    for (xmlNode* c = n->children; c; c = c->next)
      if (c->type == XML_ELEMENT_NODE) stack.push_back(c);
  }
  if (rules.empty()) return;
  std::stable_sort(rules.begin(), rules.end(), [](const Rule& a, const Rule& b) {
    return a.selector.specificity() != b.selector.specificity() ? a.selector.specificity() < b.selector.specificity()
                                                                : a.order < b.order;
  });
  for (xmlNode* n : elements) {
    std::string prefix;
    for (const Rule& rule : rules)
      if (rule.selector.matches(n)) prefix += rule.declarations + ";";
    if (prefix.empty()) continue;
    const std::string style = prefix + attribute(n, "style");
    xmlSetProp(n, BAD_CAST "style", BAD_CAST style.c_str());
  }
}

}  // namespace animpak::svg

namespace animpak {

bool selector_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), svg::selector_char);
}

}  // namespace animpak
