// `animpak sweep` and `animpak sweep-task` (docs/sweeps.md): a plan of runs, each an ordinary `pack` into
// DIR/runs/ID/ run as a child process of this same program (docs/architecture.md, "Sweeps"), so that a run
// that crashes is recorded as failed and the others go on. A run's state is its folder: what it needs next
// (a pack, a resume, a render, the report page) is read from what is there, so running the plan again
// continues it, and a run is the same whichever machine runs it.
#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <ctime>
#include <deque>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include "animpak/error.hpp"
#include "animpak/file_io.hpp"
#include "animpak/report.hpp"
#include "animpak/sha256.hpp"
#include "animpak/version.hpp"
#include "commands.hpp"
#include "console.hpp"
#include "pack_output.hpp"
#include "packed_folder.hpp"
#include "sweep_plan.hpp"

namespace animpak::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// ---- Stop signals: a sweep stops launching, passes the signal on to its packs and waits for them.

std::atomic<int> stop_signal{0};
extern "C" void on_sweep_signal(int signal) { stop_signal.store(signal); }

class SweepSignals {
 public:
  SweepSignals() {
    stop_signal.store(0);
    struct sigaction action {};
    action.sa_handler = on_sweep_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: poll() returns at once
    for (std::size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &action, &previous_[i]);
  }
  SweepSignals(const SweepSignals&) = delete;
  SweepSignals& operator=(const SweepSignals&) = delete;
  ~SweepSignals() {
    for (std::size_t i = 0; i < std::size(kSignals); ++i) sigaction(kSignals[i], &previous_[i], nullptr);
  }

 private:
  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction previous_[std::size(kSignals)]{};
};

bool is_stop_signal(int signal) { return signal == SIGINT || signal == SIGTERM || signal == SIGHUP; }

const char* signal_name(int signal) {
  return signal == SIGINT    ? "Ctrl-C (SIGINT)"
         : signal == SIGTERM ? "SIGTERM"
         : signal == SIGHUP  ? "SIGHUP"
                             : "a signal";
}

// ---- One run at a time per run: a lock (flock) on DIR/status/ID.lock, held for as long as the run runs.

class RunLock {
 public:
  /// The lock, or nullopt with `held_by` saying who holds it. `holder` empty: only look (the lock is let go
  /// at once and the file left as it is).
  static std::optional<RunLock> try_take(const fs::path& file, const std::string& holder, std::string& held_by) {
    const int fd =
        take_lock_file(file, holder, "the run's lock", "remove the link; animpak keeps a run's lock there", held_by);
    if (fd < 0) return std::nullopt;
    return RunLock(fd);
  }
  RunLock(RunLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  RunLock& operator=(RunLock&& other) noexcept {
    std::swap(fd_, other.fd_);
    return *this;
  }
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock() {
    if (fd_ >= 0) ::close(fd_);
  }

 private:
  explicit RunLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? std::string(name) : std::string("unknown");
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// This program's own path, which every run's pack runs as a child.
std::string own_executable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec || self.empty())
    throw InputError("/proc/self/exe: cannot find animpak's own path to run each pack (" + ec.message() +
                     "); a sweep needs Linux's /proc");
  return self.string();
}

// ---- A child process with its output read through a pipe.

struct Child {
  pid_t pid = -1;
  int output = -1;  ///< the read end of its stdout and stderr
};

Child spawn(const std::string& program, const std::vector<std::string>& args) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw InputError(std::string("cannot start a pack: pipe: ") + std::strerror(errno));
  std::vector<std::string> words = {program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw InputError(std::string("cannot start a pack: fork: ") + std::strerror(error));
  }
  if (pid == 0) {
    // A pack outlives no sweep: killed outright, the sweep takes its packs down with it, each saving its state
    // as SIGTERM makes it (the run then resumes).
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(128 + SIGTERM);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::execv(program.c_str(), argv.data());
    const char* message = "animpak: error: cannot run the pack's program\n";
    static_cast<void>(::write(STDERR_FILENO, message, std::strlen(message)));
    ::_exit(127);
  }
  ::close(fds[1]);
  ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  return {pid, fds[0]};
}

