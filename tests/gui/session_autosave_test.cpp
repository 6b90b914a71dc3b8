// Autosave and recovery of the model being edited (docs/gui.md "Autosave and recovery";
// session/autosave.hpp): a session with unsaved changes writes its deck; while it lives its lock
// keeps other sessions from taking it; once it has ended without discarding (a crash: the lock
// is free) the next session finds it and recovers the model, unsaved, with its original file —
// also a model still without nodes, elements or a step (read as a draft).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/test_scratch.hpp"
#include "refusal.hpp"
#include "session/autosave.hpp"
#include "session/document.hpp"
#include "session/validation.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/reader.hpp"

namespace styk::gui {
namespace {

namespace fs = std::filesystem;

class AutosaveTest : public ::testing::Test {
 protected:
  AutosaveTest() { register_builtin_elements(registry); }
  void SetUp() override {
    dir = (styk::test::test_scratch_dir("autosave") /
           ::testing::UnitTest::GetInstance()->current_test_info()->name())
              .string();
    fs::remove_all(dir);
  }
  static void add_material(Document& doc) {
    MaterialInput steel;
    steel.name = "BRONZE";
    doc.apply(material_command(doc.model(), steel));
  }
  ElementRegistry registry;
  std::string dir;
};

TEST_F(AutosaveTest, AnInterruptedSessionIsRecoveredAsADraft) {
  Document edited(registry);
  add_material(edited);  // a model with a material only: no nodes, elements or step
  auto crashed = std::make_unique<Autosave>(dir);
  EXPECT_TRUE(crashed->update(edited));
  EXPECT_FALSE(crashed->update(edited));  // nothing changed since
  const std::string deck = crashed->deck_path();
  ASSERT_TRUE(fs::exists(deck));
  // A complete read refuses the draft, which is why recovery reads it as one.
  EXPECT_NE(test::refusal([&] { read_inp(deck, registry); }), "(accepted)");

  Autosave next(dir);
  EXPECT_TRUE(next.interrupted_sessions().empty());  // the first session still runs
  crashed.reset();                                   // it ends without discarding: a crash
  const std::vector<InterruptedSession> found = next.interrupted_sessions();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].deck, deck);
  EXPECT_EQ(found[0].original_path, "");
  EXPECT_GT(found[0].saved_at, 0);

  Document recovered(registry);
  recovered.recover_inp(found[0].deck, found[0].original_path);
  EXPECT_GE(recovered.model().material_index("BRONZE"), 0);
  EXPECT_TRUE(recovered.is_modified());
  EXPECT_EQ(recovered.path(), "");
  next.forget(found[0]);
  EXPECT_FALSE(fs::exists(deck));
  EXPECT_TRUE(next.interrupted_sessions().empty());
}

// The recovered model keeps the file it came from; a saved (unmodified) document or discard()
// leaves no autosave, so a normal end offers nothing.
TEST_F(AutosaveTest, TheOriginalFileIsKeptAndANormalEndLeavesNothing) {
  const std::string original = (styk::test::test_scratch_dir("autosave") / "cube.inp").string();
  fs::copy_file(std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/cube.inp", original,
                fs::copy_options::overwrite_existing);
  Document doc(registry);
  doc.open_inp(original);
  const std::size_t elements = doc.model().elements.size();
  {
    Autosave session(dir);
    EXPECT_FALSE(session.update(doc));  // unmodified: nothing to keep
    EXPECT_FALSE(fs::exists(session.deck_path()));
    add_material(doc);
    EXPECT_TRUE(session.update(doc));
  }
  Autosave next(dir);
  const std::vector<InterruptedSession> found = next.interrupted_sessions();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].original_path, original);
  Document recovered(registry);
  recovered.recover_inp(found[0].deck, found[0].original_path);
  EXPECT_EQ(recovered.path(), original);
  EXPECT_EQ(recovered.model().elements.size(), elements);
  EXPECT_TRUE(recovered.is_modified());
  next.forget(found[0]);

  {
    Autosave session(dir);
    EXPECT_TRUE(session.update(recovered));
    session.discard();  // the user saved or discarded the changes
  }
  EXPECT_TRUE(Autosave(dir).interrupted_sessions().empty());
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".inp") << entry.path();
}

}  // namespace
}  // namespace styk::gui
