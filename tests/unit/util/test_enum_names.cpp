#include <catch2/catch.hpp>

#include "util/enum_names.hpp"

namespace {

enum class Fruit { apple, pear, plum };
constexpr ncv::EnumName<Fruit> kFruitNames[] = {
    {Fruit::apple, "apple"}, {Fruit::pear, "pear"}, {Fruit::plum, "plum"}};

}  // namespace

TEST_CASE("an enum's names round-trip through its one table", "[enum_names]") {
  for (Fruit f : {Fruit::apple, Fruit::pear, Fruit::plum}) {
    CHECK(ncv::parse_name(kFruitNames, ncv::name_of(kFruitNames, f)) == f);
  }
  CHECK(ncv::name_of(kFruitNames, Fruit::pear) == "pear");
  CHECK_FALSE(ncv::parse_name(kFruitNames, "Pear").has_value());
  CHECK_FALSE(ncv::parse_name(kFruitNames, "").has_value());
  CHECK(ncv::name_of(kFruitNames, static_cast<Fruit>(7)) == "unknown");
  CHECK(ncv::names_list(kFruitNames) == "apple, pear or plum");
}
