// The whole-file seal of a results file (docs/results.md "Integrity", item 6): the first line of
// the file's HDF5 user block holds the CRC-32 and length of every byte after it, verified before
// HDF5 reads anything. The CRC-32 is recomputed here bit by bit from the description (reflected
// polynomial 0xEDB88320, initial and final XOR 0xFFFFFFFF: zlib's and Python's zlib.crc32),
// independently of the writer's zlib call.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io_test_support.hpp"
#include "results_damage.hpp"
#include "results_file_layout.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_check.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"

namespace styk {
namespace {

const std::string kFixtures = std::string(STYK_SOURCE_DIR) + "/tests/inputs/";
constexpr std::size_t kLine = 62;  // "styk-results-seal 1 crc32:xxxxxxxx bytes:<20 digits>\n"

std::vector<unsigned char> bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t bitwise_crc32(const unsigned char* data, std::size_t n) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

// The message of the refusal by read_results_file, "" when the file was read.
std::string refusal(const std::string& path) {
  try {
    (void)read_results_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

class ResultsSeal : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = io_test::fresh_dir(std::string("seal_") +
                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    good_ = damage::write_cube_results(dir_ + "/good.styk.h5");
  }
  std::string copy(const std::string& name) {
    const std::string path = dir_ + "/" + name;
    damage::copy_file(good_, path);
    return path;
  }
  std::string dir_, good_;
};

// The line, the user block and the checksum as docs/results.md describes them.
TEST_F(ResultsSeal, WriterSealsEveryByteAfterTheLine) {
  const std::vector<unsigned char> file = bytes_of(good_);
  ASSERT_GT(file.size(), 512u + 8u);
  const std::string line(file.begin(), file.begin() + kLine);
  const std::uint32_t crc = bitwise_crc32(file.data() + kLine, file.size() - kLine);
  char expected[kLine + 1];
  std::snprintf(expected, sizeof expected, "styk-results-seal 1 crc32:%08x bytes:%020llu\n",
                static_cast<unsigned>(crc), static_cast<unsigned long long>(file.size() - kLine));
  EXPECT_EQ(line, expected);
  // HDF5's superblock follows the 512-byte user block.
  EXPECT_EQ(std::string(file.begin() + 512, file.begin() + 520), "\x89HDF\r\n\x1a\n");
  const auto seal = io::verify_results_seal(good_);
  ASSERT_TRUE(seal.has_value());
  EXPECT_EQ(seal->crc32, crc);
  EXPECT_EQ(seal->bytes, file.size() - kLine);
  const ResultsFileContents contents = read_results_file(good_);
  EXPECT_TRUE(contents.verified);
  EXPECT_TRUE(contents.sealed);
  const ResultsCheck report = check_results_file(good_);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Whole);
  EXPECT_EQ(report.seal, io::describe_seal(*seal));
  EXPECT_NE(report.summary.find("; sealed: " + report.seal), std::string::npos) << report.summary;
}

// Any flipped byte — in the line, the rest of the user block, HDF5's metadata or the values — is
// refused by the seal, before HDF5 opens the file: the message is the seal's, and `styk check`
// reads no dataset.
TEST_F(ResultsSeal, EveryFlippedByteIsRefusedBeforeHdf5) {
  const std::uint64_t size = damage::file_size(good_);
  int refused = 0;
  for (std::uint64_t at = 0; at < size; at += 97) {
    const std::string path = copy("flipped.styk.h5");
    damage::flip_byte(path, at, damage::Seal::Break);
    const std::string message = refusal(path);
    const bool by_seal = message.find("the file is damaged") != std::string::npos &&
                         (message.find("whole-file checksum mismatch") != std::string::npos ||
                          message.find("its seal") != std::string::npos);
    EXPECT_TRUE(by_seal) << "byte " << at << ": " << message;
    refused += by_seal ? 1 : 0;
    if (at % (97 * 50) == 0) {
      const ResultsCheck report = check_results_file(path);
      EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged);
      EXPECT_EQ(report.datasets, 0u) << "byte " << at << ": HDF5 was reached";
    }
  }
  const std::uint64_t flips = (size + 96) / 97;
  std::printf("%d of %llu flips (every 97th byte of %llu) refused by the seal\n", refused,
              static_cast<unsigned long long>(flips), static_cast<unsigned long long>(size));
  EXPECT_EQ(static_cast<std::uint64_t>(refused), flips);
  EXPECT_GT(flips, 300u);  // the cube's file is ~31 kB: every part of it is hit
}

TEST_F(ResultsSeal, CutShortOrExtendedIsRefused) {
  const std::string cut = copy("cut.styk.h5");
  damage::truncate_file(cut, damage::file_size(cut) - 1, damage::Seal::Break);
  EXPECT_NE(refusal(cut).find("cut short or extended) \u2014 the file is damaged"),
            std::string::npos)
      << refusal(cut);
  const std::string longer = copy("longer.styk.h5");
  std::ofstream(longer, std::ios::binary | std::ios::app) << '\0';
  EXPECT_NE(
      refusal(longer).find("bytes, but " + std::to_string(damage::file_size(good_) - kLine + 1) +
                           " follow it"),
      std::string::npos)
      << refusal(longer);
}

// The line itself damaged: its first byte (no longer a seal, yet HDF5's data lies behind a user
// block) and a digit of its length.
TEST_F(ResultsSeal, DamagedLineIsRefused) {
  const std::string first = copy("first.styk.h5");
  damage::flip_byte(first, 0, damage::Seal::Break);
  EXPECT_NE(refusal(first).find("its seal (the first line, ahead of HDF5's data) is not one Styk "
                                "writes \u2014 the file is damaged"),
            std::string::npos)
      << refusal(first);
  const std::string digit = copy("digit.styk.h5");
  damage::flip_byte(digit, kLine - 2, damage::Seal::Break);  // the last digit of the length
  EXPECT_NE(refusal(digit).find("its seal (the first line) cannot be read"), std::string::npos)
      << refusal(digit);
}

// Files written before the seal still open: checksummed ones (per-dataset checks and digest) and
// the pre-checksum fixture (with its notice).
TEST_F(ResultsSeal, UnsealedFilesStillOpen) {
  const ResultsFileContents cube = read_results_file(good_);
  const std::string unsealed = dir_ + "/unsealed.styk.h5";
  io::write_results_file_as(unsealed, cube.model, cube.results,
                            io::ResultsLayout::ChecksummedUnsealed);
  EXPECT_FALSE(io::verify_results_seal(unsealed).has_value());
  const ResultsFileContents read = read_results_file(unsealed);
  EXPECT_TRUE(read.verified);
  EXPECT_FALSE(read.sealed);
  const ResultsCheck report = check_results_file(unsealed);
  EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Whole);
  EXPECT_TRUE(report.seal.empty());
  EXPECT_NE(report.summary.find("; not sealed (written before Styk sealed its files)"),
            std::string::npos)
      << report.summary;
  const std::string legacy = kFixtures + "results/legacy-cube.styk.h5";
  EXPECT_FALSE(io::verify_results_seal(legacy).has_value());
  const ResultsFileContents old = read_results_file(legacy);
  EXPECT_FALSE(old.verified);
  EXPECT_FALSE(old.sealed);
}

// The two results-harness findings HDF5 could not survive (docs/fuzzing.md), behind a seal that
// does not match them (a sealed file damaged later in those bytes): refused by the seal, so HDF5
// never parses the damaged heap (a 504-byte over-read) or the damaged local-heap size (2 min 39 s
// and 24 GB of memory when HDF5 parses it).
TEST(ResultsSealFindings, SealedFindingsAreRefusedBeforeHdf5) {
  for (const char* name :
       {"results-sealed-heap-overread.styk.h5", "results-sealed-huge-local-heap.styk.h5"}) {
    const std::string path = kFixtures + "fuzz/" + name;
    const std::string message = refusal(path);
    EXPECT_NE(message.find(": whole-file checksum mismatch (sealed crc32:"), std::string::npos)
        << name << ": " << message;
    const ResultsCheck report = check_results_file(path);
    EXPECT_EQ(report.verdict, ResultsCheck::Verdict::Damaged) << name;
    EXPECT_EQ(report.datasets, 0u) << name;
  }
}

}  // namespace
}  // namespace styk
