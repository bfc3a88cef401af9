#include "console.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>
#include <vector>

namespace animpak::cli {
namespace fs = std::filesystem;
namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::uintmax_t size_of_tree(const fs::path& dir, int& files) {
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file(ec)) total += e.file_size(ec), ++files;
  return total;
}

// "3 PNG frames", "1 SVG frame", "3 PNG and 3 SVG frames"; empty for none.
std::string frame_count_text(int png, int svg) {
  std::string what;
  if (png) what += std::to_string(png) + " PNG";
  if (svg) what += std::string(what.empty() ? "" : " and ") + std::to_string(svg) + " SVG";
  return what.empty() ? what : what + (png + svg == 1 ? " frame" : " frames");
}

}  // namespace

std::string shell_word(const std::string& word) {
  if (!word.empty() &&
      word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./+,:=@") ==
          std::string::npos)
    return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string clock_text(double seconds) {
  char s[32];
  const long t = static_cast<long>(seconds);
  std::snprintf(s, sizeof s, "%02ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return s;
}

std::string size_text(std::uintmax_t bytes) {
  char s[32];
  if (bytes < 1024) {
    std::snprintf(s, sizeof s, "%ju B", bytes);
    return s;
  }
  const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
  double v = double(bytes) / 1024;
  int u = 0;
  while (v >= 1024 && u < 3) v /= 1024, ++u;
  std::snprintf(s, sizeof s, "%.1f %s", v, units[u]);
  return s;
}

std::string pack_progress_text(const StepStatistics& st, double elapsed, const std::optional<StopEstimate>& estimate,
                               bool verbose) {
  char gap[16];
  std::snprintf(gap, sizeof gap, std::isfinite(st.max_slice_gap) ? "%.4f" : "inf", st.max_slice_gap);
  std::ostringstream line;
  line << "iter " << st.iteration << "  gap " << gap << "  growing " << static_cast<int>(100 * st.growing_share)
       << "%  " << clock_text(elapsed) << "  "
       << (estimate ? "~" + clock_text(estimate->seconds_left) + " left" + (estimate->secondary_pending ? "+" : "")
                    : std::string("estimating"));
  if (verbose)
    line << "  overlaps " << st.overlapping_vertices << "  outside " << st.outside_vertices << "  g " << st.min_growth
         << ".." << st.max_growth;
  return line.str();
}

std::string profile_text(const PhaseTimes& times, const std::vector<KernelTime>& kernels, std::uint64_t iterations,
                         double simulation_seconds) {
  std::ostringstream out;
  const auto row = [&](const std::string& name, double seconds, const std::string& extra) {
    char line[128];
    const double share = simulation_seconds > 0 ? 100.0 * seconds / simulation_seconds : 0.0;
    const double per_iteration = iterations > 0 ? 1000.0 * seconds / static_cast<double>(iterations) : 0.0;
    std::snprintf(line, sizeof line, "  %-34.34s %9.2f s %5.1f %% %9.3f ms%s\n", name.c_str(), seconds, share,
                  per_iteration, extra.c_str());
    out << line;
  };
  out << "profile: " << iterations << " iterations, " << clock_text(simulation_seconds) << " of simulation\n";
  out << "  phase                                     time    share   per iter\n";
  double phases = 0.0;
  for (const NamedPhase& phase : phase_fields) {
    row(phase.name, times.*phase.seconds, "");
    phases += times.*phase.seconds;
  }
  // The rest: what the phases do not time (the host waiting on the device, the run loop, the checks).
  row("(not in a phase)", simulation_seconds > phases ? simulation_seconds - phases : 0.0, "");
  if (kernels.empty()) return out.str();
  std::vector<KernelTime> sorted = kernels;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const KernelTime& a, const KernelTime& b) { return a.seconds > b.seconds; });
  out << "  kernel (phase)                            time    share   per iter  launches\n";
  for (const KernelTime& k : sorted) {
    if (k.launches == 0) continue;
    row(k.name + " (" + k.phase + ")", k.seconds, " " + std::to_string(k.launches));
  }
  return out.str();
}

double ProgressShare::update(double elapsed, std::optional<double> seconds_left) {
  if (!seconds_left) return shown_;
  const double total = elapsed + std::max(*seconds_left, 0.0);
  const double share = total > 0.0 ? std::clamp(elapsed / total, 0.0, 1.0) : 0.0;
  shown_ = std::max(shown_, share);
  return shown_;
}

