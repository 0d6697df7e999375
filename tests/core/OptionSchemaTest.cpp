// SPDX-License-Identifier: AGPL-3.0-or-later
// The one schema of enum names and number options (OptionSchema.h): what
// toString, the parsers, the range checks, the command line and the GUI
// read.
#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "tetskin/core/Appearance.h"
#include "tetskin/core/ElasticMaterial.h"
#include "tetskin/core/SurfaceBinding.h"
#include "tetskin/core/UpAxis.h"

namespace tetskin {

enum class Fruit { Apple, Pear };
template <>
struct EnumSchema<Fruit> {
  static constexpr const char* what = "fruit";
  static constexpr EnumValue<Fruit> values[] = {{Fruit::Pear, "pear", "soft"},
                                                {Fruit::Apple, "apple", ""}};
};

namespace {

TEST(OptionSchema, NamesReadBackInTheSchemasOrder) {
  EXPECT_STREQ(toString(Fruit::Apple), "apple");
  EXPECT_EQ(parseName<Fruit>("pear"), Fruit::Pear);
  EXPECT_FALSE(parseName<Fruit>("Pear"));  // letter case counts unless the schema says
  EXPECT_EQ(parseName<UpAxis>("Y"), UpAxis::Y);
  EXPECT_EQ(namesOf<Fruit>(), (std::vector<std::string>{"pear", "apple"}));
  EXPECT_EQ(helpOf<Fruit>(), "pear (soft) or apple");
  EXPECT_EQ(oneOf({"a", "b", "c"}), "a, b or c");
  EXPECT_EQ(oneOf({"a"}), "a");
  EXPECT_EQ(listed({"a", "b", "c"}), "a, b, c");
  EXPECT_EQ(fromName<Fruit>("apple"), Fruit::Apple);
  try {
    fromName<Fruit>("plum");
    FAIL() << "an unknown name was read";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "unknown fruit 'plum' (known: pear, apple)");
  }
}

template <SchemaEnum E>
void expectDistinctNamesThatReadBack() {
  std::set<std::string> names;
  for (const EnumValue<E>& v : EnumSchema<E>::values) {
    EXPECT_TRUE(names.insert(v.name).second) << v.name;
    EXPECT_EQ(fromName<E>(v.name), v.value);
    EXPECT_STREQ(toString(v.value), v.name);
  }
}

TEST(OptionSchema, EveryCoreEnumHasDistinctNamesThatReadBack) {
  expectDistinctNamesThatReadBack<UpAxis>();
  expectDistinctNamesThatReadBack<BindingMethod>();
  expectDistinctNamesThatReadBack<OffsetMode>();
  expectDistinctNamesThatReadBack<FurLighting>();
}

TEST(OptionSchema, RangesSayWhatTheyHoldAndRefuseNaNAndInfinity) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(above(0).words(), "must be finite and positive");
  EXPECT_EQ(atLeast(0).words(), "must be finite and >= 0");
  EXPECT_EQ(above(1).words(), "must be finite and > 1");
  EXPECT_EQ(between(-1, 0.5, false, false).words(), "must lie in (-1, 0.5)");
  EXPECT_EQ(between(0, 1).words(), "must lie in [0, 1]");
  EXPECT_EQ(NumberRange{}.words(), "must be finite");
  for (const NumberRange& range : {above(0), atLeast(0), between(0, 1), NumberRange{}}) {
    EXPECT_FALSE(range.contains(nan));
    EXPECT_FALSE(range.contains(inf));
    EXPECT_FALSE(range.contains(-inf));
  }
  EXPECT_FALSE(above(0).contains(0));
  EXPECT_TRUE(atLeast(0).contains(0));
  EXPECT_TRUE(between(0, 1).contains(1));
  EXPECT_FALSE(between(0, 1, true, false).contains(1));
  EXPECT_TRUE(between(0, 1, false, true).contains(1));
}

TEST(OptionSchema, MaterialOptionsAreTheMaterialsDefaultsKeysAndChecks) {
  const ElasticMaterial defaults;
  std::set<std::string> keys, flags;
  for (const MaterialField& f : materialFields()) {
    EXPECT_EQ(defaults.*f.field, f.option->defaultValue) << f.option->key;
    EXPECT_FALSE(f.option->problem(f.option->defaultValue)) << f.option->key;
    EXPECT_TRUE(keys.insert(f.option->key).second);
    EXPECT_TRUE(flags.insert(f.option->flag).second);
    // The check of the material is the schema's, key by key.
    ElasticMaterial spoiled;
    spoiled.*f.field = std::numeric_limits<double>::quiet_NaN();
    const auto problem = materialProblem(spoiled);
    ASSERT_TRUE(problem) << f.option->key;
    EXPECT_EQ(problem->key, f.option->key);
    EXPECT_EQ(problem->what, *f.option->problem(spoiled.*f.field));
  }
  EXPECT_EQ(*material_option::kPoissonRatio.problem(0.5),
            "Poisson's ratio must lie in (-1, 0.5), got 0.5");
}

TEST(OptionSchema, AnOptionMaySayItsRangeInItsOwnWords) {
  constexpr NumberOption share{"share", "--share", "", "the share", "", between(0, 1, true, false),
                               0.5,     "in [0, 1)"};
  EXPECT_EQ(*share.problem(1), "the share must be in [0, 1), got 1");
  EXPECT_FALSE(share.problem(0));
}

// FurParameters' defaults are the schema's, and furParameterProblem checks
// each option's range in the config's words.
TEST(OptionSchema, FurDefaultsAndRangesAreTheSchemas) {
  using namespace fur_option;
  const FurParameters fur;
  EXPECT_EQ(fur.shells, kShells.defaultValue);
  EXPECT_EQ(fur.length, kLength.defaultValue);
  EXPECT_EQ(fur.density, kDensity.defaultValue);
  EXPECT_EQ(fur.textureSize, kTextureSize.defaultValue);
  EXPECT_EQ(fur.textureRepeats, kTextureRepeats.defaultValue);
  EXPECT_EQ(fur.rootShade, kRootShade.defaultValue);
  EXPECT_EQ(fur.drag, kDrag.defaultValue);
  EXPECT_EQ(fur.maxBend, kMaxBend.defaultValue);
  EXPECT_EQ(fur.velvet, kVelvet.defaultValue);
  EXPECT_EQ(fur.baseDarkening, kBaseDarkening.defaultValue);
  EXPECT_EQ(fur.minShells, kMinShells.defaultValue);
  EXPECT_FALSE(furParameterProblem(fur));
  FurParameters spoiled;
  spoiled.drag = kDrag.range.max * 2;
  ASSERT_TRUE(furParameterProblem(spoiled));
  EXPECT_EQ(furParameterProblem(spoiled)->key, "drag");
  EXPECT_EQ(furParameterProblem(spoiled)->what, "must lie in [0, 10], found 20");
  spoiled = {};
  spoiled.minShells = spoiled.shells + 1;  // [1, shells]
  EXPECT_EQ(furParameterProblem(spoiled)->key, "min_shells");
}

}  // namespace
}  // namespace tetskin
