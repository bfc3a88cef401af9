// The still reference of a scene (docs/quality.md, "Still reference"): the same elements standing still,
// written as scene text so that the packing folder's copy of it renders and resumes like any other.
#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "animpak/scene_spec.hpp"

namespace animpak {

std::string still_scene_text(const std::string& text, const SceneSpec& scene, double container_scale) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(text);
  // A container that moves stands still at its mean size, about the same pivot.
  const AnimationSpec& motion = scene.container.animation;
  if (motion.preset != AnimationPreset::none || !motion.keys.empty()) {
    nlohmann::ordered_json still = {{"keys", nlohmann::ordered_json::array({{{"t", 0}, {"scale", container_scale}}})}};
    if (doc["container"]["animation"].contains("pivot")) still["pivot"] = doc["container"]["animation"]["pivot"];
    doc["container"]["animation"] = still;
  }
  nlohmann::ordered_json& elements = doc["elements"];
  for (nlohmann::ordered_json& e : elements) {
    e.erase("animation");
    e.erase("phase");
  }
  // Each guided element becomes one more ordinary copy of its library element: by its count where it has
  // one, else by the scene's count (then drawn by weight), else the scene fills and places what fits.
  for (const GuidedSpec& g : scene.guided) {
    const auto it = std::find_if(scene.elements.begin(), scene.elements.end(),
                                 [&](const LibraryElementSpec& e) { return e.name == g.element; });
    nlohmann::ordered_json& e = elements[static_cast<std::size_t>(it - scene.elements.begin())];
    if (e.contains("count"))
      e["count"] = e["count"].get<int>() + 1;
    else if (doc.contains("count"))
      doc["count"] = doc["count"].get<int>() + 1;
  }
  doc.erase("guided");
  const int slices = std::min(scene.params.element.slices, still_slices);
  if (doc.contains("params")) doc["params"].erase("slices");
  doc["slices"] = slices;
  return doc.dump(2) + "\n";
}

}  // namespace animpak
