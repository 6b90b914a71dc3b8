// The studies' CSV (docs/accuracy.md links it; the desktop program opens it): what is written
// reads back unchanged, and a damaged file is refused with its line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "styk/studies/results/run_record.hpp"

namespace styk::studies {
namespace {

RunRecord sample() {
  RunRecord r;
  r.study = "stability";
  r.problem = "distortion-trapezoid";
  r.family = "C3D8I";
  r.level = 3;
  r.parameter = "angle, degrees";
  r.value = 15;
  r.h = 0.5;
  r.dof = 123456;
  r.elements = 20;
  r.time_s = 0.0123;
  r.runs = 3;
  r.memory_mb = 81.5;
  r.error[static_cast<int>(Measure::PointDisplacement)] = 0.125;
  r.error[static_cast<int>(Measure::Energy)] = 3.5e-4;
  r.warnings = {"distortion", "locking"};
  r.quantities = {{"pressure", 3.294}, {"elongation", 0.1269}};
  r.failure = "";
  return r;
}

TEST(RunRecordCsv, RoundTripKeepsEveryField) {
  RunRecord failed = sample();
  failed.family = "C3D8R";
  failed.error = {};
  failed.time_s = kNaN;
  failed.failure = "t.inp:12: element 1 (C3D8R) integrates with \"1 point\", too few";
  std::stringstream file;
  write_csv(file, {sample(), failed});
  const std::vector<RunRecord> back = read_csv(file, "t.csv");
  ASSERT_EQ(back.size(), 2u);
  const RunRecord& r = back[0];
  EXPECT_EQ(r.study, "stability");
  EXPECT_EQ(r.parameter, "angle, degrees");  // a comma inside: quoted
  EXPECT_EQ(r.level, 3);
  EXPECT_EQ(r.dof, 123456);
  EXPECT_DOUBLE_EQ(r.value, 15);
  EXPECT_DOUBLE_EQ(*r.error_of(Measure::PointDisplacement), 0.125);
  EXPECT_DOUBLE_EQ(*r.error_of(Measure::Energy), 3.5e-4);
  EXPECT_FALSE(r.error_of(Measure::PointStress));
  EXPECT_EQ(r.warnings, (std::vector<std::string>{"distortion", "locking"}));
  EXPECT_DOUBLE_EQ(r.quantities.at("pressure"), 3.294);
  EXPECT_TRUE(r.ok());
  EXPECT_FALSE(back[1].ok());
  EXPECT_EQ(back[1].failure, failed.failure);
  EXPECT_TRUE(std::isnan(back[1].time_s));
}

TEST(RunRecordCsv, DamagedFilesAreRefusedWithLineAndColumn) {
  std::stringstream wrong_header("study,problem\n");
  EXPECT_THROW(read_csv(wrong_header, "a.csv"), std::runtime_error);

  std::stringstream file;
  write_csv(file, {sample()});
  std::string text = file.str();
  const std::size_t at = text.find("123456");
  text.replace(at, 6, "12x456");
  std::stringstream damaged(text);
  try {
    read_csv(damaged, "b.csv");
    FAIL() << "a bad number was read";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "b.csv:2: column dof: '12x456' is not a number");
  }
  std::stringstream short_row(csv_header() + "\naccuracy,lame,C3D8\n");
  try {
    read_csv(short_row, "c.csv");
    FAIL() << "a short row was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("c.csv:2: expected 20 columns, found 3"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace styk::studies
