#include "card_source.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace styk::inp {

namespace fs = std::filesystem;

struct CardSource::OpenFile {
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Closer> handle;
  std::string path;    // as shown in messages
  fs::path canonical;  // for include-cycle detection
  int line = 0;        // last line read (1-based)
  std::vector<char> buffer = std::vector<char>(1 << 16);
  std::size_t pos = 0;
  std::size_t len = 0;
  bool at_end = false;

  // Refills the buffer; false when nothing is left.
  bool fill() {
    if (at_end) return false;
    len = std::fread(buffer.data(), 1, buffer.size(), handle.get());
    pos = 0;
    if (len == 0) {
      if (std::ferror(handle.get()))
        throw InputError(SourceLoc{path, line}, std::string("read error: ") + std::strerror(errno));
      at_end = true;
      return false;
    }
    return true;
  }
};

CardSource::CardSource(const std::string& path) { open(path, SourceLoc{}); }

CardSource::~CardSource() = default;

void CardSource::open(const std::string& display_path, const SourceLoc& include_site) {
  const bool included = !include_site.file.empty();
  const SourceLoc blame = included ? include_site : SourceLoc{display_path, 0};
  const std::string what = included ? "included file " + quote(display_path) : "deck";
  std::error_code ec;
  if (!fs::exists(display_path, ec))
    throw InputError(blame, "cannot open " + what + ": no such file");
  if (fs::is_directory(display_path, ec))
    throw InputError(blame, "cannot open " + what + ": it is a directory");
  auto file = std::make_unique<OpenFile>();
  file->path = display_path;
  file->canonical = fs::weakly_canonical(display_path, ec);
  if (ec) file->canonical = fs::absolute(display_path).lexically_normal();
  for (const auto& open_file : files_) {
    if (open_file->canonical != file->canonical) continue;
    std::string chain;
    for (const auto& f : files_) chain += f->path + " -> ";
    throw InputError(blame, "include cycle: " + chain + display_path);
  }
  if (files_.size() >= kMaxIncludeDepth)
    throw InputError(blame,
                     "includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " levels");
  file->handle.reset(std::fopen(display_path.c_str(), "rb"));
  if (!file->handle) throw InputError(blame, "cannot open " + what + ": " + std::strerror(errno));
  files_.push_back(std::move(file));
}

bool CardSource::read_line(std::string& line, SourceLoc& where, bool same_file) {
  while (!files_.empty()) {
    OpenFile& f = *files_.back();
    if (f.pos == f.len && !f.fill()) {
      if (same_file) return false;
      files_.pop_back();
      continue;
    }
    line.clear();
    ++f.line;
    const SourceLoc here{f.path, f.line};
    for (;;) {
      if (f.pos == f.len && !f.fill()) break;  // last line without a newline
      const char* begin = f.buffer.data() + f.pos;
      const char* end = f.buffer.data() + f.len;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', end - begin));
      const char* stop = newline ? newline : end;
      for (const char* p = begin; p != stop; ++p) {
        const auto c = static_cast<unsigned char>(*p);
        if ((c < 0x20 && c != '\t' && c != '\r' && c != '\f') || c == 0x7f) {
          const std::size_t column = line.size() + static_cast<std::size_t>(p - begin) + 1;
          char byte[8];
          std::snprintf(byte, sizeof byte, "0x%02X", c);
          throw InputError(here, std::string("not a text line (byte ") + byte + " at column " +
                                     std::to_string(column) +
                                     "); is this a binary file rather than an .inp deck?");
        }
      }
      if (line.size() + static_cast<std::size_t>(stop - begin) > kMaxLineLength)
        throw InputError(here, "line is longer than " + std::to_string(kMaxLineLength) +
                                   " characters; not an .inp deck line (Abaqus allows 256)");
      line.append(begin, stop);
      f.pos = static_cast<std::size_t>(stop - f.buffer.data());
      if (newline) {
        ++f.pos;
        break;
      }
    }
    if (f.line == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // UTF-8 BOM
    while (!line.empty() && (line.back() == '\r' || line.back() == '\f')) line.pop_back();
    where = here;
    return true;
  }
  return false;
}

namespace {
bool is_comment(std::string_view t) { return t.size() >= 2 && t[0] == '*' && t[1] == '*'; }

bool is_include(const Card& card) {
  if (!card.is_keyword) return false;
  const std::string_view text(card.text);
  return normalize_name(text.substr(1, text.find(',') - 1)) == "INCLUDE";
}
}  // namespace

std::optional<Card> CardSource::read_card() {
  std::string line;
  SourceLoc where;
  for (;;) {
    if (!read_line(line, where)) return std::nullopt;
    const std::string_view t = trim(line);
    if (t.empty() || is_comment(t)) continue;
    Card card{std::string(t), where, t.front() == '*'};
    if (!card.is_keyword) return card;
    // A keyword line ending with ',' continues on the next non-comment line of the same file.
    while (card.text.back() == ',') {
      std::string more;
      SourceLoc more_where;
      bool got = false;
      while (read_line(more, more_where, /*same_file=*/true)) {
        const std::string_view m = trim(more);
        if (m.empty() || is_comment(m)) continue;
        if (m.front() == '*')
          throw InputError(more_where, "the keyword line at line " + std::to_string(where.line) +
                                           " ends with ',' (a continuation) but this line is a "
                                           "new keyword; remove the trailing comma");
        card.text += m;
        got = true;
        break;
      }
      if (!got)
        throw InputError(where, "keyword line ends with ',' (a continuation) but the file ends");
    }
    return card;
  }
}

void CardSource::follow_include(const Card& card) {
  const KeywordLine kw = parse_keyword_line(card.text, card.where);
  const Parameter* input = nullptr;
  for (const Parameter& p : kw.params) {
    if (p.name != "INPUT")
      throw InputError(card.where,
                       "unknown parameter " + p.name + " on *INCLUDE (accepted: INPUT=file)");
    input = &p;
  }
  if (!input || input->value.empty()) throw InputError(card.where, "*INCLUDE needs INPUT=file");
  fs::path target(input->value);
  if (target.is_relative()) target = fs::path(card.where.file).parent_path() / target;
  open(target.lexically_normal().string(), card.where);
}

const Card* CardSource::peek() {
  if (!lookahead_valid_) {
    for (;;) {
      lookahead_ = read_card();
      if (lookahead_ && is_include(*lookahead_)) {
        follow_include(*lookahead_);
        continue;
      }
      break;
    }
    lookahead_valid_ = true;
  }
  return lookahead_ ? &*lookahead_ : nullptr;
}

std::optional<Card> CardSource::next() {
  peek();
  lookahead_valid_ = false;
  return std::move(lookahead_);
}

}  // namespace styk::inp
