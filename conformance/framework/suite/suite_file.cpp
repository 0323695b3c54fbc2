#include "conformance/framework/suite/suite_file.h"

#include <toml++/toml.h>

#include <set>

#include "conformance/io/atomic_file.h"

namespace voxref::conf {
namespace {

std::string at(const std::filesystem::path& file, const toml::source_region& where) {
  return file.string() + ":" + std::to_string(where.begin.line);
}

std::string text(const toml::node& n, const std::string& key, const std::string& where) {
  const auto v = n.value<std::string>();
  if (!n.is_string() || !v) throw SuiteFileError(where + ": " + key + " must be a string");
  return *v;
}

int whole(const toml::node& n, const std::string& key, const std::string& where, int least) {
  const auto v = n.value<int64_t>();
  if (!n.is_integer() || !v || *v < least || *v > 1000000)
    throw SuiteFileError(where + ": " + key + " must be a whole number of at least " + std::to_string(least));
  return static_cast<int>(*v);
}

std::vector<std::filesystem::path> paths(const toml::node& n, const std::string& key, const std::string& where,
                                         const std::filesystem::path& folder) {
  const toml::array* a = n.as_array();
  if (!a) throw SuiteFileError(where + ": " + key + " must be an array of file names");
  std::vector<std::filesystem::path> out;
  for (const toml::node& e : *a) {
    if (!e.is_string()) throw SuiteFileError(where + ": " + key + " must be an array of file names");
    const std::filesystem::path p(*e.value<std::string>());
    out.push_back(p.is_absolute() ? p : folder / p);
  }
  return out;
}

bool isName(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
  return true;
}

SuiteEntry entryOf(const toml::table& t, const std::filesystem::path& file) {
  SuiteEntry e;
  e.line = static_cast<int>(t.source().begin.line);
  const std::filesystem::path folder = file.parent_path();
  bool prefixGiven = false;
  for (const auto& [k, v] : t) {
    const std::string key(k.str());
    const std::string where = at(file, v.source());
    if (key == "name")
      e.name = text(v, key, where);
    else if (key == "driver")
      e.driver = text(v, key, where);
    else if (key == "profile")
      e.profile = text(v, key, where);
    else if (key == "filter")
      e.filter = text(v, key, where);
    else if (key == "caselists")
      e.caseLists = paths(v, key, where, folder);
    else if (key == "fails")
      e.fails = paths(v, key, where, folder);
    else if (key == "flakes")
      e.flakes = paths(v, key, where, folder);
    else if (key == "skips")
      e.skips = paths(v, key, where, folder);
    else if (key == "prefix")
      e.prefix = text(v, key, where), prefixGiven = true;
    else if (key == "fraction")
      e.fraction = whole(v, key, where, 1);
    else if (key == "flake_reruns")
      e.flakeReruns = whole(v, key, where, 0);
    else if (key == "renderer_check")
      e.rendererCheck = text(v, key, where);
    else if (key == "version_check")
      e.versionCheck = text(v, key, where);
    else if (key == "env") {
      const toml::table* env = v.as_table();
      if (!env) throw SuiteFileError(where + ": env must be a table of NAME = \"value\"");
      for (const auto& [name, value] : *env) {
        const std::string n(name.str());
        e.env.emplace_back(n, text(value, "env." + n, at(file, value.source())));
      }
    } else
      throw SuiteFileError(where + ": unknown key '" + key +
                           "' in [[conform]] (expected name, driver, profile, filter, caselists, fails, flakes, skips, "
                           "prefix, fraction, flake_reruns, renderer_check, version_check, env)");
  }
  const std::string where = file.string() + ":" + std::to_string(e.line);
  if (e.name.empty()) throw SuiteFileError(where + ": a [[conform]] entry needs a name");
  if (!isName(e.name))
    throw SuiteFileError(where + ": name '" + e.name + "' must be lower-case letters, digits, '_' and '-'");
  if (!prefixGiven) e.prefix = e.name + ".";
  return e;
}

}  // namespace

std::vector<SuiteEntry> parseSuiteText(const std::string& text, const std::filesystem::path& file) {
  toml::table root;
  try {
    root = toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    throw SuiteFileError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                         std::string(e.description()));
  }
  std::vector<SuiteEntry> entries;
  std::set<std::string> names;
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (key != "conform")
      throw SuiteFileError(at(file, v.source()) + ": unknown key '" + key + "' (a suite holds [[conform]] entries)");
    const toml::array* a = v.as_array();
    if (!a || !a->is_array_of_tables())
      throw SuiteFileError(at(file, v.source()) + ": conform must be an array of tables ([[conform]])");
    for (const toml::node& t : *a) {
      SuiteEntry e = entryOf(*t.as_table(), file);
      if (!names.insert(e.name).second)
        throw SuiteFileError(file.string() + ":" + std::to_string(e.line) + ": a second entry named '" + e.name + "'");
      entries.push_back(std::move(e));
    }
  }
  if (entries.empty()) throw SuiteFileError(file.string() + ": no [[conform]] entry");
  return entries;
}

std::vector<SuiteEntry> readSuiteFile(const std::filesystem::path& file) {
  std::string text;
  try {
    text = io::readWholeFile(file);
  } catch (const io::IoError& e) {
    throw SuiteFileError(std::string("suite file ") + e.what());
  }
  return parseSuiteText(text, file);
}

}  // namespace voxref::conf
