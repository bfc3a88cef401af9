#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"
#include "animpak/render.hpp"
#include "animpak/scene.hpp"
#include "commands.hpp"

namespace animpak::cli {
namespace {

struct Built {
  SpacetimeElement element;
  std::vector<std::string> warnings;
};

std::string lower_extension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::vector<Built> build_all(const InspectOptions& options) {
  std::vector<Built> built;
  if (lower_extension(options.file) == ".json") {
    SceneSpec scene = load_scene(options.file);
    if (options.slices) scene.params.element.slices = *options.slices;
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
      const LibraryElementSpec& spec = scene.elements[i];
      const ArtShape art = load_element_art(scene, i);
      built.push_back(
          {build_element(spec.name, art, spec.animation, scene.params, element_seed(scene.seed, i)), art.warnings});
    }
  } else {
    Params params;
    if (options.slices) params.element.slices = *options.slices;
    const ArtShape art = load_art(options.file);
    built.push_back(
        {build_element(options.file.stem().string(), art, AnimationSpec{}, params, element_seed(1, 0)), art.warnings});
  }
  return built;
}

}  // namespace

int inspect(const InspectOptions& options) {
  const std::vector<Built> built = build_all(options);

  nlohmann::ordered_json report = {{"elements", nlohmann::ordered_json::array()}};
  for (const Built& b : built) {
    for (const std::string& w : b.warnings) std::cerr << "animpak: warning: " << w << "\n";
    for (const std::string& n : b.element.notes) std::cerr << "animpak: note: " << b.element.name << ": " << n << "\n";
    const SpacetimeElement& e = b.element;
    report["elements"].push_back({
        {"name", e.name},
        {"slices", e.slice_count},
        {"vertices_per_slice", e.vertices_per_slice()},
        {"vertices", e.vertex_count()},
        {"springs",
         {{"edge", e.springs.count(SpringClass::edge)},
          {"shear", e.springs.count(SpringClass::shear)},
          {"negative_space", e.springs.count(SpringClass::negative_space)},
          {"time", e.springs.count(SpringClass::time)}}},
        {"envelope_triangles", e.envelope.size()},
        {"slices_needed", e.slices_needed},
        {"motion_error", e.motion_error},
    });
    if (const std::string warning = slice_advice_warning(e); !warning.empty())
      std::cerr << "animpak: warning: " << warning << "\n";
  }

  if (options.json) {
    std::cout << report.dump(2) << "\n";
  } else {
    std::printf("%-16s %6s %8s %9s %8s %8s %8s %8s %9s %7s\n", "element", "slices", "v/slice", "vertices", "edge",
                "shear", "neg", "time", "envelope", "needs");
    for (const auto& e : report["elements"]) {
      // "needs": about the fewest slices that keep the scripted motion within 1 % of the element's size on
      // the curve between slices; "-" when it barely moves.
      const int needs = e["slices_needed"].get<int>();
      std::printf("%-16s %6d %8d %9d %8zu %8zu %8zu %8zu %9zu %7s\n", e["name"].get<std::string>().c_str(),
                  e["slices"].get<int>(), e["vertices_per_slice"].get<int>(), e["vertices"].get<int>(),
                  e["springs"]["edge"].get<std::size_t>(), e["springs"]["shear"].get<std::size_t>(),
                  e["springs"]["negative_space"].get<std::size_t>(), e["springs"]["time"].get<std::size_t>(),
                  e["envelope_triangles"].get<std::size_t>(), needs > 0 ? std::to_string(needs).c_str() : "-");
    }
  }

  if (options.out) {
    for (const Built& b : built)
      for (const auto& file : write_inspect_pictures(b.element, *options.out, options.picture_size))
        std::cerr << "animpak: wrote " << file.string() << "\n";
  }
  return 0;
}

}  // namespace animpak::cli
