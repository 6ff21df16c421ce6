// CSV field splitting and quoting (csv_fields.h).
#include "sim_client/csv_fields.h"

#include "sim_client/text_input.h"

namespace cloudsvc::sim {

std::optional<std::vector<std::string>> split_csv_fields(std::string_view l) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < l.size(); ++i) {
    const char c = l[i];
    if (quoted) {
      if (c == '"' && i + 1 < l.size() && l[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"' && trim(fields.back()).empty()) {
      fields.back().clear();
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

std::string csv_quote(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace cloudsvc::sim
