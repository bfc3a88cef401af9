// The kernels' sources: embedded at build time (cmake/EmbedKernels.cmake), or read from the folder in
// ANIMPAK_KERNEL_DIR when it is set (kernel development without a rebuild).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace animpak::opencl {

/// The embedded text of kernels/<name>, or empty when there is no such file.
std::string_view embedded_kernel_source(std::string_view name);

/// The names of the embedded files (kernels/*.cl and *.h), in name order.
std::vector<std::string_view> embedded_kernel_names();

/// The kernel files of one program in dependency order (program.cpp says the rule): the phases' files
/// by name, and between torsion.cl and forces.cl every other embedded .cl file, the forces of
/// AP_LOCAL_FORCES (kernels/shared_types.h), in name order.
std::vector<std::string> kernel_files();

/// One OpenCL program: the FP_CONTRACT pragma, shared_types.h, then kernel_files(), each behind a #line
/// so build logs name the file. InputError when ANIMPAK_KERNEL_DIR lacks a file.
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
