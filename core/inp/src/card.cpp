#include "card.hpp"

#include <cstdio>

namespace styk::inp {

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; }

std::vector<std::string_view> split_commas(std::string_view text) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) {
      parts.push_back(text.substr(start));
      return parts;
    }
    parts.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
}
}  // namespace

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string normalize_name(std::string_view text) {
  std::string out;
  bool pending_blank = false;
  for (char c : trim(text)) {
    if (is_blank(c)) {
      pending_blank = true;
      continue;
    }
    if (pending_blank) out.push_back(' ');
    pending_blank = false;
    out.push_back(static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c));
  }
  return out;
}

std::string quote(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    } else {
      out.push_back(static_cast<char>(c));
    }
  }
  out += text.size() > kMax ? "...'" : "'";
  return out;
}

const Parameter* KeywordLine::find(std::string_view param) const {
  for (const Parameter& p : params)
    if (p.name == param) return &p;
  return nullptr;
}

KeywordLine parse_keyword_line(const std::string& text, const SourceLoc& where) {
  std::string_view body = trim(text);
  body.remove_prefix(1);  // the '*'
  const std::vector<std::string_view> parts = split_commas(body);
  KeywordLine kw;
  kw.where = where;
  kw.name = normalize_name(parts[0]);
  if (kw.name.empty())
    throw InputError(where,
                     "keyword line without a keyword name after '*' (read " + quote(text) + ")");
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string_view part = trim(parts[i]);
    if (part.empty()) {
      if (i + 1 == parts.size()) break;  // a trailing comma
      throw InputError(where, "empty parameter (two commas in a row) on " + kw.label());
    }
    Parameter p;
    const std::size_t eq = part.find('=');
    p.name = normalize_name(part.substr(0, eq));
    if (eq != std::string_view::npos) {
      p.has_value = true;
      std::string_view value = trim(part.substr(eq + 1));
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
      p.value = std::string(value);
    }
    if (p.name.empty())
      throw InputError(where,
                       "parameter without a name (read " + quote(part) + ") on " + kw.label());
    if (kw.find(p.name))
      throw InputError(where, "parameter " + p.name + " is given twice on " + kw.label());
    kw.params.push_back(std::move(p));
  }
  return kw;
}

DataLine split_data_line(const std::string& text, const SourceLoc& where) {
  DataLine line;
  line.where = where;
  for (std::string_view part : split_commas(text)) line.fields.emplace_back(trim(part));
  if (line.fields.size() > 1 && line.fields.back().empty()) {
    line.fields.pop_back();
    line.trailing_comma = true;
  }
  return line;
}

}  // namespace styk::inp
