// The five spring classes of Eq. 2 (paper §3.1, §4), shared by the element builder that makes the springs,
// the solver that gives each class its stiffness and the tools that count them; no stage owns it.
#pragma once

#include <cstdint>

namespace animpak {

enum class SpringClass : std::uint8_t { edge = 0, shear = 1, negative_space = 2, time = 3, target = 4 };
inline constexpr int spring_class_count = 5;

constexpr const char* spring_class_name(SpringClass c) {
  switch (c) {
    case SpringClass::edge:
      return "edge";
    case SpringClass::shear:
      return "shear";
    case SpringClass::negative_space:
      return "negative_space";
    case SpringClass::time:
      return "time";
    case SpringClass::target:
      return "target";
  }
  return "unknown";
}

}  // namespace animpak
