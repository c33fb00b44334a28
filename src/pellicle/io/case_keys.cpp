#include "pellicle/io/case_keys.hpp"

#include <algorithm>
#include <cctype>

namespace pellicle {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

//! The cells of a table row `| a | b \| c |`: split at pipes that are not escaped.
std::vector<std::string> cells_of(std::string_view row) {
  row = trim(row);
  if (starts_with(row, "|")) row.remove_prefix(1);
  if (!row.empty() && row.back() == '|' && (row.size() < 2 || row[row.size() - 2] != '\\'))
    row.remove_suffix(1);
  std::vector<std::string> cells;
  std::string cell;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i] == '|' && (i == 0 || row[i - 1] != '\\')) {
      cells.emplace_back(trim(cell));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  cells.emplace_back(trim(cell));
  return cells;
}

//! `|---|:--:|`: the line under a table's header.
bool is_separator(std::string_view row) {
  for (const std::string& c : cells_of(row))
    if (c.empty() || c.find_first_not_of(":-") != std::string::npos) return false;
  return true;
}

bool is_key_token(std::string_view t) {
  if (t.empty()) return false;
  const std::size_t first = t.front() == '.' ? 1 : 0;
  if (first >= t.size()) return false;
  const char c = t[first];
  if (!(std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '<')) return false;
  return std::all_of(t.begin() + first, t.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '.' || ch == '<' ||
           ch == '>';
  });
}

//! The keys named in a key cell, relative to the section: every code span that looks like a
//! key; `.name` replaces the last part of the key before it.
std::vector<std::string> keys_in(std::string_view cell) {
  std::vector<std::string> keys;
  for (std::size_t open = cell.find('`'); open != std::string_view::npos;) {
    const std::size_t close = cell.find('`', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view token = cell.substr(open + 1, close - open - 1);
    if (is_key_token(token)) {
      if (token.front() == '.' && !keys.empty()) {
        const std::string& before = keys.back();
        const std::size_t dot = before.rfind('.');
        keys.push_back((dot == std::string::npos ? std::string() : before.substr(0, dot)) +
                       std::string(token));
      } else if (token.front() != '.') {
        keys.emplace_back(token);
      }
    }
    open = cell.find('`', close + 1);
  }
  return keys;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string joined(const std::string& a, const std::string& b, const char* separator) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a + separator + b;
}

//! A range column without a type column ("> 0", "(−1, 0.5)") is a number's.
std::string type_of(const std::string& type, const std::string& range) {
  if (!type.empty() || range.empty()) return joined(type, range, ", ");
  for (const char* comparison : {">", "<", "≥", "≤"})
    if (starts_with(range, comparison)) return "number " + range;
  if (range.front() == '(' || range.front() == '[') return "number in " + range;
  return range;
}

}  // namespace

std::string strip_markdown(std::string_view text) {
  std::string out;
  bool code = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '`') {
      code = !code;
      continue;
    }
    if (c == '\\' && i + 1 < text.size() && text[i + 1] == '|') continue;  // \| is a pipe
    if (!code && c == '*') continue;                                       // emphasis
    if (!code && c == '[') {  // [text](target): the text
      const std::size_t close = text.find("](", i);
      const std::size_t end = close == std::string_view::npos ? close : text.find(')', close);
      if (end != std::string_view::npos && text.substr(i, close - i).find('\n') == text.npos) {
        out += strip_markdown(text.substr(i + 1, close - i - 1));
        i = end;
        continue;
      }
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!out.empty() && out.back() != ' ') out += ' ';
      continue;
    }
    out += c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

KeyTables parse_key_tables(std::string_view markdown) {
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start <= markdown.size();) {
    const std::size_t end = std::min(markdown.find('\n', start), markdown.size());
    lines.push_back(markdown.substr(start, end - start));
    start = end + 1;
  }
  KeyTables out;
  const auto problem = [&](std::size_t line, const std::string& what) {
    out.problems.push_back("user-guide.md:" + std::to_string(line + 1) + ": " + what);
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string_view marker = trim(lines[i]);
    if (!starts_with(marker, "<!-- keys:")) continue;
    if (marker.size() < 13 || marker.substr(marker.size() - 3) != "-->") {
      problem(i, "expected <!-- keys: SECTION (WHERE) --> on one line");
      continue;
    }
    marker = trim(marker.substr(10, marker.size() - 13));
    const std::size_t paren = marker.find('(');
    const std::string section(trim(marker.substr(0, paren)));
    std::string where;
    if (paren != std::string_view::npos) {
      const std::size_t close = marker.rfind(')');
      if (close == std::string_view::npos || close < paren) {
        problem(i, "expected the marker's WHERE in parentheses");
        continue;
      }
      where = strip_markdown(marker.substr(paren + 1, close - paren - 1));
    }
    if (section.empty() || section.find(' ') != std::string::npos) {
      problem(i, "expected a section (a dotted path) after keys:");
      continue;
    }
    std::size_t row = i + 1;
    while (row < lines.size() && trim(lines[row]).empty()) ++row;
    if (row + 1 >= lines.size() || !starts_with(trim(lines[row]), "|") ||
        !is_separator(lines[row + 1])) {
      problem(i, "expected a table after the marker");
      continue;
    }
    const std::vector<std::string> header = cells_of(lines[row]);
    int key = -1, type = -1, range = -1, unit = -1, fallback = -1, meaning = -1, variant = -1;
    for (int c = 0; c < static_cast<int>(header.size()); ++c) {
      const std::string name = lower(strip_markdown(header[c]));
      if (name == "key") key = c;
      if (name == "type") type = c;
      if (name == "range") range = c;
      if (name == "unit") unit = c;
      if (name == "default") fallback = c;
      if (name == "meaning") meaning = c;
      if (name == "model" || name == "shape" || name == "kind") variant = c;
    }
    if (key < 0) {
      problem(row, "expected a column named key");
      continue;
    }
    std::string variant_text;
    for (row += 2; row < lines.size() && starts_with(trim(lines[row]), "|"); ++row) {
      const std::vector<std::string> cells = cells_of(lines[row]);
      const auto cell = [&](int c) {
        return c >= 0 && c < static_cast<int>(cells.size()) ? strip_markdown(cells[c])
                                                            : std::string();
      };
      if (variant >= 0 && !cell(variant).empty())
        variant_text = lower(strip_markdown(header[variant])) + " = " + cell(variant);
      const std::vector<std::string> names =
          key < static_cast<int>(cells.size()) ? keys_in(cells[key]) : std::vector<std::string>{};
      if (names.empty()) {
        problem(row, "expected one or more keys in backticks in the key column");
        continue;
      }
      for (const std::string& name : names) {
        DocumentedKey k;
        k.key = section + "." + name;
        k.where = joined(where, variant_text, "; ");
        k.type = type_of(cell(type), cell(range));
        k.unit = cell(unit);
        k.default_value = cell(fallback);
        k.meaning = cell(meaning);
        k.line = static_cast<int>(row) + 1;
        out.keys.push_back(std::move(k));
      }
    }
  }
  return out;
}

const std::vector<DocumentedKey>& documented_keys() {
  static const std::vector<DocumentedKey> keys = parse_key_tables(user_guide_text()).keys;
  return keys;
}

}  // namespace pellicle
