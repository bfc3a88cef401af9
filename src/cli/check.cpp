// `animpak check`: the preflight a designer runs on one art file before packing it. It reports what the
// importer took from the file and what the element builder made of it (the same calls as inspect and pack),
// every warning on the way, and can draw the art as imported at the document's own viewport so it can be
// held next to a browser's rendering. docs/check.md describes the report and its JSON.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unordered_set>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "animpak/render.hpp"
#include "animpak/scene.hpp"
#include "commands.hpp"

namespace animpak::cli {
namespace {

using Json = nlohmann::ordered_json;

// The frames draw strokes thinner than this many pixels this wide (Picture::draw_art); the preview does not.
constexpr double thinnest_stroke_px = 0.5;

std::string hex_colour(const Rgba& c) {
  char text[8];
  const auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

Json box_json(const Box& box) { return {box.min.x, box.min.y, box.width(), box.height()}; }

// Rings are compared on the 1e-9 grid painted_region rounds to, so a vertex of a path's own region that
// survives into the union is found exactly.
struct GridKey {
  long long x, y;
  bool operator==(const GridKey&) const = default;
};
struct GridHash {
  std::size_t operator()(const GridKey& k) const { return std::hash<long long>()(k.x * 1000003LL ^ k.y); }
};
GridKey grid_key(Vec2 p) { return {std::llround(p.x * 1e9), std::llround(p.y * 1e9)}; }

// Which paths reach the outer boundary of everything the art paints (the boundary the element's outline
// is offset from, §3.1), and the holes inside it, which the solid element fills.
struct ArtOutline {
  std::vector<bool> on_outline;  // per path
  std::vector<double> hole_areas;
};

ArtOutline outline_of(const ArtShape& unit_art) {
  ArtOutline out;
  std::unordered_set<GridKey, GridHash> outer;
  for (const auto& ring : painted_region(unit_art)) {
    if (signed_area(ring) < 0.0) {
      out.hole_areas.push_back(-signed_area(ring));
      continue;
    }
    for (Vec2 p : ring) outer.insert(grid_key(p));
  }
  // Arcs as fine as element_outline's, so the same stroke vertices come out.
  constexpr double arc_tolerance = 1e-4;
  for (const ArtPath& path : unit_art.paths) {
    std::vector<std::vector<Vec2>> points;
    for (const Polyline& line : path.polylines) points.push_back(line.points);
    bool reaches = false;
    for (const auto& ring : painted_region(path, points, path.stroke_width, arc_tolerance))
      reaches = reaches || std::any_of(ring.begin(), ring.end(), [&](Vec2 p) { return outer.count(grid_key(p)) > 0; });
    out.on_outline.push_back(reaches);
  }
  return out;
}

Json paint_json(const Paint& paint) {
  if (!paint.enabled) return nullptr;
  return {{"color", hex_colour(paint.color)}, {"opacity", paint.color.a}};
}

std::string describe_path(const ArtPath& path, std::size_t index) {
  return path.id.empty() ? "path " + std::to_string(index) : path.id;
}

// Paths that share one problem, each with how many of its subpaths have it.
struct PathCounts {
  std::vector<std::string> names;
  int total = 0;
  void add(const std::string& name, int count) {
    names.push_back(name);
    total += count;
  }
};

// One warning line for a problem: "file: path3: 2 …" for one path, "file: 19 paths (path3, path5, path7 and
// 16 more): 23 …" (the subpaths of all of them) for several, as the importer groups its own.
void warn_paths(std::vector<std::string>& warnings, const std::string& file, const PathCounts& paths,
                const std::string& problem) {
  if (paths.names.empty()) return;
  std::string who = paths.names.front();
  if (paths.names.size() > 1) {
    who = std::to_string(paths.names.size()) + " paths (";
    const std::size_t shown = std::min<std::size_t>(paths.names.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) who += (i ? ", " : "") + paths.names[i];
    if (paths.names.size() > shown) who += " and " + std::to_string(paths.names.size() - shown) + " more";
    who += ")";
  }
  warnings.push_back(file + ": " + who + ": " + std::to_string(paths.total) + problem);
}

// The report's paths and the warnings only the check adds: what the import keeps silently but a browser
// user should know (open subpaths that are filled as if closed, subpaths crossing themselves).
Json paths_json(const ArtShape& art, const std::string& file, std::vector<std::string>& warnings) {
  PathCounts open_filled, crossing_nonzero, crossing_evenodd;
  Json paths = Json::array();
  for (std::size_t i = 0; i < art.paths.size(); ++i) {
    const ArtPath& path = art.paths[i];
    int open = 0, crossing = 0;
    std::size_t points = 0;
    for (const Polyline& line : path.polylines) {
      open += line.closed ? 0 : 1;
      crossing += crosses_itself(line) ? 1 : 0;
      points += line.points.size();
    }
    if (open > 0 && path.fill.enabled) open_filled.add(describe_path(path, i), open);
    if (crossing > 0)
      (path.fill_rule == FillRule::evenodd ? crossing_evenodd : crossing_nonzero).add(describe_path(path, i), crossing);
    Json stroke = paint_json(path.stroke);
    if (!stroke.is_null()) stroke["width"] = path.stroke_width;
    paths.push_back({{"index", i},
                     {"source_index", path.source_index},
                     {"id", path.id},
                     {"path_type", path.path_type},
                     {"subpaths", path.polylines.size()},
                     {"open_subpaths", open},
                     {"self_intersecting_subpaths", crossing},
                     {"points", points},
                     {"fill", paint_json(path.fill)},
                     {"fill_rule", path.fill_rule == FillRule::evenodd ? "evenodd" : "nonzero"},
                     {"stroke", stroke},
                     {"on_outline", false}});
  }
  warn_paths(warnings, file, open_filled,
             " open subpath(s) filled as if closed (as SVG fills them); the element's outline takes them in closed");
  warn_paths(warnings, file, crossing_nonzero,
             " subpath(s) cross themselves; the non-zero fill rule decides what is inside, as in a browser");
  warn_paths(warnings, file, crossing_evenodd,
             " subpath(s) cross themselves; the even-odd fill rule decides what is inside, as in a browser");
  return paths;
}

Json element_json(const SpacetimeElement& e, const ArtOutline& outline, const Params& params) {
  Box art_box = e.art.art.bounds(), ring_box;
  for (Vec2 p : e.slice.vertices) ring_box.add(p);
  return {{"scale", e.art.frame.scale},
          {"size", {art_box.width(), art_box.height()}},
          {"offset", params.element.offset},
          {"outline_size", {ring_box.width(), ring_box.height()}},
          {"boundary_vertices", e.slice.boundary_count},
          {"slice_vertices", e.vertices_per_slice()},
          {"holes", outline.hole_areas}};
}

// The `exclude` entries that leave out `piece` and nothing else: for each of its paths, the outermost
// element it is drawn through whose #id (else one of its .classes) selects only paths of the piece;
// `unnamed` gets the paths that no such selector reaches (they need an id). A path that also paints in
// another piece cannot be left out without it and is in neither list.
struct PieceExclusion {
  std::vector<std::string> selectors;
  std::vector<int> unnamed;
};

PieceExclusion piece_exclusion(const ArtShape& art, const std::vector<OutlinePiece>& pieces, std::size_t k) {
  const auto in_piece = [&](int path, std::size_t piece) {
    const std::vector<int>& paths = pieces[piece].paths;
    return std::find(paths.begin(), paths.end(), path) != paths.end();
  };
  const auto only_here = [&](int path) {
    for (std::size_t other = 0; other < pieces.size(); ++other)
      if (other != k && in_piece(path, other)) return false;
    return in_piece(path, k);
  };
  // Whether `selects(origin)` holds only on paths drawn wholly in this piece.
  const auto confined = [&](const auto& selects) {
    for (std::size_t i = 0; i < art.paths.size(); ++i)
      for (const ArtOrigin& o : art.paths[i].lineage)
        if (selects(o) && !only_here(static_cast<int>(i))) return false;
    return true;
  };
  PieceExclusion out;
  std::vector<int> covered;
  for (const int path : pieces[k].paths) {
    if (!only_here(path) || std::find(covered.begin(), covered.end(), path) != covered.end()) continue;
    std::string chosen;
    for (const ArtOrigin& o : art.paths[path].lineage) {
      if (selector_name(o.id) && confined([&](const ArtOrigin& x) { return x.id == o.id; })) chosen = "#" + o.id;
      for (std::size_t c = 0; chosen.empty() && c < o.classes.size(); ++c)
        if (selector_name(o.classes[c]) && confined([&](const ArtOrigin& x) {
              return std::find(x.classes.begin(), x.classes.end(), o.classes[c]) != x.classes.end();
            }))
          chosen = "." + o.classes[c];
      if (!chosen.empty()) break;
    }
    if (chosen.empty()) {
      out.unnamed.push_back(path);
      continue;
    }
    out.selectors.push_back(chosen);
    // Everything the selector leaves out is covered.
    const bool by_id = chosen[0] == '#';
    const std::string name = chosen.substr(1);
    for (std::size_t i = 0; i < art.paths.size(); ++i)
      for (const ArtOrigin& o : art.paths[i].lineage)
        if (by_id ? o.id == name : std::find(o.classes.begin(), o.classes.end(), name) != o.classes.end())
          covered.push_back(static_cast<int>(i));
  }
  return out;
}

// The pieces the art's offset outline comes in (docs/check.md, "Pieces of the art"): each one's share of
// the painted area, whether it was bridged or dropped, its paths and the `exclude` entries that leave it out.
Json pieces_json(const ArtShape& art, const SpacetimeElement& e) {
  Json pieces = Json::array();
  for (std::size_t k = 0; k < e.outline_pieces.size(); ++k) {
    const OutlinePiece& piece = e.outline_pieces[k];
    Json paths = Json::array();
    for (const int i : piece.paths)
      paths.push_back({{"index", i}, {"id", art.paths[i].id}, {"element", lineage_text(art.paths[i])}});
    Json entry = {{"share", piece.share},
                  {"state", k == 0          ? "largest"
                            : piece.dropped ? "dropped"
                                            : "bridged"},
                  {"paths", paths}};
    if (k > 0) {
      const PieceExclusion exclusion = piece_exclusion(art, e.outline_pieces, k);
      entry["exclude"] = exclusion.selectors;
      entry["unnamed_paths"] = exclusion.unnamed;
    }
    pieces.push_back(entry);
  }
  return pieces;
}

void print_pieces(const Json& element, const std::string& file, bool path_file) {
  const Json& pieces = element["pieces"];
  if (pieces.empty()) return;
  const double radius = element["bridge_radius"].get<double>();
  char bridged[64] = "";
  if (radius > 0.0) std::snprintf(bridged, sizeof bridged, ", bridged with a closing of radius %g", radius);
  std::printf("pieces     the art's outline comes in %zu pieces%s; paths numbered as in the table above:\n",
              pieces.size(), bridged);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Json& piece = pieces[k];
    const Json& paths = piece["paths"];
    std::printf(
        "  %zu  %5.1f %% of the art's area, %s: %zu path%s\n", k + 1, 100.0 * piece["share"].get<double>(),
        piece["state"].get<std::string>() == "largest" ? "the largest" : piece["state"].get<std::string>().c_str(),
        paths.size(), paths.size() == 1 ? "" : "s");
    if (k == 0) continue;
    const std::size_t shown = std::min<std::size_t>(paths.size(), 6);
    for (std::size_t i = 0; i < shown; ++i)
      std::printf("       path %d: %s\n", paths[i]["index"].get<int>(), paths[i]["element"].get<std::string>().c_str());
    if (paths.size() > shown) std::printf("       and %zu more\n", paths.size() - shown);
    const std::vector<std::string> selectors = piece["exclude"];
    const std::vector<int> unnamed = piece["unnamed_paths"];
    if (path_file) {
      std::printf("     a .path file cannot leave a piece out: delete it in an editor, or use the art as SVG\n");
      continue;
    }
    if (!selectors.empty()) {
      std::string entry, flags;
      for (const std::string& s : selectors) {
        entry.append(entry.empty() ? "" : ", ").append(Json(s).dump());
        flags += " --exclude '" + s + "'";
      }
      std::printf("     to leave it out, add to the scene's element: \"exclude\": [%s]\n", entry.c_str());
      std::printf("     (animpak check %s%s --png OUT shows the art without it)\n", file.c_str(), flags.c_str());
    }
    if (!unnamed.empty()) {
      std::string list;
      for (const int i : unnamed) list.append(list.empty() ? "" : ", ").append(std::to_string(i));
      std::printf(
          "     path%s %s %s no id or class of %s own that selects only this piece: give %s an id in your "
          "editor to leave %s out\n",
          unnamed.size() == 1 ? "" : "s", list.c_str(), unnamed.size() == 1 ? "has" : "have",
          unnamed.size() == 1 ? "its" : "their", unnamed.size() == 1 ? "it" : "each",
          unnamed.size() == 1 ? "it" : "them");
    }
  }
}

std::string path_name(const ArtShape& art, int source_index) {
  for (const ArtPath& p : art.paths)
    if (p.source_index == source_index && !p.id.empty())
      return "path " + std::to_string(source_index) + " (" + p.id + ")";
  return "path " + std::to_string(source_index);
}

const ArtPath* path_at(const ArtShape& art, int source_index) {
  for (const ArtPath& p : art.paths)
    if (p.source_index == source_index) return &p;
  return nullptr;
}

// The container as pack takes it (make_container; docs/scene-format.md, "`container`"): which paths are its
// outline and holes, their areas and the area left for the elements, in the art's units and, after
// normalizing (longer side 1), in the unit square the seeds and parameters are measured in.
Json container_json(const Container& c, const ArtShape& art, const std::string& file,
                    std::vector<std::string>& warnings) {
  const double per_unit = 1.0 / (c.frame.scale * c.frame.scale);  // unit-square area → art units²
  const auto ring_json = [&](int path, const std::vector<Vec2>& ring) {
    const ArtPath* p = path_at(art, path);
    return Json{{"path", path},
                {"id", p ? p->id : ""},
                {"points", ring.size()},
                {"area", std::abs(signed_area(ring)) * per_unit},
                {"unit_area", std::abs(signed_area(ring))}};
  };
  Json holes = Json::array();
  for (std::size_t i = 0; i < c.holes.size(); ++i) holes.push_back(ring_json(c.hole_paths[i], c.holes[i]));
  const Box unit = c.bounds();
  const Vec2 art_min = c.frame.to_art(unit.min), art_max = c.frame.to_art(unit.max);
  // A boundary path lying wholly inside the outline that is not a hole is packed over: in an SVG, where no
  // path is a hole by default, it usually was meant as one.
  for (const ArtPath& p : c.art.paths) {
    if (p.source_index == c.outline_path || p.path_type != 0 ||
        std::find(c.hole_paths.begin(), c.hole_paths.end(), p.source_index) != c.hole_paths.end())
      continue;
    bool inside = !p.polylines.empty();
    double area = 0.0;
    for (const Polyline& line : p.polylines) {
      area += std::abs(signed_area(line.points));
      inside = inside &&
               std::all_of(line.points.begin(), line.points.end(), [&](Vec2 q) { return ring_contains(c.outline, q); });
    }
    if (inside && area > 0.0)
      warnings.push_back(file + ": " + path_name(art, p.source_index) +
                         " lies inside the container's outline but is not a hole: elements are packed over it; to "
                         "keep them out, list it in the scene's container.holes (check --container --holes " +
                         std::to_string(p.source_index) + " shows the result)");
  }
  return {{"outline", ring_json(c.outline_path, c.outline)},
          {"holes", holes},
          {"area", c.area() * per_unit},
          {"unit_area", c.area()},
          {"bounds", {art_min.x, art_min.y, art_max.x - art_min.x, art_max.y - art_min.y}},
          {"scale", c.frame.scale},
          {"size", {unit.width(), unit.height()}}};
}

void print_container(const Json& c) {
  const auto ring = [](const Json& r) {
    char text[160];
    std::snprintf(text, sizeof text, "path %d%s%s%s: %d points, area %.6g (%.3g of the unit square)",
                  r["path"].get<int>(), r["id"].get<std::string>().empty() ? "" : " (",
                  r["id"].get<std::string>().c_str(), r["id"].get<std::string>().empty() ? "" : ")",
                  r["points"].get<int>(), r["area"].get<double>(), r["unit_area"].get<double>());
    return std::string(text);
  };
  const Json& b = c["bounds"];
  std::printf("outline    %s\n", ring(c["outline"]).c_str());
  std::printf("holes      %zu%s\n", c["holes"].size(), c["holes"].empty() ? "" : ":");
  for (const Json& h : c["holes"]) std::printf("  %s\n", ring(h).c_str());
  std::printf("area       %.6g art units² for the elements (outline minus holes), %.3g of the unit square\n",
              c["area"].get<double>(), c["unit_area"].get<double>());
  std::printf("bounds     %g %g %g %g (art units: x y width height); %.3g x %.3g after normalizing (x %.3g)\n",
              b[0].get<double>(), b[1].get<double>(), b[2].get<double>(), b[3].get<double>(),
              c["size"][0].get<double>(), c["size"][1].get<double>(), c["scale"].get<double>());
}

void print_text(const Json& report) {
  const Json& doc = report["document"];
  std::printf("file       %s\n", report["file"].get<std::string>().c_str());
  if (doc["viewport"].is_null()) {
    std::printf("viewport   none set (the preview frames the painted art)\n");
  } else {
    const Json& v = doc["viewport"];
    std::printf("viewport   %g %g %g %g (art units: x y width height)\n", v[0].get<double>(), v[1].get<double>(),
                v[2].get<double>(), v[3].get<double>());
  }
  const Json& paths = report["paths"];
  int filled = 0, stroked = 0, open = 0, crossing = 0;
  std::string outline;
  for (const Json& p : paths) {
    filled += p["fill"].is_null() ? 0 : 1;
    stroked += p["stroke"].is_null() ? 0 : 1;
    open += p["open_subpaths"].get<int>();
    crossing += p["self_intersecting_subpaths"].get<int>();
  }
  std::printf("paths      %zu: %d filled, %d stroked; %d open subpaths, %d crossing themselves\n", paths.size(), filled,
              stroked, open, crossing);
  const bool container = report.contains("container");
  std::printf("  %4s %-20s %-8s %-16s %-8s %8s %8s %s\n", "#", "id", "fill", "stroke (width)", "rule", "subpaths",
              "points", container ? "role" : "outline");
  for (const Json& p : paths) {
    std::string stroke = "-";
    if (!p["stroke"].is_null()) {
      char width[32];
      std::snprintf(width, sizeof width, " (%.3g)", p["stroke"]["width"].get<double>());
      stroke = p["stroke"]["color"].get<std::string>() + width;
    }
    std::printf("  %4d %-20s %-8s %-16s %-8s %8d %8d %s\n", p["index"].get<int>(), p["id"].get<std::string>().c_str(),
                p["fill"].is_null() ? "-" : p["fill"]["color"].get<std::string>().c_str(), stroke.c_str(),
                p["fill_rule"].get<std::string>().c_str(), p["subpaths"].get<int>(), p["points"].get<int>(),
                container                     ? p["role"].get<std::string>().c_str()
                : p["on_outline"].get<bool>() ? "yes"
                                              : "");
  }
  if (report.contains("element")) {
    const Json& e = report["element"];
    std::printf(
        "element    %.3g x %.3g after normalizing (art units x %.3g); outline offset %g: %.3g x %.3g, %d "
        "boundary and %d slice vertices\n",
        e["size"][0].get<double>(), e["size"][1].get<double>(), e["scale"].get<double>(), e["offset"].get<double>(),
        e["outline_size"][0].get<double>(), e["outline_size"][1].get<double>(), e["boundary_vertices"].get<int>(),
        e["slice_vertices"].get<int>());
    const std::size_t holes = e["holes"].size();
    if (holes > 0)
      std::printf("holes      %zu in the art, filled by the element (its outline is the outer boundary only)\n", holes);
    std::string extension = std::filesystem::path(report["file"].get<std::string>()).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    print_pieces(e, report["file"].get<std::string>(), extension == ".path");
  }
  if (container) print_container(report["container"]);
  if (report.contains("exclude")) {
    std::string list;
    for (const Json& s : report["exclude"]) list.append(list.empty() ? "" : " ").append(s.get<std::string>());
    std::printf("excluded   %s (left out of the outline and the drawing)\n", list.c_str());
  }
  std::printf("warnings   %zu%s\n", report["warnings"].size(), report["warnings"].empty() ? "" : " (on stderr)");
  if (report.contains("png")) std::printf("preview    %s\n", report["png"].get<std::string>().c_str());
  if (container)
    std::printf("%s\n", report["ready"].get<bool>() ? "ready to pack into (as a container)" : "cannot be packed into");
  else
    std::printf("%s\n", report["ready"].get<bool>() ? "ready to pack" : "cannot be packed");
}

}  // namespace

int check(const CheckOptions& options) {
  Json report = {{"file", options.file.string()}, {"ready", false}};
  // What cannot be imported or built goes out as the error every command gives (exit 2); --json first
  // says so on stdout, so scripts always get an object.
  const auto refuse = [&](const InputError& e) {
    if (options.json) {
      report["error"] = e.what();
      std::cout << report.dump(2) << "\n";
    }
  };
  // A scene is checked for its container, read as pack reads it: the scene's outline, holes and tolerance.
  std::filesystem::path art_file = options.file;
  std::optional<ContainerSpec> container;
  std::vector<std::string> scene_notes;  // what the scene itself warns of, as pack does
  SvgOptions import;
  std::string extension = options.file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".json") {
    try {
      const SceneSpec scene = load_scene(options.file);
      container = scene.container;
      import.flatten_tolerance = scene.params.art.flatten_tolerance;
      for (const std::string& warning : scene_warnings(scene))
        scene_notes.push_back(options.file.string() + ": " + warning);
    } catch (const InputError& e) {
      refuse(e);
      throw;
    }
    art_file = container->art;
    report = {{"file", art_file.string()}, {"scene", options.file.string()}, {"ready", false}};
  } else if (options.container) {
    container = ContainerSpec{};
    container->art = options.file;
    container->outline = options.outline;
    if (!options.holes.empty()) container->holes = options.holes;
  }
  if (!options.exclude.empty()) {
    // Only an element leaves pieces out (its scene entry's `exclude`); a scene's container has no such field.
    if (container)
      throw UsageError(
          "--exclude leaves pieces out of an element's art; a scene's container cannot (check the "
          "element's art file instead)");
    import.exclude = options.exclude;
    report["exclude"] = options.exclude;
  }
  const std::string file = art_file.string();
  ArtShape art;
  try {
    art = load_art(art_file, import);
  } catch (const InputError& e) {
    refuse(e);
    throw;
  }
  std::vector<std::string> warnings = scene_notes;
  warnings.insert(warnings.end(), art.warnings.begin(), art.warnings.end());
  report["document"] = {{"viewport", art.viewport ? box_json(*art.viewport) : Json(nullptr)},
                        {"bounds", box_json(art.bounds())}};
  report["paths"] = paths_json(art, file, warnings);