// The last lines of a child's output, as the status file keeps them.
std::string tail_lines(const std::string& text, std::size_t lines) {
  std::size_t at = text.size();
  if (at > 0 && text[at - 1] == '\n') --at;
  for (std::size_t n = 0; at > 0; --at)
    if (text[at - 1] == '\n' && ++n == lines) break;
  return text.substr(at);
}

// The error a failed child printed last (its `animpak: error: …` line), without the prefix.
std::string error_line(const std::string& output) {
  const std::string marker = "error: ";
  std::size_t at = output.rfind("animpak: " + marker);
  if (at == std::string::npos) return {};
  at += std::string("animpak: ").size() + marker.size();
  return output.substr(at, output.find('\n', at) - at);
}

// The run's scene, DIR/scenes/ID.json, from the sweep's copy of the scene in DIR/input/ (its art checked
// against the manifest's hashes, read from nowhere else) with the run's seed and settings.
void write_run_scene(const fs::path& dir, const SweepPlan& plan, const SweepRun& run) {
  Checkpoint scene;
  scene.scene_text = read_folder_file(dir, fs::path("input") / plan.scene_file, "plan the sweep again");
  scene.scene_file = dir / "input" / plan.scene_file;
  if (sha256_hex(scene.scene_text) != plan.scene_sha256)
    throw InputError(scene.scene_file.string() + ": is not the scene " + (dir / "plan.json").string() +
                     " was planned with (its SHA-256 differs); plan the sweep again into another folder");
  const PackedScene packed = packed_scene(dir, scene);
  const std::string text = run_scene_text(scene.scene_text, run, [&](const std::string& written) {
    const fs::path copy = packed.locate(written, {});
    return (fs::path("..") / copy.lexically_relative(dir)).generic_string();
  });
  fs::create_directories(dir / "scenes");
  write_file_atomically(run_scene_file(dir, run), text);
}

// ---- Running runs.

struct RunResult {
  std::string state;  ///< done, failed, interrupted, busy (another animpak runs it)
  std::string message;
};

class Runner {
 public:
  Runner(const fs::path& dir, const SweepPlan& plan, std::string program, bool echo)
      : dir_(dir), plan_(plan), program_(std::move(program)), echo_(echo), host_(host_name()) {}

  /// Runs `runs` (indices into the plan), `jobs` at a time; returns each run's result by index.
  std::vector<std::pair<std::size_t, RunResult>> run(const std::vector<std::size_t>& runs, int jobs) {
    std::deque<std::size_t> queue(runs.begin(), runs.end());
    std::vector<std::pair<std::size_t, RunResult>> results;
    bool forwarded = false;
    while (true) {
      while (stop_signal.load() == 0 && int(active_.size()) < jobs && !queue.empty()) {
        const std::size_t index = queue.front();
        queue.pop_front();
        if (std::optional<RunResult> r = start(index)) results.emplace_back(index, *r);
      }
      if (active_.empty()) break;
      if (stop_signal.load() != 0 && !forwarded) {
        // Each pack saves its state and exits (130, 143, 129); one already stopped by a terminal's Ctrl-C
        // takes the second signal as the first.
        for (const Active& a : active_) ::kill(a.child.pid, stop_signal.load());
        forwarded = true;
      }
      wait_a_little();
      for (std::size_t k = 0; k < active_.size();) {
        int status = 0;
        if (::waitpid(active_[k].child.pid, &status, WNOHANG) != active_[k].child.pid) {
          ++k;
          continue;
        }
        read_output(active_[k]);
        ::close(active_[k].child.output);
        active_[k].child = {};
        if (std::optional<RunResult> r = finished(active_[k], status)) {
          results.emplace_back(active_[k].index, *r);
          active_.erase(active_.begin() + std::ptrdiff_t(k));
        } else {
          ++k;  // its next step started
        }
      }
    }
    return results;
  }

 private:
  struct Active {
    std::size_t index = 0;
    RunLock lock;
    Child child;
    RunStep step = RunStep::none;
    std::vector<RunStep> steps;
    std::string output;
    std::string started;
    double start = 0.0;
  };

