// SPDX-License-Identifier: MIT
// ObjectFactory: registration of untemplated and templated classes and their aliases, the
// choice of a template (scene, then context, then default) and the errors, with suggestions,
// for unknown classes and templates.
#include "core/ObjectFactory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/StateTypes.h"

namespace stroma {
namespace {

struct Gravity : Base {};
template <class DataTypes>
struct PointState : Base {
  using Coord = typename DataTypes::Coord;
};
template <class DataTypes>
struct UniformMass : Base {};

class ObjectFactoryTest : public ::testing::Test {
 protected:
  ObjectFactoryTest() {
    factory.add("Gravity", "Uniform acceleration", "Core").with<Gravity>();
    factory.add("MechanicalObject", "Positions and velocities", "Core")
        .with<PointState<Vec3Types>>("Vec3d")
        .with<PointState<Rigid3Types>>("Rigid3d")
        .alias("MechanicalState")
        .alias("MO");
    factory.add("UniformMass", "Same mass for every point", "Masses")
        .with<UniformMass<Rigid3Types>>("Rigid")
        .with<UniformMass<Vec3Types>>("Vec3f");
  }

  std::unique_ptr<Base> create(std::string_view name, std::string_view templateName = {},
                               std::string_view context = {}) {
    error.clear();
    auto object = factory.create(name, templateName, context, error);
    EXPECT_NE(object, nullptr) << error;
    return object;
  }

  std::string failure(std::string_view name, std::string_view templateName = {},
                      std::string_view context = {}) {
    error.clear();
    EXPECT_EQ(factory.create(name, templateName, context, error), nullptr) << name;
    return error;
  }

