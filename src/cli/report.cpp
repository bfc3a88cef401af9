// `animpak report DIR`: the packing in DIR as one self-contained HTML page (animpak/report.hpp; docs/cli.md,
// "`report`"). Reads DIR/stats.json for every figure, rebuilds the world from state.bin and DIR/input/ for the
// table of elements, and embeds DIR/animation.svg, drawing one into a scratch folder when the packing was
// rendered without it.
#include <fstream>
#include <iostream>
#include <sstream>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/report.hpp"
#include "commands.hpp"
#include "pack_output.hpp"

namespace animpak::cli {
namespace {

// The animated SVG from its first "<svg" on (the file has no XML declaration today; an older one may).
std::string svg_element(const std::string& text, const std::filesystem::path& file) {
  const std::size_t at = text.find("<svg");
  if (at == std::string::npos)
    throw InputError(file.string() + ": not an SVG; run `animpak render " + file.parent_path().string() +
                     " --format png,gif,svg-anim` to write it again");
  return text.substr(at);
}

}  // namespace

int report(const ReportOptions& options) {
  const std::filesystem::path stats_file = options.dir / "stats.json";
  if (!std::filesystem::exists(options.dir / "state.bin"))
    throw InputError(options.dir.string() + ": no state.bin; `animpak report` reads a folder `animpak pack` wrote");
  const FolderLock lock(options.dir, "animpak report " + options.dir.string());
  recover_folder(options.dir);
  if (!std::filesystem::exists(stats_file))
    throw InputError(stats_file.string() + ": not found; run `animpak render " + options.dir.string() +
                     "`, which measures the frames and writes it");
  ReportInput input;
  std::optional<Stats> stats = read_stats_json(stats_file);
  if (!stats)
    throw InputError(stats_file.string() +
                     ": not a packing's stats.json (not JSON, or without its fields); run `animpak render " +
                     options.dir.string() + "` to write it again");
  input.stats = std::move(*stats);
  if (!input.stats.frames || input.stats.frames->empty())
    throw InputError(stats_file.string() +
                     ": no frames (packed with --no-render, or by animpak-solve); run `animpak render " +
                     options.dir.string() + "` first, which measures the frames the report plots");
  input.title = std::filesystem::absolute(options.dir).lexically_normal().filename().string();
  if (input.title.empty())
    input.title = std::filesystem::absolute(options.dir).lexically_normal().parent_path().filename().string();

  const Checkpoint checkpoint = read_checkpoint(options.dir / "state.bin");
  const PackedScene packed = packed_scene(options.dir, checkpoint);
  LoadedWorld loaded = world_from_checkpoint(checkpoint, true, packed);
  const World& world = loaded.world;
  // The element count the file names, and its per-element rows when it has them, against the state's.
  std::size_t stats_elements = std::size_t(input.stats.elements);
  if (input.stats.final_growth && !input.stats.final_growth->empty() && stats_elements == world.elements.size())
    stats_elements = input.stats.final_growth->size();
  if (stats_elements != world.elements.size())
    throw InputError(stats_file.string() + ": " + std::to_string(stats_elements) + " elements, but state.bin has " +
                     std::to_string(world.elements.size()) +
                     "; the statistics are another packing's: run `animpak render " + options.dir.string() +
                     "` to measure this one");
  std::vector<std::string> thumbnails(world.library.size());
  for (std::size_t l = 0; l < world.library.size(); ++l) thumbnails[l] = art_svg(world.library[l].art.art, 44);
  for (const ElementInstance& e : world.elements) {
    const SpacetimeElement& lib = world.library[e.library];
    input.elements.push_back({e.name, lib.name, lib.art.art.source.filename().string(),
                              e.guided      ? "guided"
                              : e.secondary ? "secondary"
                                            : "unguided",
                              thumbnails[e.library]});
  }

  const std::filesystem::path animation = options.dir / "animation.svg", gif = options.dir / "animation.gif";
  const bool have_svg = std::filesystem::exists(animation);
  const std::uintmax_t svg_bytes = have_svg ? std::filesystem::file_size(animation) : 0;
  if (svg_bytes > kInlineSvgLimit && std::filesystem::exists(gif)) {
    // Too large to open quickly inline: the GIF stands in, and the page says so.
    const std::uintmax_t megabytes = (svg_bytes + (1u << 19)) >> 20;
    input.animation_gif = read_folder_file(options.dir, "animation.gif", "render the folder again");
    input.animation_note = "animation.svg (" + std::to_string(megabytes) +
                           " MB) is too large to open quickly inside a page, so this shows animation.gif; the slider "
                           "moves the plots' cursor. Open animation.svg beside this page for the vector animation.";
    std::cerr << "animpak: " << animation.string() << " is " << megabytes
              << " MB; the page shows animation.gif instead (the slider then moves the plots' cursor only)\n";
  } else if (have_svg) {
    input.animation_svg =
        svg_element(read_folder_file(options.dir, "animation.svg", "render the folder again"), animation);
  } else {
    // Drawn as `render --format svg-anim` would, with the frame count the statistics were measured at; the
    // folder's own files are left as they are.
    std::cerr << "animpak: " << options.dir.string() << " has no animation.svg; drawing one for the report ("
              << input.stats.frames->size() << " frames; `animpak render DIR --format png,gif,svg-anim` keeps one)\n";
    const std::filesystem::path scratch = options.dir / ".report-partial";
    std::filesystem::remove_all(scratch);
    std::filesystem::create_directories(scratch);
    FrameOutput out;
    out.dir = scratch;
    out.count = int(input.stats.frames->size());
    out.formats = {FrameFormat::svg_anim};
    write_frames(world, world.state, out);
    input.animation_svg = svg_element(read_folder_file(scratch, "animation.svg", "check that the folder is writable"),
                                      scratch / "animation.svg");
    std::filesystem::remove_all(scratch);
  }

  const std::filesystem::path file = options.out.value_or(options.dir / "report.html");
  const std::string page = report_page(input);
  write_file_atomically(file, page);
  std::cerr << "animpak: wrote " << file.string() << " (" << (page.size() + 1023) / 1024 << " KiB, self-contained)\n";
  return 0;
}

}  // namespace animpak::cli
