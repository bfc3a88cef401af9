#include "pack_output.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>

#include "animpak/error.hpp"

namespace animpak::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LoadedWorld world_from_checkpoint(const Checkpoint& checkpoint, bool with_state) {
  const auto start = std::chrono::steady_clock::now();
  SceneSpec scene = parse_scene(checkpoint.scene_text, checkpoint.scene_file, checkpoint.scene_file.parent_path());
  scene.seed = checkpoint.seed;
  LoadedWorld loaded{make_world(scene), 0.0};
  if (with_state) {
    const Topology& topo = loaded.world.topology;
    const SimState& s = checkpoint.state;
    if (s.x.size() != std::size_t(topo.vertex_count()) || s.spring_rest.size() != topo.spring_other.size() ||
        s.growth.size() != std::size_t(topo.slice_count()))
      throw InputError(checkpoint.scene_file.string() + ": the scene now builds " + std::to_string(topo.vertex_count()) +
                       " vertices but the state holds " + std::to_string(s.x.size()) +
                       "; the scene or its art changed since packing, so pack it again");
    loaded.world.state = s;
  }
  loaded.setup_seconds = seconds_since(start);
  return loaded;
}

void write_stats(const std::filesystem::path& file, const PackReport& r) {
  using nlohmann::json;
  const World& w = r.world;
  json growth = json::array();
  for (std::size_t e = 0; e < w.elements.size(); ++e) {
    const std::int32_t begin = w.topology.element_slice_begin[e], end = w.topology.element_slice_begin[e + 1];
    float lo = w.state.growth[begin], hi = lo;
    double sum = 0;
    for (std::int32_t s = begin; s < end; ++s) {
      lo = std::min(lo, w.state.growth[s]);
      hi = std::max(hi, w.state.growth[s]);
      sum += w.state.growth[s];
    }
    growth.push_back({{"element", w.elements[e].name}, {"min", lo}, {"mean", sum / (end - begin)}, {"max", hi}});
  }
  json frames = json::array();
  double coverage = 0, min_gap = std::numeric_limits<double>::infinity();
  int max_overlaps = 0;
  for (const FrameMetrics& m : r.frames) {
    frames.push_back({{"t", m.t}, {"coverage", m.coverage}, {"min_gap", m.min_gap}, {"mean_gap", m.mean_gap},
                      {"overlapping_pairs", m.overlapping_pairs}});
    coverage += m.coverage / double(r.frames.size());
    min_gap = std::min(min_gap, m.min_gap);
    max_overlaps = std::max(max_overlaps, m.overlapping_pairs);
  }
  json seconds = {{"setup", r.setup_seconds}, {"simulation", r.result.seconds}};
  for (const NamedPhase& phase : phase_fields) seconds[phase.name] = r.times.*phase.seconds;
  json stats = {
      {"animpak", "0.1.0"},
      {"commit", ANIMPAK_COMMIT},
      {"scene", r.checkpoint.scene_file.string()},
      {"seed", r.checkpoint.seed},
      {"device", r.device},
      {"driver", r.driver},
      {"elements", w.elements.size()},
      {"vertices", w.topology.vertex_count()},
      {"springs", w.topology.spring_other.size() / 2},
      {"envelope_triangles", w.topology.envelope_count()},
      {"iterations", r.result.last_good.iteration},
      {"stop_reason", r.checkpoint.stop_reason},
      {"seconds", seconds},
      {"final_growth", growth},
      {"frames", frames},
      {"summary",
       {{"mean_coverage", coverage}, {"min_gap", r.frames.empty() ? 0.0 : min_gap},
        {"max_overlapping_pairs", max_overlaps}}},
  };
  std::ofstream out(file);
  out << stats.dump(2) << "\n";
  if (!out) throw InputError(file.string() + ": cannot write the statistics; check the folder");
}

}  // namespace animpak::cli
