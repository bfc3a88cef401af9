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

ArtShape load_art(const std::filesystem::path& file, const SvgOptions& options) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".svg") return load_svg(file, options);
  if (ext == ".path") return load_path_file(file);
  throw InputError(file.string() + ": file: unsupported art format \"" + ext +
                   "\"; give an .svg file or a RepulsionPak/AnimationPak .path file");
}

}  // namespace animpak