  const SweepRun& plan_run(std::size_t index) const { return plan_.runs[index]; }

  void write_status(const Active& a, const std::string& state, const std::string& message, int exit_code) {
    const SweepRun& run = plan_run(a.index);
    json steps = json::array();
    for (RunStep s : a.steps) steps.push_back(step_name(s));
    json status = {{"id", run.id},
                   {"index", run.index},
                   {"state", state},
                   {"message", message},
                   {"steps", steps},
                   {"host", host_},
                   {"started", a.started},
                   {"seconds", seconds_now() - a.start},
                   {"output", tail_lines(a.output, 40)}};
    if (state != "running") status["ended"] = utc_now();
    if (exit_code >= 0) status["exit_code"] = exit_code;
    write_file_atomically(run_status_file(dir_, run), status.dump(2) + "\n");
  }

  // Takes the run's lock and starts its first step; a result when there is nothing to start.
  std::optional<RunResult> start(std::size_t index) {
    const SweepRun& run = plan_run(index);
    // The sweep's folder is data: no link in it leads a run's files elsewhere (docs/cli.md, "What survives").
    for (const fs::path& relative :
         {fs::path("runs") / run.id, fs::path("scenes") / (run.id + ".json"), fs::path("status") / (run.id + ".json")})
      refuse_links_below(dir_, relative, "remove the link; a sweep writes its runs inside its folder");
    std::string held_by;
    std::optional<RunLock> lock = RunLock::try_take(
        dir_ / "status" / (run.id + ".lock"),
        "pid " + std::to_string(::getpid()) + " on " + host_ + ": animpak sweep " + dir_.string() + "\n", held_by);
    if (!lock) {
      say(run,
          "another animpak is running it" + (held_by.empty() ? std::string() : " (" + held_by + ")") + "; left to it");
      return RunResult{"busy", held_by};
    }
    Active a{index, std::move(*lock), {}, RunStep::none, {}, {}, utc_now(), seconds_now()};
    try {
      const RunStep step = next_step(dir_, run);
      if (step == RunStep::none) {
        say(run, "already complete");
        return RunResult{"done", "already complete"};
      }
      write_run_scene(dir_, plan_, run);
      launch(a, step);
      write_status(a, "running", "", -1);
    } catch (const std::exception& e) {
      // Its folder or its scene cannot be used: this run fails, the others go on.
      a.output += std::string("animpak: error: ") + e.what() + "\n";
      write_status(a, "failed", e.what(), -1);
      say(run, std::string("failed: ") + e.what());
      return RunResult{"failed", e.what()};
    }
    active_.push_back(std::move(a));
    return std::nullopt;
  }

  void launch(Active& a, RunStep step) {
    const SweepRun& run = plan_run(a.index);
    const std::vector<std::string> args = step_arguments(step, dir_, plan_, run);
    std::string line = "animpak";
    for (const std::string& w : args) line += " " + shell_word(w);
    a.output += "$ " + line + "\n";
    if (echo_) std::cerr << "animpak: sweep-task: " << line << "\n" << std::flush;
    say(run, step_name(step));
    a.step = step;
    a.steps.push_back(step);
    a.child = spawn(program_, args);
  }

