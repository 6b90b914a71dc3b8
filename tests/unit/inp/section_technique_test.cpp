// *SOLID SECTION, TECHNIQUE= (Styk-only, docs/input.md): selective (B-bar) volumetric integration.
#include <sstream>

#include <gtest/gtest.h>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"

namespace styk {
namespace {

std::string deck(const std::string& section_line) {
  return "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
         "*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n1,1,2,3,4,5,6,7,8\n"
         "*MATERIAL, NAME=RUBBER\n*ELASTIC\n10., 0.4999\n" +
         section_line + "\n*BOUNDARY\n1,1,3\n*STEP\n*STATIC\n*END STEP\n";
}

TEST(SectionTechnique, SelectiveSetsTheFlagAndRoundTrips) {
  const ElementRegistry registry = test::fake_registry();
  const Model m = read_inp(
      test::write_deck("technique_selective.inp",
                       deck("*SOLID SECTION, ELSET=BLOCK, MATERIAL=RUBBER, TECHNIQUE=selective")),
      registry);
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_TRUE(m.sections[0].selective_volumetric);

  std::ostringstream written;
  write_inp(m, written);
  EXPECT_NE(written.str().find("TECHNIQUE=SELECTIVE"), std::string::npos) << written.str();
  const Model again = read_inp(test::write_deck("technique_again.inp", written.str()), registry);
  EXPECT_TRUE(again.sections[0].selective_volumetric);
}

TEST(SectionTechnique, FullIsTheDefault) {
  const ElementRegistry registry = test::fake_registry();
  const Model m = read_inp(test::write_deck("technique_default.inp",
                                            deck("*SOLID SECTION, ELSET=BLOCK, MATERIAL=RUBBER")),
                           registry);
  EXPECT_FALSE(m.sections[0].selective_volumetric);
}

TEST(SectionTechnique, UnknownValueIsAnErrorAtTheSectionLine) {
  const ElementRegistry registry = test::fake_registry();
  try {
    read_inp(
        test::write_deck("technique_bad.inp",
                         deck("*SOLID SECTION, ELSET=BLOCK, MATERIAL=RUBBER, TECHNIQUE=HYBRID")),
        registry);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 15);
    EXPECT_NE(std::string(e.what()).find("TECHNIQUE=HYBRID"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace styk
