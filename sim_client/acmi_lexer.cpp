// ACMI 2.x text lexer: logical lines (backslash continuations), record kinds, "\,"
// escapes (syntax summary in acmi_lexer.h).
#include "sim_client/acmi_lexer.h"

#include <cstdio>

#include "sim_client/flight_log_error.h"
#include "sim_client/text_input.h"
#include "sim_client/value_checks.h"

namespace cloudsvc::sim::acmi {

namespace {

constexpr std::string_view kZipSignature("PK\x03\x04", 4);

// Splits "Key=Value,Key=Value" at commas not escaped as "\,"; unescapes "\,".
std::vector<std::string> split_unescaped(std::string_view s) {
  std::vector<std::string> parts(1);
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == ',') {
      parts.back() += ',';
      ++i;
    } else if (s[i] == ',') {
      parts.emplace_back();
    } else {
      parts.back() += s[i];
    }
  }
  return parts;
}

class Lexer {
 public:
  Lexer(std::string_view text, const std::string& source,
        const std::function<void(const Record&)>& on_record)
      : text_(text), lines_(split_lines(text)), source_(source), on_record_(on_record) {}

  void run() {
    if (text_.substr(0, 4) == kZipSignature)
      fail(0, "unsupported: zipped ACMI (.zip.acmi); unzip first");
    std::size_t k = 0;
    std::string logical;
    std::size_t line = 0;
    int header_lines = 0;
    while (next_logical(k, logical, line)) {
      if (header_lines == 0) {
        check_file_type(line, logical);
        ++header_lines;
      } else if (header_lines == 1) {
        check_file_version(line, logical);
        ++header_lines;
      } else {
        handle(line, logical);
      }
    }
    if (header_lines == 0) fail(1, "missing ACMI header: empty file");
    if (header_lines == 1) fail(lines_.size(), "missing FileVersion=2.x header line");
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw FlightLogError(source_, line, problem);
  }

  // Next logical line from physical line k on (continuations joined with "\n").
  bool next_logical(std::size_t& k, std::string& out, std::size_t& line) {
    if (k >= lines_.size()) return false;
    line = k + 1;
    out.clear();
    while (true) {
      std::string_view phys = lines_[k++];
      if (phys.empty() || phys.back() != '\\') {
        out += phys;
        return true;
      }
      phys.remove_suffix(1);
      out += phys;
      out += '\n';
      if (k >= lines_.size())
        fail(line, "truncated file: line continuation '\\' at the end of the file");
    }
  }

  void check_file_type(std::size_t line, std::string_view l) const {
    if (trim(l) != "FileType=text/acmi/tacview")
      fail(line, "missing ACMI header: first line must be FileType=text/acmi/tacview, found " +
                     quoted_excerpt(l));
  }

  void check_file_version(std::size_t line, std::string_view l) const {
    constexpr std::string_view kKey = "FileVersion=";
    l = trim(l);
    if (l.substr(0, kKey.size()) != kKey)
      fail(line, "missing FileVersion=2.x header line, found " + quoted_excerpt(l));
    const std::string_view version = l.substr(kKey.size());
    if (version.substr(0, 2) != "2." || !parse_number(version))
      fail(line, "unsupported ACMI FileVersion " + quoted_excerpt(version) + " (2.x expected)");
  }

  void handle(std::size_t line, std::string_view l) {
    if (trim(l).empty() || l.substr(0, 2) == "//") return;
    if (l.front() == '#') {
      const std::optional<double> t = parse_number(l.substr(1));
      if (!t) fail(line, "malformed time frame " + quoted_excerpt(l) + ": expected #<seconds>");
      if (auto p = finite_problem("time frame", *t)) fail(line, *p);
      // The first frame may be negative (before ReferenceTime): the records above it (the
      // header's) are at time 0 without being a frame of their own.
      if (seen_frame_ && *t < time_s_)
        fail(line, "time goes backwards: #" + format_number(*t) + " after #" +
                       format_number(time_s_));
      time_s_ = *t;
      seen_frame_ = true;
      return;
    }
    Record rec;
    rec.line = line;
    rec.time_s = time_s_;
    if (l.front() == '-') {
      rec.kind = Record::Kind::object_removal;
      if (!parse_object_id(trim(l.substr(1)), rec.id))
        fail(line, "malformed object removal " + quoted_excerpt(l) + ": expected -<hex id>");
      on_record_(rec);
      return;
    }
    const std::size_t comma = l.find(',');
    const std::string_view id_text = l.substr(0, comma);
    if (!parse_object_id(trim(id_text), rec.id))
      fail(line, "malformed record " + quoted_excerpt(l) + ": expected <hex id>,Key=Value,...");
    if (comma != std::string_view::npos) {
      for (std::string& part : split_unescaped(l.substr(comma + 1))) {
        if (trim(part).empty()) continue;  // "1,T=1|2|3," : trailing comma
        const std::size_t eq = part.find('=');
        if (eq == 0 || eq == std::string::npos)
          fail(line, "malformed property " + quoted_excerpt(part) + ": expected Key=Value");
        rec.properties.push_back({std::string(trim(std::string_view(part).substr(0, eq))),
                                  part.substr(eq + 1)});
      }
    }
    on_record_(rec);
  }

  std::string_view text_;
  std::vector<std::string_view> lines_;
  const std::string& source_;
  const std::function<void(const Record&)>& on_record_;
  double time_s_ = 0.0;
  bool seen_frame_ = false;  // a # line has been read
};

}  // namespace

void lex_acmi(std::string_view text, const std::string& source,
              const std::function<void(const Record&)>& on_record) {
  Lexer(text, source, on_record).run();
}

bool parse_object_id(std::string_view text, std::uint64_t& id) {
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X'))
    text.remove_prefix(2);
  if (text.empty() || text.size() > 16) return false;
  std::uint64_t v = 0;
  for (char c : text) {
    int d = 0;
    if (c >= '0' && c <= '9') d = c - '0';
    else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
    else return false;
    v = v * 16 + static_cast<std::uint64_t>(d);
  }
  id = v;
  return true;
}

std::string format_object_id(std::uint64_t id) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%llx", static_cast<unsigned long long>(id));
  return buf;
}

}  // namespace cloudsvc::sim::acmi
