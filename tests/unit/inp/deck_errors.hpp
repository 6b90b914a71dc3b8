// Refusal checks shared by the reader tests: a deck must be refused at the line of a marker with
// a message that says why.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/inp/reader.hpp"

namespace styk::test {

// The 1-based line of the first occurrence of `marker` in `text`.
inline int line_of(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  int line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// Reading `text` (written as scratch deck `name`, fake elements) fails at the line of `marker`
// with a message containing `substring`.
inline void expect_error(const std::string& name, const std::string& text,
                         const std::string& marker, const std::string& substring) {
  const ElementRegistry registry = fake_registry();
  try {
    read_inp(write_deck(name, text), registry);
    ADD_FAILURE() << name << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, line_of(text, marker)) << name << ": " << e.what();
    EXPECT_NE(e.message().find(substring), std::string::npos) << name << ": " << e.what();
  }
}

}  // namespace styk::test
