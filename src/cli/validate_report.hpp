// How `animpak validate` prints what it found (animpak/validation.hpp): a table, a summary row, JSON.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "animpak/validation.hpp"

namespace animpak::cli {

struct ValidationHeader {
  std::string scene;
  std::size_t elements = 0, vertices = 0;
  int steps = 0;
  int grid_rebuild_interval = 1;
};

void print_table(std::ostream& out, const ValidationHeader& header, const DeviceValidation& v);
void print_summary(std::ostream& out, const ValidationHeader& header, const std::vector<DeviceValidation>& all);
void print_json(std::ostream& out, const ValidationHeader& header, const std::vector<DeviceValidation>& all);

}  // namespace animpak::cli
