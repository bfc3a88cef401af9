// `animpak trajectory DIR... --element NAME`: one element's path through the loop in each packing, drawn
// into one SVG (animpak/report.hpp; docs/cli.md, "`trajectory`"), the paper's Fig. 16c for any element.
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/render.hpp"
#include "animpak/report.hpp"
#include "commands.hpp"
#include "pack_output.hpp"
#include "packed_folder.hpp"

namespace animpak::cli {
namespace {

int element_named(const World& world, const std::string& name, const std::filesystem::path& dir) {
  for (std::size_t e = 0; e < world.elements.size(); ++e)
    if (world.elements[e].name == name) return int(e);
  std::string names;
  for (std::size_t e = 0; e < world.elements.size() && e < 40; ++e) names += (e ? ", " : "") + world.elements[e].name;
  if (world.elements.size() > 40) names += ", …";
  throw InputError(dir.string() + ": no element named \"" + name + "\"; its elements are " + names +
                   " (stats.json's final_growth lists them too)");
}

}  // namespace

int trajectory(const TrajectoryOptions& options) {
  TrajectoryFigure figure;
  figure.element = options.element;
  std::vector<double> widths;
  // One lock per folder, each taken once: a folder named twice would otherwise wait on itself.
  std::vector<std::unique_ptr<FolderLock>> locks;
  std::set<std::filesystem::path> locked;
  for (const std::filesystem::path& dir : options.dirs)
    if (std::filesystem::is_directory(dir) && locked.insert(std::filesystem::weakly_canonical(dir)).second) {
      locks.push_back(std::make_unique<FolderLock>(dir, "animpak trajectory " + dir.string()));
      recover_folder(dir);
    }
  for (std::size_t d = 0; d < options.dirs.size(); ++d) {
    const std::filesystem::path& dir = options.dirs[d];
    if (!std::filesystem::exists(dir / "state.bin"))
      throw InputError(dir.string() + ": no state.bin; `animpak trajectory` reads folders `animpak pack` wrote");
    const Checkpoint checkpoint = read_checkpoint(dir / "state.bin");
    const World world = world_from_checkpoint(checkpoint, true, packed_scene(dir, checkpoint)).world;
    const int element = element_named(world, options.element, dir);
    if (d == 0) {
      figure.outline = world.container.shown_outline();
      figure.holes = world.container.shown_holes();
      figure.loop = world.loop;
    } else if (world.loop != figure.loop) {
      throw InputError(dir.string() + ": " + (world.loop ? "loops" : "does not loop") + " but " +
                       options.dirs[0].string() + (figure.loop ? " does" : " does not") +
                       "; draw packings that agree on `loop` together");
    }
    const Box bounds = world.container.shown_bounds();
    widths.push_back(bounds.width());
    TrajectoryRun run;
    run.label = std::filesystem::absolute(dir).lexically_normal().filename().string();
    if (run.label.empty())
      run.label = std::filesystem::absolute(dir).lexically_normal().parent_path().filename().string();
    run.t = frame_times(options.samples, world.loop);
    run.path = element_path(world, world.state, element, run.t);
    if (world.loop) {
      const LoopNeighbours loop = loop_neighbours(world)[std::size_t(element)];
      run.after = loop.into == element ? run.path.front() : element_path(world, world.state, loop.into, {0.0})[0];
      run.before =
          loop.from == element ? run.path.back() : element_path(world, world.state, loop.from, {run.t.back()})[0];
    }
    for (const auto& path : element_art(world, element, element_at(world, world.state, element, 0.0)).points)
      for (const auto& line : path) run.outline_at_0.push_back(line);
    figure.runs.push_back(std::move(run));
  }
  for (std::size_t d = 1; d < widths.size(); ++d)
    if (std::abs(widths[d] - widths[0]) > 1e-6 * std::max(1.0, widths[0]))
      std::cerr << "animpak: " << options.dirs[d].string() << "'s container is " << widths[d] << " wide, "
                << options.dirs[0].string() << "'s " << widths[0] << "; the top view shows the first one's\n";

  for (const TrajectoryRun& run : figure.runs) {
    const TrajectoryStats stats = trajectory_stats(run, widths[0], figure.loop);
    std::cout << std::fixed << std::setprecision(2) << run.label << ": path " << stats.length
              << " container widths per loop, acceleration median " << std::setprecision(1) << stats.acceleration_median
              << ", 99th percentile " << stats.acceleration_p99 << " container widths per loop^2\n";
  }
  const std::filesystem::path file = options.out.value_or(options.dirs[0] / "trajectory.svg");
  write_file_atomically(file, trajectory_svg(figure));
  std::cerr << "animpak: wrote " << file.string() << "\n";
  return 0;
}

}  // namespace animpak::cli