  void wait_a_little() {
    std::vector<pollfd> fds;
    for (const Active& a : active_)
      if (a.child.output >= 0) fds.push_back({a.child.output, POLLIN, 0});
    if (fds.empty() || ::poll(fds.data(), fds.size(), 200) <= 0) {
      if (fds.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
      return;
    }
    for (Active& a : active_)
      if (a.child.output >= 0) read_output(a);
  }

  void read_output(Active& a) {
    char buffer[4096];
    while (true) {
      const ssize_t n = ::read(a.child.output, buffer, sizeof buffer);
      if (n <= 0) break;
      a.output.append(buffer, std::size_t(n));
      if (echo_) std::cerr.write(buffer, n).flush();
    }
    // The tail is what the status keeps.
    if (a.output.size() > (256u << 10)) a.output.erase(0, a.output.size() - (128u << 10));
  }

  // A step ended: the next one started (nullopt), or the run's result, recorded in its status file.
  std::optional<RunResult> finished(Active& a, int status) {
    const SweepRun& run = plan_run(a.index);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const int signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    const auto end = [&](const std::string& state, const std::string& message) {
      write_status(a, state, message, code >= 0 ? code : 128 + signal);
      say(run, state == "done" ? "done in " + clock_text(seconds_now() - a.start) : state + ": " + message);
      return RunResult{state, message};
    };
    if (code == 130 || code == 143 || code == 129 || (signal && is_stop_signal(signal)))
      return end("interrupted", std::string("stopped by ") + signal_name(code > 0 ? code - 128 : signal) +
                                    " during its " + step_name(a.step) + "; running the sweep again continues it");
    if (code != 0) {
      std::string why = error_line(a.output);
      if (why.empty())
        why = signal ? std::string(step_name(a.step)) + " was killed by signal " + std::to_string(signal) + " (" +
                           strsignal(signal) + ")"
                     : std::string(step_name(a.step)) + " exited with code " + std::to_string(code);
      return end("failed", why);
    }
    RunStep next = RunStep::none;
    try {
      next = next_step(dir_, run);
    } catch (const std::exception& e) {
      return end("failed", e.what());
    }
    if (next == RunStep::none) return end("done", "");
    if (stop_signal.load() != 0)
      return end("interrupted", std::string("stopped by ") + signal_name(stop_signal.load()) + " before its " +
                                    step_name(next) + "; running the sweep again continues it");
    if (std::count(a.steps.begin(), a.steps.end(), next) > 0)
      return end("failed", std::string(step_name(next)) + " ended without error but the run's folder still needs it");
    try {
      launch(a, next);
    } catch (const std::exception& e) {
      return end("failed", e.what());
    }
    return std::nullopt;
  }

  void say(const SweepRun& run, const std::string& what) {
    std::cerr << "animpak: sweep: [" << run.index + 1 << "/" << plan_.runs.size() << "] " << run.id << ": " << what
              << "\n"
              << std::flush;
  }

  fs::path dir_;
  const SweepPlan& plan_;
  std::string program_;
  bool echo_;
  std::string host_;
  std::vector<Active> active_;
};

// ---- Planning.

// The art of DIR/input/manifest.json: each reference as written with its SHA-256 (empty without a manifest).
std::vector<std::pair<std::string, std::string>> manifest_art(const fs::path& dir) {
  std::vector<std::pair<std::string, std::string>> art;
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir / "input" / "manifest.json", ec))) return art;
  const json j = json::parse(read_folder_file(dir, "input/manifest.json", "remove the sweep's folder and plan again"),
                             nullptr, false);
  if (j.is_object() && j.contains("art") && j["art"].is_array())
    for (const json& a : j["art"])
      if (a.is_object() && a.contains("reference") && a.contains("sha256"))
        art.emplace_back(a["reference"].dump(), a["sha256"].dump());
  std::sort(art.begin(), art.end());
  return art;
}

ClusterOptions cluster_options(const SweepOptions& options) {
  ClusterOptions c;
  c.animpak = options.node_animpak.empty() ? own_executable() : options.node_animpak;
  c.k8s_animpak = options.node_animpak.empty() ? "animpak" : options.node_animpak;
  c.k8s_image = options.k8s_image.empty() ? "animpak:" + std::string(animpak_version) : options.k8s_image;
  c.k8s_claim = options.k8s_claim;
  c.cpus_per_task = options.cpus_per_task;
  c.parallelism = options.jobs.value_or(int(std::min<std::size_t>(64, kMaxSweepRuns)));
  return c;
}

