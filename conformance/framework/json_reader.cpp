#include "conformance/framework/json_reader.h"

namespace voxref::conf {

JsonObjectReader::JsonObjectReader(const nlohmann::json& j, std::string path) : j_(&j), path_(std::move(path)) {
  if (!j.is_object()) throw JsonFieldError((path_.empty() ? std::string("the document") : path_) + ": expected an object, got " + j.dump());
}

const nlohmann::json& JsonObjectReader::at(const char* key) {
  if (!j_->contains(key)) throw JsonFieldError(fieldPath(key) + ": missing");
  read_.insert(key);
  return (*j_)[key];
}

int JsonObjectReader::getInt(const char* key, int fallback, int lo, int hi) {
  const int v = get<int>(key, fallback);
  if (v < lo || v > hi)
    throw JsonFieldError(fieldPath(key) + ": " + std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

JsonObjectReader JsonObjectReader::object(const char* key) { return JsonObjectReader(at(key), fieldPath(key)); }

void JsonObjectReader::finish() const {
  for (const auto& [key, value] : j_->items())
    if (!read_.count(key)) throw JsonFieldError(fieldPath(key.c_str()) + ": unknown key");
}

}  // namespace voxref::conf
