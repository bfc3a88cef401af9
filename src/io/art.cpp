// Art-format dispatch and the bounds every later stage normalises by.
#include <algorithm>
#include <cctype>

#include "animpak/error.hpp"
#include "animpak/io.hpp"

namespace animpak {

Box ArtShape::bounds() const {
  Box box;
  for (const ArtPath& path : paths)
    for (const Polyline& line : path.polylines)
      for (Vec2 p : line.points) box.add(p);
  return box;
}

std::string lineage_text(const ArtPath& path) {
  if (path.lineage.empty()) return "path " + std::to_string(path.source_index);
  std::string text;
  for (const ArtOrigin& o : path.lineage) {
    text += (text.empty() ? "" : " > ") + o.tag + (o.id.empty() ? "" : "#" + o.id);
    for (const std::string& c : o.classes) text += "." + c;
  }
  return text;
}

ArtShape load_art(const std::filesystem::path& file, const SvgOptions& options) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".svg") return load_svg(file, options);
  if (ext == ".path") {
    // The authors' format has no ids or classes, so nothing can be selected in it.
    if (!options.exclude.empty())
      throw InputError(file.string() + ": exclude: a .path file has no ids or classes to select a piece by; " +
                       "remove the exclude, or use the art as SVG with an id on the piece");
    return load_path_file(file);
  }
  throw InputError(file.string() + ": file: unsupported art format \"" + ext +
                   "\"; give an .svg file or a RepulsionPak/AnimationPak .path file");
}

}  // namespace animpak