  if (options.png) {
    // Drawn before the element is built: the picture of what was imported helps most when building fails.
    const Picture preview = draw_art_preview(art, options.size);
    const double px_per_unit = preview.to_pixel({1, 0}).x - preview.to_pixel({0, 0}).x;
    int thin = 0;
    for (const ArtPath& path : art.paths)
      thin += path.stroke.enabled && path.stroke_width * px_per_unit < thinnest_stroke_px ? 1 : 0;
    if (thin > 0) {
      std::ostringstream text;
      text << file << ": " << thin << " stroke(s) are thinner than " << thinnest_stroke_px << " px at " << options.size
           << " px: the preview draws them at their width, as a browser does; frames of that "
           << "size widen them to " << thinnest_stroke_px << " px";
      warnings.push_back(text.str());
    }
    preview.write(*options.png);
    report["png"] = options.png->string();
  }

  if (container) {
    try {
      const Container c = make_container(art, *container);
      for (Json& path : report["paths"]) {
        const int index = path["source_index"].get<int>();
        path.erase("on_outline");
        path["role"] = index == c.outline_path                                           ? "outline"
                       : std::count(c.hole_paths.begin(), c.hole_paths.end(), index) > 0 ? "hole"
                                                                                         : "";
      }
      report["container"] = container_json(c, art, file, warnings);
    } catch (const InputError& e) {
      report["warnings"] = warnings;
      for (const std::string& w : warnings) std::cerr << "animpak: warning: " << w << "\n";
      refuse(e);
      throw;
    }
  } else {
    if (std::any_of(art.paths.begin(), art.paths.end(), [](const ArtPath& p) { return p.path_type == 7; }))
      warnings.push_back(file +
                         ": has hole paths (.path type 7), as a container has; this is its report as an element, "
                         "`animpak check --container " +
                         file + "` reports it as a container");
    try {
      const Params params;
      const SpacetimeElement element =
          build_element(options.file.stem().string(), art, AnimationSpec{}, params, element_seed(1, 0));
      const ArtOutline outline = outline_of(element.art.art);
      for (std::size_t i = 0; i < outline.on_outline.size(); ++i)
        report["paths"][i]["on_outline"] = outline.on_outline[i];
      report["element"] = element_json(element, outline, params);
      report["element"]["pieces"] = pieces_json(element.art.art, element);
      report["element"]["bridge_radius"] = element.bridge_radius;
      warnings.insert(warnings.end(), element.notes.begin(), element.notes.end());
    } catch (const InputError& e) {
      report["warnings"] = warnings;
      for (const std::string& w : warnings) std::cerr << "animpak: warning: " << w << "\n";
      refuse(e);
      throw;
    }
  }
  report["warnings"] = warnings;
  report["ready"] = true;
  for (const std::string& w : warnings) std::cerr << "animpak: warning: " << w << "\n";
  if (options.json)
    std::cout << report.dump(2) << "\n";
  else
    print_text(report);
  return 0;
}

}  // namespace animpak::cli