std::string progress_bar(double done) {
  const int width = 8;
  const int filled = static_cast<int>(width * std::clamp(done, 0.0, 1.0));
  return "[" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
}

std::string render_progress_text(const std::string& stage, int done, int total, double elapsed) {
  std::ostringstream line;
  if (stage == "frame") {
    line << "render: frame " << done << "/" << total << "  " << clock_text(elapsed);
    if (done > 0 && done < total) line << "  ~" << clock_text(elapsed * double(total - done) / done) << " left";
  } else {
    line << "render: " << (stage == "between slices" ? "measuring between slices" : "writing " + stage) << "  "
         << clock_text(elapsed);
  }
  return line.str();
}

RenderProgress::RenderProgress() : tty_(::isatty(STDERR_FILENO)), start_(now()) {}

void RenderProgress::operator()(const std::string& stage, int done, int total) {
  const double elapsed = now() - start_;
  const bool new_stage = stage != last_stage_;
  last_stage_ = stage;
  if (tty_ ? elapsed - last_print_ < 0.2 && !new_stage && done != total
           : elapsed - last_print_ < 5.0 && !(new_stage && stage != "frame"))
    return;
  last_print_ = elapsed;
  const std::string text = render_progress_text(stage, done, total, elapsed);
  if (tty_) {
    std::cerr << "\ranimpak: " << text << "\033[K" << std::flush;
    drawn_ = true;
  } else {
    std::cerr << "animpak: " << text << "\n";
  }
}

void RenderProgress::finish() {
  if (drawn_) std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

std::string written_files(const fs::path& dir, WrittenBy by, const std::vector<fs::path>& removed) {
  struct Row {
    std::string name, what;
  };
  std::vector<Row> rows;
  std::error_code ec;
  auto file = [&](const std::string& name) {
    if (fs::is_regular_file(dir / name, ec)) rows.push_back({name, size_text(fs::file_size(dir / name, ec))});
  };
  if (by == WrittenBy::pack) {
    file("state.bin");
    if (fs::is_directory(dir / "input", ec)) {
      int n = 0;
      const std::uintmax_t bytes = size_of_tree(dir / "input", n);
      rows.push_back({"input/", std::to_string(n) + " files, " + size_text(bytes)});
    }
  }
  file("stats.json");
  if (fs::is_directory(dir / "frames", ec)) {
    int png = 0, svg = 0;
    std::uintmax_t bytes = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "frames", ec)) {
      if (!e.is_regular_file(ec)) continue;
      const std::string ext = e.path().extension().string();
      if (ext != ".png" && ext != ".svg") continue;
      (ext == ".png" ? png : svg) += 1;
      bytes += e.file_size(ec);
    }
    if (png + svg) rows.push_back({"frames/", frame_count_text(png, svg) + ", " + size_text(bytes)});
  }
  for (const char* name :
       {"animation.gif", "animation.mp4", "animation.json", "animation.lottie", "animation.svg", "contact.png"})
    file(name);
  std::ostringstream out;
  out << "animpak: files in " << dir.string() << ":\n";
  for (const Row& r : rows) {
    std::string name = r.name;
    name.resize(std::max<std::size_t>(name.size(), 18), ' ');
    out << "  " << name << r.what << "\n";
  }
  // The run before's rendered files that are gone (docs/cli.md, "The output folder"): one written again
  // under its name is listed above instead.
  int removed_png = 0, removed_svg = 0;
  std::vector<std::string> gone;
  std::set<fs::path> seen;
  for (const fs::path& old : removed) {
    if (!seen.insert(old).second || fs::exists(fs::symlink_status(dir / old, ec))) continue;
    if (old.parent_path() == "frames")
      (old.extension() == ".svg" ? removed_svg : removed_png) += 1;
    else
      gone.push_back(old.string());
  }
  if (removed_png + removed_svg)
    gone.insert(gone.begin(), "frames/ (" + frame_count_text(removed_png, removed_svg) + ")");
  if (gone.empty()) return out.str();
  const std::size_t indent = 20;  // the sizes' column above
  std::string line = "  removed:";
  line.resize(indent, ' ');
  for (std::size_t i = 0; i < gone.size(); ++i) {
    const std::string item = gone[i] + (i + 1 < gone.size() ? "," : "");
    if (line.size() > indent && line.size() + 1 + item.size() > 80) {
      out << line << "\n";
      line.assign(indent, ' ');
    }
    if (line.size() > indent) line += ' ';
    line += item;
  }
  out << line << "\n";
  return out.str();
}

}  // namespace animpak::cli
