#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "animpak/param_table.hpp"

using namespace animpak;

// The table of docs/parameters.md is printed from param_table() and checked by the `docs:` tests; here,
// every constant also needs its paragraph under "Why each value".
TEST_CASE("param_table: every entry is unique, in range at its default, and explained") {
  const Params defaults;
  std::ifstream doc(std::string(ANIMPAK_SOURCE_DIR) + "/docs/parameters.md");
  REQUIRE(doc.good());
  std::stringstream text;
  text << doc.rdbuf();
  std::set<std::string> names;
  for (const ParamInfo& info : param_table()) {
    INFO(info.name);
    CHECK(names.insert(std::string(info.name)).second);
    const double v = param_value(defaults, info);
    CHECK(v >= info.min);
    CHECK(v <= info.max);
    std::string key = "\n- `";
    key.append(info.name).append("`: ");
    CHECK(text.str().find(key) != std::string::npos);
  }
  CHECK(names.size() == param_table().size());
}

TEST_CASE("param_table: writing through an entry changes exactly that member") {
  for (const ParamInfo& info : param_table()) {
    INFO(info.name);
    Params p;
    std::visit(
        [&](auto member) {
          member(p) = static_cast<std::remove_reference_t<decltype(member(p))>>(param_value(p, info) + 1);
        },
        info.field);
    CHECK(param_value(p, info) == param_value(Params{}, info) + 1);
    int changed = 0;
    for (const ParamInfo& other : param_table()) changed += param_value(p, other) != param_value(Params{}, other);
    CHECK(changed == 1);
  }
}