// sbatch's job id: `sbatch --parsable` prints "ID" or "ID;CLUSTER".
std::string submit_slurm(const fs::path& dir, const SweepPlan& plan, const std::vector<std::size_t>& pending) {
  const std::string script = (fs::absolute(dir).lexically_normal() / "slurm.sbatch").string();
  const std::vector<std::string> args = {"--parsable", "--array=" + index_ranges(pending), script};
  std::string sbatch;
  if (const char* path = std::getenv("PATH"))
    for (const std::string& folder : [&] {
           std::vector<std::string> parts;
           std::string p = path;
           for (std::size_t b = 0, e; b <= p.size(); b = e + 1) {
             e = std::min(p.find(':', b), p.size());
             parts.push_back(p.substr(b, e - b));
           }
           return parts;
         }())
      if (!folder.empty() && ::access((fs::path(folder) / "sbatch").c_str(), X_OK) == 0) {
        sbatch = (fs::path(folder) / "sbatch").string();
        break;
      }
  if (sbatch.empty())
    throw InputError(
        "sbatch: not found on PATH; run this on a Slurm login node (or put Slurm's client commands on "
        "PATH), or submit " +
        script + " yourself");
  Child child = spawn(sbatch, args);
  std::string output;
  char buffer[4096];
  int status = 0;
  while (true) {
    pollfd fd{child.output, POLLIN, 0};
    ::poll(&fd, 1, 200);
    ssize_t n;
    while ((n = ::read(child.output, buffer, sizeof buffer)) > 0) output.append(buffer, std::size_t(n));
    if (n == 0) break;
  }
  ::close(child.output);
  ::waitpid(child.pid, &status, 0);
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError("sbatch " + script + ": failed: " + (output.empty() ? "no message" : output) +
                     "; check the cluster (`sinfo`) and the script's #SBATCH lines");
  const std::string id = tail_lines(output, 1).substr(0, tail_lines(output, 1).find(';'));
  static_cast<void>(plan);
  return id;
}

void print_cluster_help(const fs::path& dir, const SweepPlan& plan) {
  const std::string home = shell_word(fs::absolute(dir).lexically_normal().string());
  std::cerr << "animpak: planned " << plan.runs.size() << " runs in " << (dir / "plan.json").string() << "\n"
            << "  here:       the same `animpak sweep` command without --plan-only\n"
            << "  Slurm:      sbatch " << home << "/slurm.sbatch   (or add --submit slurm)\n"
            << "  Kubernetes: kubectl apply -f " << home << "/k8s-job.yaml   (edit its image and claim first)\n"
            << "  a list:     parallel < " << home << "/commands.txt   (or xargs, HTCondor: docs/sweeps.md)\n"
            << "  then:       animpak sweep collect " << home << "\n";
}

std::optional<long long> index_from_environment(std::string& from) {
  for (const char* name : {"SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX"}) {
    const char* value = std::getenv(name);
    if (!value || !*value) continue;
    from = name;
    char* end = nullptr;
    errno = 0;
    const long long index = std::strtoll(value, &end, 10);
    if (errno != 0 || *end != '\0' || index < 0)
      throw UsageError(std::string(name) + "=" + value + ": not a run's index; give --index N");
    return index;
  }
  return std::nullopt;
}

}  // namespace

int default_sweep_jobs() {
  const unsigned cores = std::thread::hardware_concurrency();
  return std::max(1, int(cores / 2));
}

