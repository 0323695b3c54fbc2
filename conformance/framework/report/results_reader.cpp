#include "conformance/framework/report/results_reader.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "conformance/io/atomic_file.h"

namespace voxref::conf {
namespace {

const nlohmann::json& field(const nlohmann::json& j, const char* key, const std::string& where) {
  if (!j.is_object()) throw ResultsFormatError(where + ": expected an object");
  const auto it = j.find(key);
  if (it == j.end()) throw ResultsFormatError(where + "." + key + ": missing");
  return *it;
}

std::string text(const nlohmann::json& j, const char* key, const std::string& where) {
  const nlohmann::json& v = field(j, key, where);
  if (!v.is_string()) throw ResultsFormatError(where + "." + key + ": expected a string");
  return v.get<std::string>();
}

std::string optionalText(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

double numberValue(const nlohmann::json& v, const std::string& what) {
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();  // written for NaN
  if (!v.is_number()) throw ResultsFormatError(what + ": expected a number");
  return v.get<double>();
}

double number(const nlohmann::json& j, const char* key, const std::string& where) {
  return numberValue(field(j, key, where), where + "." + key);
}

// An int, checked before it is converted (a NaN or 1e300 converted into an int is undefined).
int integer(const nlohmann::json& j, const char* key, const std::string& where) {
  const nlohmann::json& v = field(j, key, where);
  const bool fits = v.is_number_unsigned()
                        ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                        : v.is_number_integer() && v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                              v.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) throw ResultsFormatError(where + "." + key + ": expected an integer (an int), got " + v.dump());
  return static_cast<int>(v.get<std::int64_t>());
}

// What judged a case or an oracle (case.h, Judge); absent in results.json of earlier versions: none.
Judge optionalJudge(const nlohmann::json& j, const char* key, const std::string& where) {
  const auto it = j.find(key);
  if (it == j.end()) return Judge::None;
  const auto judge = it->is_string() ? parseJudge(it->get<std::string>()) : std::nullopt;
  if (!judge)
    throw ResultsFormatError(where + "." + key +
                             ": expected one of none, exact, envelope, fetch, iso_geometry, prediction, gl_behaviour");
  return *judge;
}

}  // namespace

CaseResult caseFromJson(const nlohmann::json& j) {
  CaseResult r;
  r.id = text(j, "id", "case");
  const std::string where = "case " + r.id;
  r.system = text(j, "system", where);
  r.description = text(j, "description", where);
  const auto status = parseStatus(text(j, "status", where));
  if (!status) throw ResultsFormatError(where + ".status: not one of pass, warn, fail, skip, crash, timeout");
  r.status = *status;
  r.message = text(j, "message", where);
  r.judgedBy = optionalJudge(j, "judged_by", where);
  if (const auto it = j.find("probed_model_failed"); it != j.end()) {  // absent in earlier versions
    if (!it->is_boolean()) throw ResultsFormatError(where + ".probed_model_failed: expected true or false");
    r.probedModelFailed = it->get<bool>();
  }
  r.stderrText = optionalText(j, "stderr");
  const nlohmann::json& oracles = field(j, "oracles", where);
  if (!oracles.is_object()) throw ResultsFormatError(where + ".oracles: expected an object");
  for (const auto& [key, o] : oracles.items()) {
    const std::string at = where + ".oracles." + key;
    const auto verdict = parseVerdict(text(o, "verdict", at));
    if (!verdict) throw ResultsFormatError(at + ".verdict: unknown");
    r.oracles.push_back(
        {key, *verdict, text(o, "summary", at), field(o, "figures", at), optionalJudge(o, "judges", at)});
  }
  const nlohmann::json& effects = field(j, "effects", where);
  if (!effects.is_array()) throw ResultsFormatError(where + ".effects: expected an array");
  for (const auto& e : effects) r.effects.push_back(e.is_string() ? e.get<std::string>() : e.dump());
  const nlohmann::json& findings = field(j, "findings", where);
  if (!findings.is_array()) throw ResultsFormatError(where + ".findings: expected an array");
  for (const auto& f : findings)
    r.findings.push_back({text(f, "id", where + ".findings"), text(f, "description", where + ".findings"),
                          field(f, "figures", where + ".findings")});
  r.figures = field(j, "figures", where);
  r.secondsGl = number(j, "seconds_gl", where);
  r.secondsEmulation = number(j, "seconds_emulation", where);
  r.secondsReference = number(j, "seconds_reference", where);
  if (const auto it = j.find("timings"); it != j.end()) {  // absent in results.json of earlier versions
    if (!it->is_object()) throw ResultsFormatError(where + ".timings: expected an object");
    r.timings = *it;
  }
  // seconds, reruns and outcome are absent in results.json of earlier versions.
  if (const auto it = j.find("seconds"); it != j.end()) r.seconds = number(j, "seconds", where);
  if (const auto it = j.find("reruns"); it != j.end()) {
    if (!it->is_array()) throw ResultsFormatError(where + ".reruns: expected an array of statuses");
    for (const auto& s : *it) {
      const auto st = s.is_string() ? parseStatus(s.get<std::string>()) : std::nullopt;
      if (!st) throw ResultsFormatError(where + ".reruns: not one of pass, warn, fail, skip, crash, timeout");
      r.reruns.push_back(*st);
    }
  }
  r.outcome = optionalText(j, "outcome");
  const nlohmann::json& images = field(j, "images", where);
  r.images.rendered = optionalText(images, "rendered");
  r.images.emulated = optionalText(images, "emulated");
  r.images.reference = optionalText(images, "reference");
  r.images.errorMask = optionalText(images, "error_mask");
  if (const auto it = j.find("worst_pixels"); it != j.end() && it->is_array())
    for (const auto& w : *it) {
      const std::string at = where + ".worst_pixels";
      PixelValues p;
      p.x = integer(w, "x", at);
      p.y = integer(w, "y", at);
      p.k = integer(w, "k", at);
      p.oracle = text(w, "oracle", at);
      p.gl = number(w, "gl", at);
      p.emulated = number(w, "emulated", at);
      p.reference = number(w, "reference", at);
      if (const auto a = w.find("allowed"); a != w.end() && a->is_array() && a->size() == 2)
        p.allowed = std::make_pair(numberValue((*a)[0], at + ".allowed"), numberValue((*a)[1], at + ".allowed"));
      r.worstPixels.push_back(p);
    }
  return r;
}

LoadedResults loadResults(const std::filesystem::path& file) {
  std::string bytes;
  try {
    bytes = io::readWholeFile(file);
  } catch (const std::exception& e) {
    throw ResultsFormatError(e.what());
  }
  return parseResults(bytes, file.string());
}

LoadedResults parseResults(std::string_view bytes, const std::string& where) {
  LoadedResults out;
  try {
    out.document = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number beyond double
    throw ResultsFormatError(where + ": not JSON: " + e.what());
  }
  // Compared as JSON values: value("format", "") would throw type_error for a format of another type.
  const nlohmann::json& doc = out.document;
  if (!doc.is_object() || !doc.contains("format") || doc["format"] != "voxref-results")
    throw ResultsFormatError(where + ": not a voxref results file (\"format\" is not \"voxref-results\")");
  if (!doc.contains("format_version") || doc["format_version"] != 1)
    throw ResultsFormatError(where + ": results format version " +
                             (doc.contains("format_version") ? doc["format_version"].dump() : "(none)") +
                             " (this voxref reads version 1)");
  const nlohmann::json& cases = field(out.document, "cases", where);
  if (!cases.is_array()) throw ResultsFormatError(where + ".cases: expected an array");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    try {
      out.cases.push_back(caseFromJson(cases[i]));
    } catch (const nlohmann::json::exception& e) {
      throw ResultsFormatError(where + ": cases[" + std::to_string(i) + "]: " + e.what());
    } catch (const ResultsFormatError& e) {  // caseFromJson names the case and the field; this names the file
      throw ResultsFormatError(where + ": cases[" + std::to_string(i) + "]: " + e.what());
    }
  }
  return out;
}

}  // namespace voxref::conf
