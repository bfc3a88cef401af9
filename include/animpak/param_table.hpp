// The table of every overridable constant of Params (include/animpak/params.hpp): its flat name in a scene
// file's "params" object, its group, an accessor, its range, its meaning and the paper's value. The io
// library defines it (src/io/params.cpp) and reads scene files through it (src/io/scene_file.cpp); the
// schema, `animpak params` and docs/parameters.md's table are printed from it (docs/architecture.md,
// "Layers"). The solver reads Params directly and never needs it.
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "animpak/params.hpp"

namespace animpak {

/// One entry of the table of overridable constants.
struct ParamInfo {
  std::string_view name;   ///< key in the scene file's "params" object, the member's own name
  std::string_view group;  ///< the Params group holding it: "art", "element", "placement", "forces", "growth", "stop"
  std::variant<double& (*)(Params&), int& (*)(Params&)> field;  ///< the member, in a given Params
  double min;                                                   ///< smallest valid value (inclusive)
  double max;                                                   ///< largest valid value (inclusive)
  std::string_view meaning;
  std::string_view paper;  ///< what the paper gives, before the conversion to the unit container
};

/// Every member of Params, group by group in declaration order. docs/parameters.md documents each entry;
/// its table is `animpak params --markdown`.
std::span<const ParamInfo> param_table();

/// Reads a constant by its table entry, as a double.
double param_value(const Params& params, const ParamInfo& info);

/// Whether the constant is an integer (a scene must give it as one).
bool param_is_integer(const ParamInfo& info);

}  // namespace animpak