int sweep(const SweepOptions& options) {
  if (options.scene.empty() || options.out.empty())
    throw UsageError("sweep needs SCENE and --out DIR (`animpak sweep collect DIR` gathers a sweep)");
  const fs::path dir = options.out;
  // Everything the command line says is checked before anything is written.
  std::vector<SweepSetting> settings;
  std::set<std::string> names;
  for (const std::string& text : options.sets) {
    settings.push_back(parse_setting(text));
    if (!names.insert(settings.back().name).second)
      throw UsageError("--set " + settings.back().name + " is given twice; list all its values in one --set");
  }
  const fs::path scene_file = fs::absolute(options.scene);
  const SceneSpec scene = load_scene(scene_file);
  const std::vector<std::uint64_t> seeds =
      options.seeds.empty() ? std::vector<std::uint64_t>{scene.seed} : parse_seeds(options.seeds);
  SweepPlan plan;
  plan.runs = plan_runs(seeds, settings);
  for (const SweepSetting& s : settings) plan.varied.push_back(s.name);
  plan.pack = options.pack;
  plan.packed_from = scene_file.string();
  plan.scene_file = scene_file.filename().string();
  const std::string text = read_bytes(scene_file, "check the scene file's path");
  plan.scene_sha256 = sha256_hex(text);
  // Every run's scene as pack will read it, with the art where it is now: a value the scene cannot take
  // (a count beside the container's fill, an element too many) fails here, before any run.
  for (const SweepRun& run : plan.runs) {
    const std::string run_text = run_scene_text(text, run, [](const std::string& written) { return written; });
    parse_scene(run_text, scene_file.string() + " (run " + run.id + ")", scene_file.parent_path());
  }

  std::error_code ec;
  if (fs::exists(fs::symlink_status(dir / "state.bin", ec)))
    throw InputError(dir.string() + ": holds a packing (state.bin), not a sweep; give --out a folder of its own");
  check_inputs_writable(dir);
  check_folder_writable(dir);
  const FolderLock lock(dir, "animpak sweep " + dir.string());
  const InputSnapshot snapshot = snapshot_inputs(scene_file, text);
  if (fs::exists(fs::symlink_status(dir / "plan.json", ec))) {
    // The same sweep continued, or more runs of it: the same scene, art, settings and pack options.
    const SweepPlan before = read_plan(dir);
    std::vector<std::pair<std::string, std::string>> art;
    for (const InputSnapshot::Art& a : snapshot.art)
      art.emplace_back(json(a.written).dump(), json(sha256_hex(a.bytes)).dump());
    std::sort(art.begin(), art.end());
    SweepPlan same = plan;
    same.runs = before.runs;
    same.packed_from = before.packed_from;
    std::string differs;
    if (before.scene_sha256 != plan.scene_sha256 || before.scene_file != plan.scene_file)
      differs = "the scene";
    else if (manifest_art(dir) != art)
      differs = "the scene's art";
    else if (before.varied != plan.varied)
      differs = "the settings it varies";
    else if (plan_json(same) != plan_json(before))
      differs = "the pack options (frames, size, formats, iterations, device)";
    if (!differs.empty())
      throw InputError((dir / "plan.json").string() + ": the sweep there differs in " + differs +
                       " from this command's; give --out another folder, or repeat the command that planned it");
    // Runs already planned keep their index (a cluster task names a run by it); new ones come after.
    std::vector<SweepRun> merged = before.runs;
    std::set<std::string> known;
    for (const SweepRun& r : merged) known.insert(r.id);
    for (SweepRun& r : plan.runs)
      if (!known.count(r.id)) {
        r.index = merged.size();
        merged.push_back(r);
      }
    if (merged.size() > kMaxSweepRuns)
      throw UsageError("the sweep would hold more than " + std::to_string(kMaxSweepRuns) + " runs");
    plan.runs = std::move(merged);
    plan.packed_from = before.packed_from;
  } else {
    write_inputs(dir, snapshot);
  }
  for (const char* sub : {"runs", "scenes", "status", "logs"}) fs::create_directories(dir / sub);

  const ClusterOptions cluster = cluster_options(options);
  write_file_atomically(dir / "plan.json", plan_json(plan));
  write_file_atomically(dir / "slurm.sbatch", slurm_script(dir, plan, cluster));
  write_file_atomically(dir / "k8s-job.yaml", k8s_job(dir, plan, cluster));
  write_file_atomically(dir / "commands.txt", command_lines(dir, plan, cluster));
  sync_folder(dir);
  if (plan.runs.size() > 1001)
    std::cerr << "animpak: warning: " << plan.runs.size()
              << " runs: a Slurm array holds 1001 tasks unless the cluster's MaxArraySize is raised\n";

  // Each run's scene now, so that the folder holds everything a cluster's tasks read.
  std::vector<std::size_t> pending;
  for (const SweepRun& run : plan.runs) {
    write_run_scene(dir, plan, run);
    if (next_step(dir, run) != RunStep::none) pending.push_back(run.index);
  }
  Runner runner(dir, plan, own_executable(), false);

  if (options.submit == "slurm") {
    if (pending.empty()) {
      std::cerr << "animpak: every run of " << (dir / "plan.json").string() << " is complete; nothing submitted\n";
      return 0;
    }
    const std::string job = submit_slurm(dir, plan, pending);
    std::cerr << "animpak: submitted " << pending.size() << " runs of " << (dir / "plan.json").string()
              << " as Slurm array job " << job << "; `squeue -j " << job << "` follows it, `animpak sweep collect "
              << shell_word(dir.string()) << "` gathers the runs\n";
    std::cout << job << "\n";
    return 0;
  }
  if (options.plan_only) {
    print_cluster_help(dir, plan);
    return 0;
  }

  const int jobs = options.jobs.value_or(default_sweep_jobs());
  std::cerr << "animpak: sweep of " << plan.runs.size() << " runs into " << dir.string() << ": "
            << plan.runs.size() - pending.size() << " complete, " << pending.size() << " to run, " << jobs
            << " at a time\n";
  std::vector<std::pair<std::size_t, RunResult>> results;
  {
    const SweepSignals signals;
    results = runner.run(pending, jobs);
  }
  int failed = 0;
  std::string failures;
  for (const auto& [index, r] : results)
    if (r.state == "failed") {
      ++failed;
      failures += "\n  " + plan.runs[index].id + ": " + r.message;
    }
  sweep_collect({dir});
  if (stop_signal.load() != 0) {
    std::cerr << "animpak: sweep stopped by " << signal_name(stop_signal.load())
              << "; every unfinished run is saved, and the same command continues the sweep\n";
    return 128 + stop_signal.load();
  }
  if (failed > 0) {
    std::cerr << "animpak: error: " << failed << " of " << plan.runs.size()
              << " runs failed (the others' results stand):" << failures << "\n";
    return static_cast<int>(ExitCode::bad_input);
  }
  return 0;
}

