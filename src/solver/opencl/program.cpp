// Assembling and building the kernels' program in one place, so every caller gets the same
// source, options and annotated build log (docs/architecture.md, "The twin rule").
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "animpak/error.hpp"
#include "cl_host.hpp"
#include "kernel_sources.hpp"

namespace animpak::opencl {
namespace {

// Dependency order: each file uses only functions of the files before it. The files of the forces of
// AP_LOCAL_FORCES (kernels/shared_types.h) are not named: kernel_files() puts every .cl file these lists
// leave out between them, so a force's file uses only functions of before_forces and forces.cl calls it.
constexpr std::string_view before_forces[] = {"closest_point.cl", "segments.cl",     "grid.cl",      "curve.cl",
                                              "overlap.cl",       "overlap_grid.cl", "repulsion.cl", "springs.cl",
                                              "target.cl",        "boundary.cl",     "contact.cl",   "torsion.cl"};
constexpr std::string_view from_forces[] = {"forces.cl", "integrate.cl", "constraints.cl", "growth.cl", "stats.cl"};

std::string kernel_text(const std::string& name) {
  if (const char* dir = std::getenv("ANIMPAK_KERNEL_DIR"); dir != nullptr && *dir != '\0') {
    const std::filesystem::path file = std::filesystem::path(dir) / name;
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string() + ": cannot read this kernel file (ANIMPAK_KERNEL_DIR is set)");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  return std::string(embedded_kernel_source(name));
}

}  // namespace

std::vector<std::string> kernel_files() {
  std::vector<std::string> files(std::begin(before_forces), std::end(before_forces));
  const auto named = [](std::string_view name) {
    return std::find(std::begin(before_forces), std::end(before_forces), name) != std::end(before_forces) ||
           std::find(std::begin(from_forces), std::end(from_forces), name) != std::end(from_forces);
  };
  for (const std::string_view name : embedded_kernel_names())
    if (name.ends_with(".cl") && !named(name)) files.emplace_back(name);
  files.insert(files.end(), std::begin(from_forces), std::end(from_forces));
  return files;
}

std::string program_source() {
  // FP_CONTRACT OFF: no fused multiply-adds, so every product and sum rounds as in the reference.
  std::string source = "#pragma OPENCL FP_CONTRACT OFF\n#line 1 \"shared_types.h\"\n" + kernel_text("shared_types.h");
  for (const std::string& name : kernel_files()) source += "\n#line 1 \"" + name + "\"\n" + kernel_text(name);
  return source;
}

std::string program_location(const std::string& source, int line) {
  // Walk the program once: a "#line 1 \"file\"" directive on program line L makes L + 1 that file's line 1.
  std::string file;
  int file_first_line = 0;
  int current = 1;
  std::size_t pos = 0;
  while (current < line && pos < source.size()) {
    const std::size_t end = source.find('\n', pos);
    const std::string_view text(source.data() + pos, (end == std::string::npos ? source.size() : end) - pos);
    constexpr std::string_view directive = "#line 1 \"";
    if (text.substr(0, directive.size()) == directive && text.size() > directive.size() + 1) {
      file = std::string(text.substr(directive.size(), text.size() - directive.size() - 1));
      file_first_line = current + 1;
    }
    if (end == std::string::npos) break;
    pos = end + 1;
    ++current;
  }
  if (file.empty() || line < file_first_line) return "program line " + std::to_string(line);
  return file + ":" + std::to_string(line - file_first_line + 1);
}

std::string annotate_build_log(const std::string& log, const std::string& source) {
  // The names drivers give the whole program in their logs (PoCL/Clang, NVIDIA, Intel), each followed by
  // ":<line>". A plain scan rather than std::regex: GCC 12 warns inside <regex> under the sanitizers.
  constexpr std::string_view names[] = {"<kernel>:", "<source>:", "input.cl:"};
  const auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  std::string out;
  std::size_t copied = 0, pos = 0;
  while (pos < log.size()) {
    std::size_t digits = std::string::npos;
    for (const std::string_view name : names) {
      if (log.compare(pos, name.size(), name) != 0) continue;
      if (name.front() != '<' && pos > 0 && is_word(log[pos - 1])) continue;  // "xinput.cl" is another file
      if (pos + name.size() < log.size() && std::isdigit(static_cast<unsigned char>(log[pos + name.size()])) != 0)
        digits = pos + name.size();
      break;
    }
    if (digits == std::string::npos) {
      ++pos;
      continue;
    }
    std::size_t end = digits;
    while (end < log.size() && std::isdigit(static_cast<unsigned char>(log[end])) != 0) ++end;
    const std::string number = log.substr(digits, end - digits);
    // A line number too long for an int is left as the driver wrote it.
    if (number.size() <= 9) {
      out.append(log, copied, pos - copied);
      out += program_location(source, std::stoi(number));
      copied = end;
    }
    pos = end;
  }
  out.append(log, copied, std::string::npos);
  return out;
}

std::string device_build_options(const cl::Device& device) {
  cl_device_type type = 0;
  check(device.getInfo(CL_DEVICE_TYPE, &type), "clGetDeviceInfo(CL_DEVICE_TYPE)");
  // A CPU compiler puts the 16 lanes in SIMD registers; a GPU already runs one work-item per lane,
  // where 16 lanes per work-item would only multiply its registers. Oclgrind calls itself every type
  // at once: it gets the one-slot loops (its uninitialized-value checker crashes on the overlap test's
  // lanes, in Oclgrind 21.10).
  std::string options = build_options;
  if ((type & CL_DEVICE_TYPE_CPU) != 0 && (type & CL_DEVICE_TYPE_GPU) == 0) options += " -DAP_NEAR_LANES=16";
  return options;
}

cl::Program build_program(const cl::Context& context, const cl::Device& device) {
  cl_int err = CL_SUCCESS;
  const std::string source = program_source();
  cl::Program program(context, source, false, &err);
  check(err, "clCreateProgramWithSource");
  const std::string options = device_build_options(device);
  const cl_int built = program.build(std::vector<cl::Device>{device}, options.c_str());
  if (built != CL_SUCCESS) {
    std::string log, name;
    device.getInfo(CL_DEVICE_NAME, &name);
    program.getBuildInfo(device, CL_PROGRAM_BUILD_LOG, &log);
    throw OpenclError("clBuildProgram", built, "device " + name + ", options " + options,
                      annotate_build_log(log, source));
  }
  return program;
}

}  // namespace animpak::opencl
