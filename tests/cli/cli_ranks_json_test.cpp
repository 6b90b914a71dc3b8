// `styk solve --ranks N --progress json` when the distributed run cannot start or a rank dies
// (docs/cli.md "Progress protocol", exit code 6): the failure is the protocol's error event,
// kind "run_environment", as the last line of stderr, so a program driving the solver (the desktop
// program) sees why the run ended; without --progress json the same failure stays prose. The
// runners are stand-ins (no MPI needed): a PATH without mpirun, and a runner that ends as Open
// MPI's does when a rank is killed (status 128 + 9).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "support/test_scratch.hpp"

namespace styk::testing {
namespace {

namespace fs = std::filesystem;

const std::string kDeck = std::string(STYK_SOURCE_DIR) + "/tests/inputs/results/cube.inp";

std::string last_line(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == '\n') trimmed.pop_back();
  const std::size_t start = trimmed.rfind('\n');
  return start == std::string::npos ? trimmed : trimmed.substr(start + 1);
}

// The error event of the run's last stderr line; fails the test when it is no such event.
nlohmann::json error_event(const CommandResult& run) {
  const std::string line = last_line(run.err);
  const nlohmann::json event = nlohmann::json::parse(line, nullptr, false);
  EXPECT_FALSE(event.is_discarded()) << "not a JSON line: " << line;
  if (event.is_discarded()) return {};
  EXPECT_EQ(event.value("event", ""), "error") << line;
  EXPECT_EQ(event.value("styk_progress", 0), 1) << line;
  EXPECT_EQ(event.value("exit_code", 0), 6) << line;
  EXPECT_EQ(event.value("kind", ""), "run_environment") << line;
  EXPECT_FALSE(event.contains("file")) << "a launch failure points into no deck: " << line;
  return event;
}

bool nothing_written(const fs::path& out) { return !fs::exists(out) || fs::is_empty(out); }

TEST(RanksJson, MissingRunnerIsAnErrorEvent) {
  const fs::path dir = test::test_scratch_dir("ranks_json");
  const CommandResult run = run_command("env PATH=/nonexistent " + styk_executable() + " solve '" +
                                            kDeck + "' -o out --ranks 2 --progress json",
                                        dir.string());
  EXPECT_EQ(run.exit_code, 6) << run.err;
  const nlohmann::json event = error_event(run);
  EXPECT_NE(event.value("message", "").find("needs an MPI runner, and 'mpirun' was not found"),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(nothing_written(dir / "out"));
}

TEST(RanksJson, DyingRankIsAnErrorEvent) {
  const fs::path dir = test::test_scratch_dir("ranks_json");
  const fs::path runner = dir / "killed_rank_runner.sh";
  std::ofstream(runner) << "#!/bin/sh\nexit 137\n";
  fs::permissions(runner, fs::perms::owner_all);
  const CommandResult run =
      run_command("env STYK_MPIRUN='" + runner.string() + "' " + styk_executable() + " solve '" +
                      kDeck + "' -o out --ranks 2 --progress json",
                  dir.string());
  EXPECT_EQ(run.exit_code, 6) << run.err;
  const nlohmann::json event = error_event(run);
  EXPECT_NE(event.value("message", "").find("ended with status 137 (signal 9)"), std::string::npos)
      << run.err;
  EXPECT_TRUE(nothing_written(dir / "out"));
}

// Without --progress json the failure is the prose line people read.
TEST(RanksJson, TextProgressKeepsTheProseLine) {
  const fs::path dir = test::test_scratch_dir("ranks_json");
  const CommandResult run = run_command(
      "env PATH=/nonexistent " + styk_executable() + " solve '" + kDeck + "' -o out --ranks 2",
      dir.string());
  EXPECT_EQ(run.exit_code, 6) << run.err;
  EXPECT_EQ(last_line(run.err).rfind("styk: --ranks 2 needs an MPI runner", 0), 0u) << run.err;
}

}  // namespace
}  // namespace styk::testing
