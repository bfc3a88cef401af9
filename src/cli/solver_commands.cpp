// `animpak-solve`: the solver commands of run.cpp and nothing that draws, so that it links neither Cairo nor
// OpenImageIO and runs on a GPU machine that has only an OpenCL driver. pack writes state.bin and stats.json
// (without frame metrics); the frames are drawn later by `animpak render DIR` where the rendering stack is.
#include <CLI/CLI.hpp>

#include <iostream>

#include "frontend.hpp"

namespace animpak::cli {
namespace {

class SolverFrontend final : public Frontend {
 public:
  std::string name() const override { return "animpak-solve"; }
  std::string description() const override {
    return "animpak-solve: the animpak solver without rendering (AnimationPak); draw the frames with "
           "`animpak render DIR` on a machine with Cairo and OpenImageIO";
  }

  void add_commands(CLI::App& app, CLI::App& pack, CLI::App& bench) override {
    pack.description("Pack a scene's animated elements into its container; writes state.bin and stats.json");
    // Accepted so that a command line written for `animpak pack --no-render` runs unchanged here.
    pack.add_flag("--no-render")->description("implied: animpak-solve never renders frames");
    // Refused while parsing, with the reason, rather than as an unknown option or after minutes of timing.
    bench.add_option("--plot")
        ->description("not in animpak-solve: the plot needs the rendering library")
        ->check([](const std::string&) {
          return std::string("the plot needs the rendering library; use animpak bench --plot, or plot the --json file");
        });
    app.footer(app.get_footer() +
               " Not here (they need Cairo and OpenImageIO): inspect, render, bench --plot; "
               "use the full animpak.");
  }

  std::optional<int> run_own_command() override { return std::nullopt; }

  // Not a renderer: the place where pack would draw says where the frames will come from instead.
  FrameRenderer frame_renderer() const override {
    return [](const World&, const std::filesystem::path& dir, const BesideFrames&) {
      std::cerr << "animpak: no frames rendered (animpak-solve has no rendering library); render them with "
                   "`animpak render "
                << dir.string() << "` on a machine with the rendering stack\n";
      return Rendered{};
    };
  }

  BenchPlotter bench_plotter() const override { return {}; }
};

}  // namespace

}  // namespace animpak::cli

int main(int argc, char** argv) {
  return animpak::cli::run(argc, argv, std::make_unique<animpak::cli::SolverFrontend>());
}
