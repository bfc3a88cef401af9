// Errors carry their full context (file, field path or element) in the message. They are thrown below
// src/cli and caught once in main, which prints `animpak: error: <message>` and exits with the code.
#pragma once

#include <stdexcept>
#include <string>

namespace animpak {

/// `differs`: `animpak validate` found a device whose numbers are not bit for bit the reference's.
enum class ExitCode : int { ok = 0, usage = 1, bad_input = 2, internal = 3, differs = 4, interrupted = 130 };

/// Bad input: a file that cannot be read, a malformed or unsupported SVG/JSON/.path, degenerate art.
/// The message names the file, the field or element, and what to do.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The command line itself is wrong (unknown flag, missing argument).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace animpak
