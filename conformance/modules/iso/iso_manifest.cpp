#include "conformance/modules/iso/iso_manifest.h"

#include <algorithm>

#include "conformance/io/atomic_file.h"

namespace voxref::conf {
namespace {

// A scene's files are written under <dir>/<name>/: the name must be one plain path component.
bool plainName(std::string_view n) {
  return !n.empty() && n != "." && n != ".." && n.find('/') == std::string_view::npos &&
         n.find('\0') == std::string_view::npos;
}

// A file's path must stay inside the fixture directory: relative, no "." or ".." component.
bool insideDirectory(std::string_view p) {
  if (p.empty() || p.front() == '/' || p.find('\0') != std::string_view::npos) return false;
  std::size_t begin = 0;
  while (begin <= p.size()) {
    const std::size_t end = std::min(p.find('/', begin), p.size());
    const std::string_view part = p.substr(begin, end - begin);
    if (part == "." || part == "..") return false;
    begin = end + 1;
  }
  return true;
}

bool sha256Hex(std::string_view s) {
  return s.size() == 64 &&
         std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

}  // namespace

IsoFixtureManifest parseIsoFixtureManifest(std::string_view bytes, const std::string& sourceName) {
  struct Fail {
    const std::string& source;
    [[noreturn]] void operator()(const std::string& what) const { throw io::FormatError(source + ": " + what); }
  } const fail{sourceName};
  IsoFixtureManifest m;
  try {
    m.document = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number beyond double
    fail(std::string("not JSON: ") + e.what());
  }
  const nlohmann::json& d = m.document;
  if (!d.is_object()) fail("expected a JSON object");
  if (const auto g = d.find("generator"); g != d.end()) {  // a missing generator is a mismatch, reported by verify
    if (!g->is_string()) fail("generator: expected a string, got " + g->dump());
    m.generator = g->get<std::string>();
  }
  const auto scenes = d.find("scenes");
  if (scenes == d.end() || !scenes->is_array()) fail("scenes: expected an array");
  for (std::size_t i = 0; i < scenes->size(); ++i) {
    const std::string at = "scenes[" + std::to_string(i) + "]";
    try {
      m.scenes.push_back(isoSceneFromJson((*scenes)[i]));
    } catch (const nlohmann::json::exception& e) {
      fail(at + ": " + e.what());
    } catch (const JsonFieldError& e) {
      fail(at + "." + e.what());
    }
    if (!plainName(m.scenes.back().name))
      fail(at + ".name: '" + m.scenes.back().name +
           "' is not a plain file name (the scene's files are written under it)");
  }
  const auto files = d.find("files");
  if (files == d.end() || !files->is_array()) fail("files: expected an array");
  for (std::size_t i = 0; i < files->size(); ++i) {
    const std::string at = "files[" + std::to_string(i) + "]";
    const nlohmann::json& f = (*files)[i];
    if (!f.is_object()) fail(at + ": expected an object");
    const auto path = f.find("path"), sha = f.find("sha256");
    if (path == f.end() || !path->is_string()) fail(at + ".path: expected a string");
    if (sha == f.end() || !sha->is_string()) fail(at + ".sha256: expected a string");
    IsoFixtureFile file{path->get<std::string>(), sha->get<std::string>()};
    if (!insideDirectory(file.path))
      fail(at + ".path: '" + file.path + "' is not a relative path inside the fixture directory");
    if (!sha256Hex(file.sha256)) fail(at + ".sha256: expected 64 lowercase hexadecimal digits");
    m.files.push_back(std::move(file));
  }
  return m;
}

}  // namespace voxref::conf