  ObjectFactory factory;
  std::string error;
};

TEST(NormalizeTemplateName, MapsSofaSpellingsToTheDoubleOnes) {
  EXPECT_EQ(normalizeTemplateName("Vec3"), "Vec3d");
  EXPECT_EQ(normalizeTemplateName("Vec3f"), "Vec3d");
  EXPECT_EQ(normalizeTemplateName("Vec3d"), "Vec3d");
  EXPECT_EQ(normalizeTemplateName("Vec1"), "Vec1d");
  EXPECT_EQ(normalizeTemplateName("Vec6f"), "Vec6d");
  EXPECT_EQ(normalizeTemplateName("Rigid"), "Rigid3d");
  EXPECT_EQ(normalizeTemplateName("Rigid3"), "Rigid3d");
  EXPECT_EQ(normalizeTemplateName("Rigid3f"), "Rigid3d");
  EXPECT_EQ(normalizeTemplateName("Rigid3d"), "Rigid3d");
  EXPECT_EQ(normalizeTemplateName("Rigid2f"), "Rigid2d");
  EXPECT_EQ(normalizeTemplateName("CompressedRowSparseMatrixMat3x3f"),
            "CompressedRowSparseMatrixMat3x3d");
  EXPECT_EQ(normalizeTemplateName("Custom"), "Custom");
  EXPECT_EQ(normalizeTemplateName(""), "");
  EXPECT_EQ(normalizeTemplateName("Vec"), "Vec");
}

TEST_F(ObjectFactoryTest, CreatesAnUntemplatedClass) {
  auto object = create("Gravity");
  ASSERT_NE(object, nullptr);
  EXPECT_NE(dynamic_cast<Gravity*>(object.get()), nullptr);
  EXPECT_EQ(object->className(), "Gravity");
  EXPECT_EQ(object->templateName(), "");
  const ComponentClass* c = factory.find("Gravity");
  ASSERT_NE(c, nullptr);
  EXPECT_FALSE(c->isTemplated());
  EXPECT_TRUE(c->templateNames().empty());
  EXPECT_EQ(c->description, "Uniform acceleration");
  EXPECT_EQ(c->plugin, "Core");
}

TEST_F(ObjectFactoryTest, UntemplatedClassIgnoresTheTemplates) {
  auto object = create("Gravity", "Rigid3d", "Vec3d");
  ASSERT_NE(object, nullptr);
  EXPECT_EQ(object->templateName(), "");
}

TEST_F(ObjectFactoryTest, RegistersTemplatesUnderTheirNormalizedNames) {
  const ComponentClass* mass = factory.find("UniformMass");
  ASSERT_NE(mass, nullptr);
  EXPECT_TRUE(mass->isTemplated());
  EXPECT_EQ(mass->templateNames(), (std::vector<std::string>{"Rigid3d", "Vec3d"}));
}

TEST_F(ObjectFactoryTest, TemplateWrittenInTheSceneComesFirst) {
  auto object = create("MechanicalObject", "Rigid3d", "Vec3d");
  ASSERT_NE(object, nullptr);
  EXPECT_NE(dynamic_cast<PointState<Rigid3Types>*>(object.get()), nullptr);
  EXPECT_EQ(object->templateName(), "Rigid3d");
  // SOFA's spellings are accepted.
  EXPECT_EQ(create("MechanicalObject", "Rigid")->templateName(), "Rigid3d");
  EXPECT_EQ(create("MechanicalObject", "Vec3f", "Rigid3d")->templateName(), "Vec3d");
}

TEST_F(ObjectFactoryTest, TemplateOfTheContextComesNext) {
  auto object = create("MechanicalObject", "", "Rigid3d");
  ASSERT_NE(object, nullptr);
  EXPECT_NE(dynamic_cast<PointState<Rigid3Types>*>(object.get()), nullptr);
  EXPECT_EQ(create("UniformMass", "", "Vec3")->templateName(), "Vec3d");
}

TEST_F(ObjectFactoryTest, FirstRegisteredTemplateIsTheDefault) {
  EXPECT_EQ(create("MechanicalObject")->templateName(), "Vec3d");
  EXPECT_EQ(create("UniformMass")->templateName(), "Rigid3d");
  // A context the class does not have falls back to the default too.
  EXPECT_EQ(create("MechanicalObject", "", "Vec2d")->templateName(), "Vec3d");
}

TEST_F(ObjectFactoryTest, UnknownTemplateListsTheAvailableOnes) {
  EXPECT_EQ(failure("MechanicalObject", "Vec2"),
            "component 'MechanicalObject' has no template 'Vec2'; available: 'Vec3d' or "
            "'Rigid3d'");
  EXPECT_EQ(failure("MO", "Rigid2d", "Vec3d"),
            "component 'MechanicalObject' has no template 'Rigid2d'; available: 'Vec3d' or "
            "'Rigid3d'");
}

TEST_F(ObjectFactoryTest, AliasesGiveTheCanonicalClass) {
  const ComponentClass* byAlias = factory.find("MechanicalState");
  ASSERT_NE(byAlias, nullptr);
  EXPECT_EQ(byAlias, factory.find("MechanicalObject"));
  EXPECT_EQ(byAlias->name, "MechanicalObject");
  EXPECT_EQ(byAlias->aliases, (std::vector<std::string>{"MechanicalState", "MO"}));
  auto object = create("MO", "Rigid3d");
  ASSERT_NE(object, nullptr);
  EXPECT_EQ(object->className(), "MechanicalObject");
  EXPECT_EQ(object->templateName(), "Rigid3d");
}

TEST_F(ObjectFactoryTest, FindIsExactAndCaseSensitive) {
  EXPECT_EQ(factory.find("gravity"), nullptr);
  EXPECT_EQ(factory.find("Gravit"), nullptr);
  EXPECT_EQ(factory.find(""), nullptr);
}

TEST_F(ObjectFactoryTest, UnknownClassSuggestsTheNearestNames) {
  EXPECT_EQ(failure("MechanicalObjet"),
            "unknown component 'MechanicalObjet'; did you mean 'MechanicalObject' or "
            "'MechanicalState'?");
  // A name that differs only by case is the best suggestion.
  EXPECT_EQ(failure("mechanicalstate"),
            "unknown component 'mechanicalstate'; did you mean 'MechanicalState'?");
  EXPECT_EQ(failure("gravity"), "unknown component 'gravity'; did you mean 'Gravity'?");
  EXPECT_EQ(failure("UniformMas", "Vec3d"),
            "unknown component 'UniformMas'; did you mean 'UniformMass'?");
  EXPECT_EQ(failure("Xyzzy"), "unknown component 'Xyzzy'");
}

TEST_F(ObjectFactoryTest, ListsClassesSortedAndEveryName) {
  std::vector<std::string> names;
  for (const ComponentClass* c : factory.classes()) names.push_back(c->name);
  EXPECT_EQ(names, (std::vector<std::string>{"Gravity", "MechanicalObject", "UniformMass"}));
  auto all = factory.allNames();
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, (std::vector<std::string>{"Gravity", "MO", "MechanicalObject", "MechanicalState",
                                           "UniformMass"}));
}

TEST_F(ObjectFactoryTest, SameTemplateTwiceIsAProgrammingError) {
  try {
    factory.add("MechanicalObject", "Positions and velocities", "Core")
        .with<PointState<Vec3Types>>("Vec3");
    FAIL() << "a second Vec3d variant was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "component MechanicalObject registered twice with template 'Vec3d'");
  }
  EXPECT_THROW(factory.add("Gravity", "again", "Core").with<Gravity>(), std::logic_error);
  EXPECT_EQ(factory.find("MechanicalObject")->variants.size(), 2u);
}

TEST_F(ObjectFactoryTest, SameClassFromTwoPluginsIsAProgrammingError) {
  try {
    factory.add("Gravity", "Another gravity", "OtherPlugin");
    FAIL() << "a second provider was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "component Gravity is provided by two plugins: Core and OtherPlugin");
  }
}

TEST_F(ObjectFactoryTest, ClassWithoutCreatorCannotBeCreated) {
  factory.add("Placeholder", "Nothing yet");
  EXPECT_EQ(failure("Placeholder"), "component 'Placeholder' has no creator");
}

TEST_F(ObjectFactoryTest, CustomCreatorsAreCalledForEachObject) {
  int calls = 0;
  factory.add("Counted", "Counts its creations").addCreator("", [&calls] {
    ++calls;
    return std::make_unique<Gravity>();
  });
  create("Counted");
  create("Counted");
  EXPECT_EQ(calls, 2);
}

TEST_F(ObjectFactoryTest, ClearForgetsEverything) {
  factory.clear();
  EXPECT_TRUE(factory.classes().empty());
  EXPECT_TRUE(factory.allNames().empty());
  EXPECT_EQ(factory.find("MO"), nullptr);
  EXPECT_EQ(failure("Gravity"), "unknown component 'Gravity'");
}

}  // namespace
}  // namespace stroma