int sweep_task(const SweepTaskOptions& options) {
  const fs::path dir = options.dir;
  const SweepPlan plan = read_plan(dir);
  std::string from = "--index";
  std::optional<long long> index = options.index;
  if (!index) index = index_from_environment(from);
  if (!index)
    throw UsageError(
        "sweep-task needs the run's index: --index N, or SLURM_ARRAY_TASK_ID (a Slurm array task) or "
        "JOB_COMPLETION_INDEX (a Kubernetes Indexed Job) in the environment");
  if (*index < 0 || std::size_t(*index) >= plan.runs.size())
    throw UsageError(from + " " + std::to_string(*index) + ": " + (dir / "plan.json").string() + " has runs 0 to " +
                     std::to_string(plan.runs.size() - 1));
  const SweepRun& run = plan.runs[std::size_t(*index)];
  std::cerr << "animpak: sweep-task: run " << run.index << " of " << (dir / "plan.json").string() << ": " << run.id
            << " on " << host_name() << "\n";
  for (const char* sub : {"runs", "scenes", "status", "logs"}) fs::create_directories(dir / sub);
  Runner runner(dir, plan, own_executable(), true);
  std::vector<std::pair<std::size_t, RunResult>> results;
  {
    const SweepSignals signals;
    results = runner.run({run.index}, 1);
  }
  const RunResult result = results.empty() ? RunResult{"failed", "no result"} : results.front().second;
  if (stop_signal.load() != 0 || result.state == "interrupted")
    return 128 + (stop_signal.load() ? stop_signal.load() : SIGTERM);
  if (result.state == "failed") {
    std::cerr << "animpak: error: run " << run.id << " failed: " << result.message << "\n";
    return static_cast<int>(ExitCode::bad_input);
  }
  if (result.state == "busy")
    throw InputError(run.id + ": another animpak is running this run (" + result.message + "); it is left to it");
  return 0;
}

