// CardSource turns the files of a deck into a stream of keyword and data lines: it skips comments
// (**) and blank lines, joins keyword continuation lines, follows *INCLUDE (textually, so an
// included file may hold just the data lines of the keyword above it) and rejects what is not a
// text deck (NUL or control bytes, absurdly long lines) as soon as it reads it, using memory
// bounded by the longest accepted line.
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "card.hpp"

namespace styk::inp {

class CardSource {
 public:
  // Longest physical line accepted; Abaqus itself allows 256 characters.
  static constexpr std::size_t kMaxLineLength = std::size_t{1} << 20;
  // Deepest *INCLUDE nesting accepted.
  static constexpr std::size_t kMaxIncludeDepth = 32;

  // Opens the deck; throws InputError (line 0) when it cannot be read.
  explicit CardSource(const std::string& path);
  ~CardSource();
  CardSource(const CardSource&) = delete;
  CardSource& operator=(const CardSource&) = delete;

  // The next card without consuming it; nullptr at the end of the deck.
  const Card* peek();
  // The next card; std::nullopt at the end of the deck.
  std::optional<Card> next();

 private:
  struct OpenFile;

  void open(const std::string& display_path, const SourceLoc& include_site);
  // Next physical line of the innermost open file, closing exhausted files and going on in the
  // including file unless `same_file`; false at the end.
  bool read_line(std::string& line, SourceLoc& where, bool same_file = false);
  std::optional<Card> read_card();
  void follow_include(const Card& card);

  std::vector<std::unique_ptr<OpenFile>> files_;  // include stack, main deck first
  std::optional<Card> lookahead_;
  bool lookahead_valid_ = false;
};

}  // namespace styk::inp
