// docs/user-guide.md and the case readers agree: every key a reader asks for, reading the
// built-in cases and every variant of each section (material models, region, membrane and
// surface shapes, contact, boundary and PDE models, probe quantities), is in the guide's key
// tables (`pellicle list keys` prints them).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "pellicle/core/error.hpp"
#include "pellicle/io/builtin_cases.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/io/case_keys.hpp"
#include "pellicle/io/surface_case.hpp"
#include "pellicle/io/toml_parameters.hpp"

namespace pellicle {
namespace {

//! A key as the guide writes it: "body[1].region.parts[0].radius" → "body.region.radius"
//! (no indices; a region's parts are regions).
std::string normalised(const std::string& asked) {
  std::string key;
  for (std::size_t i = 0; i < asked.size(); ++i) {
    if (asked[i] != '[') {
      key += asked[i];
      continue;
    }
    i = asked.find(']', i);
  }
  for (std::size_t at; (at = key.find("region.parts.")) != std::string::npos;) key.erase(at + 6, 6);
  // An entry of [[surface.shapes]] is a shape table.
  if (key.rfind("surface.shapes.", 0) == 0) key.erase(13, 1);
  return key;
}

//! Every key asked for while reading `text` with `sets`; the case may be refused (the
//! variants below leave out required keys), the readers ask for the keys all the same.
std::set<std::string> asked_keys(const std::string& text, const std::string& name,
                                 const std::vector<std::string>& sets, std::string* refused) {
  AskedKeys asked;
  try {
    const auto source = case_source_from_text(text, name, sets);
    if (is_surface_case(*source)) {
      if (surface_case_dimension(*source) == 2)
        read_surface_case<2>(*source);
      else
        read_surface_case<3>(*source);
    } else if (case_dimension(*source) == 2) {
      read_case<2>(*source);
    } else {
      read_case<3>(*source);
    }
  } catch (const InputError& e) {
    if (refused) *refused = e.what();
  }
  std::set<std::string> keys;
  for (const auto& k : asked.keys()) keys.insert(normalised(k));
  return keys;
}

//! The options a choice offers, from the message refusing an unknown one ("expected one of
//! \"a\", \"b\" or \"c\", found …"), so new models and shapes are covered without a list.
std::vector<std::string> options_of(const std::string& case_name, const std::string& set) {
  std::string refused;
  asked_keys(builtin_case(case_name), case_name, {set}, &refused);
  std::vector<std::string> options;
  const auto from = refused.find("expected one of ");
  const auto to = refused.find(", found", from);
  EXPECT_NE(from, std::string::npos) << set << ": " << refused;
  if (from == std::string::npos) return options;
  for (auto open = refused.find('"', from); open < to;) {
    const auto close = refused.find('"', open + 1);
    options.push_back(refused.substr(open + 1, close - open - 1));
    open = refused.find('"', close + 1);
  }
  EXPECT_FALSE(options.empty()) << refused;
  return options;
}

//! Whether `guide` holds `key`: as a key, as the table of keys it has (a section), or through
//! a key part `<name>` (in either), which stands for any name.
bool any_name(const std::string& part) {
  return !part.empty() && part.front() == '<' && part.back() == '>';
}

bool documented(const std::string& key, const std::vector<std::string>& guide) {
  const auto parts = [](const std::string& k) {
    std::vector<std::string> out;
    for (std::size_t start = 0;;) {
      const auto dot = k.find('.', start);
      out.push_back(k.substr(start, dot - start));
      if (dot == std::string::npos) return out;
      start = dot + 1;
    }
  };
  const auto wanted = parts(key);
  for (const auto& d : guide) {
    const auto have = parts(d);
    if (have.size() < wanted.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < wanted.size() && same; ++i)
      same = have[i] == wanted[i] || any_name(have[i]) || any_name(wanted[i]);
    if (same) return true;
  }
  return false;
}

TEST(UserGuideKeys, KeyTablesParse) {
  const KeyTables tables = parse_key_tables(user_guide_text());
  for (const auto& p : tables.problems) ADD_FAILURE() << p;
  EXPECT_GE(tables.keys.size(), 150u);
  std::set<std::string> sections;
  for (const auto& k : tables.keys) {
    sections.insert(k.key.substr(0, k.key.find('.')));
    EXPECT_EQ(k.key.find_first_of(" `*|"), std::string::npos) << k.key;
  }
  for (const char* s : {"case", "grid", "solver", "output", "material", "body", "contact",
                        "boundary", "probe", "surface", "pde"})
    EXPECT_TRUE(sections.count(s)) << s;
}

TEST(UserGuideKeys, MarkdownIsStripped) {
  EXPECT_EQ(strip_markdown("`\"fixed\"` \\| *required*  [theory](theory/x.md)"),
            "\"fixed\" | required theory");
  const KeyTables t = parse_key_tables(
      "<!-- keys: body (a `where`) -->\n\n| key | unit | meaning |\n|---|---|---|\n"
      "| `initial_stress.xx`, `.yy` | Pa | \\|x\\| of *it* |\n| no key | | |\n");
  ASSERT_EQ(t.keys.size(), 2u);
  EXPECT_EQ(t.keys[0].key, "body.initial_stress.xx");
  EXPECT_EQ(t.keys[1].key, "body.initial_stress.yy");
  EXPECT_EQ(t.keys[1].where, "a where");
  EXPECT_EQ(t.keys[1].meaning, "|x| of it");
  ASSERT_EQ(t.problems.size(), 1u);
  EXPECT_NE(t.problems[0].find("user-guide.md:6:"), std::string::npos) << t.problems[0];
}

//! Every key the readers ask for (→ the first reading that asked), reading every built-in
//! case and every variant of each section: a table with only the choice leaves the reader to
//! ask for all of that variant's keys (and to refuse the case for the missing ones).
const std::map<std::string, std::string>& keys_the_readers_ask_for() {
  static const std::map<std::string, std::string> asked = [] {
    std::map<std::string, std::string> out;
    const auto read = [&](const std::string& name, const std::vector<std::string>& sets) {
      std::string reading = name;
      for (const auto& s : sets) reading += " --set " + s;
      for (const auto& k : asked_keys(builtin_case(name), name, sets, nullptr))
        out.emplace(k, reading);
    };
    for (const auto& [name, text] : builtin_cases()) read(name, {});
    const auto each = [&](const std::string& name, const std::string& key, const char* before,
                          const char* after) {
      const auto set = [&](const std::string& option) {
        return key + "=" + before + "\"" + option + "\"" + after;
      };
      for (const auto& option : options_of(name, set("no-such"))) read(name, {set(option)});
    };
    for (const char* name : {"two_disks.toml", "elastic_bar_vibration_3d.toml"}) {
      each(name, "body[0].region", "{shape=", "}");
      each(name, "material[0].model", "", "");
      each(name, "contact", "{model=", "}");
      each(name, "boundary", "[{model=", "}]");
      each(name, "probe", "[{name=\"p\",body=\"b\",quantity=", "}]");
      read(name, {"body[0].initial_stress={xx=1.0,points=[0,1]}"});
    }
    each("fsi_quarter_circle.toml", "body[0].membrane", "{thickness=0.1,shape=", "}");
    each("fsi_balloon_3d.toml", "body[0].membrane", "{thickness=0.1,shape=", "}");
    each("surface_wave_sphere.toml", "surface.shape", "{kind=", "}");
    each("surface_wave_sphere.toml", "pde", "{model=", "}");
    read("surface_wave_sphere.toml", {"surface.shape={kind=\"circle\",center=[0.0,0.0],radius=1.0}",
                                      "surface.velocity=[\"0\",\"0\"]"});
    read("surface_wave_sphere.toml", {"output.monitors={radius=\"x\"}"});
    read("surface_joining_spheres.toml",
         {"surface.contact.rules=[{surfaces=[\"left\",\"right\"],response=\"merge\"}]"});
    return out;
  }();
  return asked;
}

TEST(UserGuideKeys, EveryKeyTheReadersAskForIsDocumented) {
  const auto& asked = keys_the_readers_ask_for();
  EXPECT_GE(asked.size(), 150u);
  std::vector<std::string> guide;
  for (const auto& d : documented_keys()) guide.push_back(d.key);
  for (const auto& [key, reading] : asked)
    EXPECT_TRUE(documented(key, guide))
        << key << " (asked for reading " << reading
        << ") is not in docs/user-guide.md's key tables: add it with its unit, default and "
           "meaning";
}

TEST(UserGuideKeys, EveryDocumentedKeyIsOneTheReadersAskFor) {
  std::vector<std::string> asked;
  for (const auto& [key, reading] : keys_the_readers_ask_for()) asked.push_back(key);
  for (const auto& d : documented_keys())
    EXPECT_TRUE(documented(d.key, asked))
        << d.key << " (docs/user-guide.md:" << d.line
        << ") is documented, but no reader asked for it: a misspelt or removed key?";
}

}  // namespace
}  // namespace pellicle
