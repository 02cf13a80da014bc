// YAML text into a Spec: aliases repeat what their anchors name, and a document its aliases
// make infinite or huge is an InputError naming the line, not a stack overflow or an
// exhausted memory (found while adding the YAML readers' fuzz targets: fuzz/README.md).
#include "sightline/csp/files/yaml_spec.h"

#include <gtest/gtest.h>

#include <string>

namespace sightline::csp {
namespace {

TEST(YamlSpec, AnAliasRepeatsWhatItsAnchorNames) {
  const Spec doc = parse_yaml("colours: &c [red, green]\nother: *c\n", "doc.yaml");
  EXPECT_EQ(doc.at("other").as_strings(), (std::vector<std::string>{"red", "green"}));
  EXPECT_EQ(doc.at("colours").as_strings(), doc.at("other").as_strings());
}

TEST(YamlSpec, AChainOfAliasesWithinTheLimitsReads) {
  // 200 anchors, each a list holding the alias of the one before: 200 deep, 20,100 values.
  std::string text = "a0: &a0 [1]\n";
  for (int i = 1; i < 200; ++i) {
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" +
            std::to_string(i - 1) + "]\n";
  }
  const Spec doc = parse_yaml(text, "doc.yaml");
  const Spec* node = &doc.at("a199");
  int depth = 0;
  while (node->is_list()) {
    node = &node->items().front();
    ++depth;
  }
  EXPECT_EQ(depth, 200);
  EXPECT_EQ(node->as_number(), 1);
}

// `a: &a [*a]` once crashed every YAML reader: the alias is the list that holds it, and
// converting it recursed until the stack overflowed.
TEST(YamlSpec, AnAliasInsideTheNodeItsAnchorNamesIsAnInputError) {
  for (const char* text : {"a: &a [*a]\n", "&a {x: *a}\n", "x: &a\n  y: *a\n"}) {
    try {
      parse_yaml(text, "doc.yaml");
      FAIL() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "doc.yaml") << text;
      EXPECT_EQ(e.where().line, 1) << text;
      EXPECT_NE(std::string(e.what()).find("nested more than 1000 deep"), std::string::npos)
          << e.what();
    }
  }
}

// Nine lines whose aliases stand for 10^9 values ("billion laughs"): refused once the
// expansion passes its bound, instead of exhausting the memory.
TEST(YamlSpec, AliasesThatExpandToBillionsOfValuesAreAnInputError) {
  std::string text = "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  const std::string names = "abcdefghi";
  for (std::size_t i = 1; i < names.size(); ++i) {
    const std::string alias = std::string("*") + names[i - 1];
    text += std::string(1, names[i]) + ": &" + names[i] + " [" + alias;
    for (int k = 1; k < 10; ++k) text += ", " + alias;
    text += "]\n";
  }
  try {
    parse_yaml(text, "doc.yaml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "doc.yaml");
    EXPECT_GE(e.where().line, 1);
    EXPECT_NE(std::string(e.what()).find("values beyond one per character"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sightline::csp
