#pragma once
//! The case-file keys docs/user-guide.md documents, read from the guide's key tables (the
//! guide is compiled in). `pellicle list keys` prints them; a unit test checks that every key
//! the case readers ask for is among them.
//!
//! A key table is a markdown table right after a line `<!-- keys: SECTION (WHERE) -->`:
//! SECTION is the dotted path of the table the keys belong to ("solver", "body.membrane"),
//! WHERE (optional) says when they apply ("surface cases", `model = "gas"`). The table's
//! header names its columns: `key` (required: one or more keys in backticks, each relative
//! to SECTION; `.name` replaces the last part of the key before it, so `initial_stress.xx`,
//! `.yy` is two keys), `type`, `range`, `unit`, `default`, `meaning`, and `model`, `shape`
//! or `kind` for a column that says which variant of the section a row belongs to (an empty
//! cell: the row above's). Other columns are ignored. A key part `<name>` stands for any
//! name the user chooses.

#include <string>
#include <string_view>
#include <vector>

namespace pellicle {

struct DocumentedKey {
  std::string key;    //!< full dotted path without indices: "solver.end_time", "body.region.radius"
  std::string where;  //!< when it applies: "surface cases", "model = \"gas\"", or ""
  std::string type;   //!< type and range, e.g. "number > 0"
  std::string unit;
  std::string default_value;  //!< "required" for keys without default
  std::string meaning;
  int line = 0;  //!< its row in the guide
};

struct KeyTables {
  std::vector<DocumentedKey> keys;  //!< in the guide's order
  //! Marked tables the reader could not understand: "user-guide.md:120: no key column".
  std::vector<std::string> problems;
};

//! The key tables of a markdown text (the user guide's conventions above), markdown stripped.
KeyTables parse_key_tables(std::string_view markdown);

//! docs/user-guide.md as it was at build time.
const std::string& user_guide_text();

//! The keys of the compiled-in user guide.
const std::vector<DocumentedKey>& documented_keys();

//! Text as a reader sees it: code spans and emphasis unmarked, links reduced to their text,
//! `\|` to `|`, runs of white space to one space.
std::string strip_markdown(std::string_view text);

}  // namespace pellicle