int sweep_collect(const SweepCollectOptions& options) {
  const fs::path dir = options.dir;
  const SweepPlan plan = read_plan(dir);
  SweepCollection c;
  c.title = fs::absolute(dir).lexically_normal().filename().string();
  if (c.title.empty()) c.title = fs::absolute(dir).lexically_normal().parent_path().filename().string();
  c.scene_file = plan.scene_file;
  c.varied = plan.varied;
  std::error_code ec;
  for (const SweepRun& run : plan.runs) {
    CollectedRun r;
    r.index = run.index;
    r.id = run.id;
    r.seed = run.seed;
    r.set = run.set;
    const fs::path folder = run_folder(dir, run), status_file = run_status_file(dir, run);
    json status;
    if (fs::is_regular_file(fs::symlink_status(status_file, ec)))
      status = json::parse(read_folder_file(dir, status_file.lexically_relative(dir), "run the sweep again"), nullptr,
                           false);
    const std::string last = status.is_object() ? status.value("state", "") : "";
    std::string held_by;
    const bool running = fs::is_directory(fs::symlink_status(dir / "status", ec)) &&
                         !RunLock::try_take(dir / "status" / (run.id + ".lock"), "", held_by);
    const bool folder_there = fs::is_directory(fs::symlink_status(folder, ec));
    std::optional<Stats> stats;
    if (folder_there) stats = read_stats_json(folder / "stats.json");
    const std::string reason = stats ? stats->stop_reason : "";
    const bool finished = stats && stats->frames && !stats->frames->empty() && reason != "interrupted" &&
                          reason != "running" && reason != "non_finite" && !has_unfinished_pack(folder);
    const std::string again = "; `animpak sweep-task " + shell_word(dir.string()) + " --index " +
                              std::to_string(run.index) + "` (or the sweep's command) continues it";
    if (running) {
      r.state = "running";
      r.message = held_by.empty() ? "being run" : "being run by " + held_by;
    } else if (last == "failed") {
      r.state = "failed";
      r.message = status.value("message", "failed");
    } else if (finished) {
      r.state = "done";
      r.stats = stats;
    } else if (folder_there || !last.empty()) {
      r.state = "unfinished";
      r.message =
          (last == "interrupted" ? status.value("message", "interrupted") : std::string("not finished")) + again;
    } else {
      r.state = "not started";
    }
    if (r.state == "done") {
      // The pictures go inside the page; one too large to open quickly there stays out, named.
      constexpr std::uintmax_t kMaxPicture = 8u << 20;
      for (const auto& [name, bytes] : {std::pair<const char*, std::string*>{"frames/frame_0000.png", &r.frame_png},
                                        std::pair<const char*, std::string*>{"animation.gif", &r.animation_gif}}) {
        const fs::path file = folder / name;
        if (!fs::is_regular_file(fs::symlink_status(file, ec))) continue;
        if (fs::file_size(file, ec) > kMaxPicture) {
          r.picture_note +=
              std::string(r.picture_note.empty() ? "" : " ") + name + " is over 8 MB, left out of this page;";
          continue;
        }
        *bytes = read_folder_file(folder, name, "render the run again");
      }
      r.report = fs::is_regular_file(fs::symlink_status(folder / "report.html", ec));
    }
    c.runs.push_back(std::move(r));
  }
  const std::string page = sweep_page(c);
  write_file_atomically(dir / "runs.csv", sweep_csv(c));
  write_file_atomically(dir / "sweep.html", page);
  std::map<std::string, int> counts;
  for (const CollectedRun& r : c.runs) ++counts[r.state];
  std::string summary;
  for (const auto& [state, n] : counts) summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + state;
  std::cerr << "animpak: " << plan.runs.size() << " runs in " << dir.string() << ": " << summary << "\n"
            << "animpak: wrote " << (dir / "sweep.html").string() << " (" << (page.size() + 1023) / 1024
            << " KiB, self-contained) and " << (dir / "runs.csv").string() << "\n";
  const SweepMeasure& first = sweep_measures().front();
  const CollectedRun* best = nullptr;
  std::optional<double> best_value;
  for (const CollectedRun& r : c.runs) {
    const std::optional<double> v = r.state == "done" && r.stats ? first.value(*r.stats) : std::nullopt;
    if (v && std::isfinite(*v) && (!best || *v > *best_value)) best = &r, best_value = v;
  }
  if (best)
    std::cout << "best by " << first.label << ": " << best->id << " ("
              << report_number(*best_value * first.scale, first.decimals) << first.unit << "), "
              << (dir / "runs" / best->id).string() << "\n";
  return 0;
}

}  // namespace animpak::cli
