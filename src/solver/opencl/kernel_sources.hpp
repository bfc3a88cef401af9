// The kernels' sources: embedded at build time (cmake/EmbedKernels.cmake), or read from the folder in
// ANIMPAK_KERNEL_DIR when it is set (kernel development without a rebuild).
#pragma once

#include <string>
#include <string_view>

namespace animpak::opencl {

/// The embedded text of kernels/<name>, or empty when there is no such file.
std::string_view embedded_kernel_source(std::string_view name);

/// One OpenCL program: the FP_CONTRACT pragma, shared_types.h, then every kernel file in dependency
/// order, each behind a #line so build logs name the file. InputError when ANIMPAK_KERNEL_DIR lacks a file.
std::string program_source();

/// Where line `line` (1-based) of program_source() comes from, as "file.cl:N"; the line itself when it
/// falls before the first file.
std::string program_location(const std::string& source, int line);

/// The build log with every "<kernel>:LINE", "<source>:LINE" or "input.cl:LINE" (compilers that ignore
/// #line and count lines in the whole program: NVIDIA's, Oclgrind's) rewritten as "file.cl:N", so every driver's log
/// names the kernel file and the line in it.
std::string annotate_build_log(const std::string& log, const std::string& source);

/// Options every build uses (docs/architecture.md, "The twin rule").
inline constexpr const char* build_options = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

}  // namespace animpak::opencl
