// The lines of a deck after comments and continuations are dealt with: keyword lines split into
// name and parameters, data lines split into fields. Private to styk_inp.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "styk/core/diagnostics.hpp"

namespace styk::inp {

// One logical line of a deck as the card source delivers it.
struct Card {
  std::string text;  // without the line end; keyword lines joined over continuations
  SourceLoc where;   // first physical line
  bool is_keyword = false;
};

// One parameter of a keyword line: NAME=value or a bare NAME (a flag such as GENERATE).
struct Parameter {
  std::string name;   // upper-case, blanks collapsed
  std::string value;  // trimmed, case as written (file names keep their case)
  bool has_value = false;
};

struct KeywordLine {
  std::string name;  // upper-case, inner blanks collapsed: "SOLID SECTION"
  std::vector<Parameter> params;
  SourceLoc where;

  const Parameter* find(std::string_view param) const;
  std::string label() const { return "*" + name; }
};

// Parses "*NAME, P1=v, P2". Throws InputError when the line has no keyword name, a parameter
// has no name or a parameter is given twice.
KeywordLine parse_keyword_line(const std::string& text, const SourceLoc& where);

struct DataLine {
  std::vector<std::string> fields;  // trimmed; a single trailing empty field is dropped
  bool trailing_comma = false;      // the line ended with ',' (element continuation)
  SourceLoc where;
};

DataLine split_data_line(const std::string& text, const SourceLoc& where);

// Upper-case with runs of blanks collapsed to one blank and the ends trimmed.
std::string normalize_name(std::string_view text);
std::string_view trim(std::string_view text);
// The text as it should appear inside a message: quoted, at most 40 characters, non-printable
// bytes shown as \xNN.
std::string quote(std::string_view text);

}  // namespace styk::inp
