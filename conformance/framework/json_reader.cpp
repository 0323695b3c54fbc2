#include "conformance/framework/json_reader.h"

namespace voxref::conf {

JsonObjectReader::JsonObjectReader(const nlohmann::json& j, std::string path) : j_(&j), path_(std::move(path)) {
  if (!j.is_object())
    throw JsonFieldError((path_.empty() ? std::string("the document") : path_) + ": expected an object, got " +
                         j.dump());
}

const nlohmann::json& JsonObjectReader::at(const char* key) {
  if (!j_->contains(key)) throw JsonFieldError(fieldPath(key) + ": missing");
  read_.insert(key);
  return (*j_)[key];
}

int JsonObjectReader::getInt(const char* key, int fallback, int lo, int hi) {
  const int v = get<int>(key, fallback);
  if (v < lo || v > hi)
    throw JsonFieldError(fieldPath(key) + ": " + std::to_string(v) + " is outside " + std::to_string(lo) + ".." +
                         std::to_string(hi));
  return v;
}

std::int64_t JsonObjectReader::integerIn(const nlohmann::json& v, const std::string& path, std::int64_t lo,
                                         std::int64_t hi) {
  // Checked before nlohmann converts it: get<int>() of 1e300 is undefined behaviour, of 2.5 a truncation.
  if (!v.is_number_integer()) throw JsonFieldError(path + ": expected an integer, got " + v.dump());
  const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(hi) &&
                                                 (lo <= 0 || v.get<std::uint64_t>() >= static_cast<std::uint64_t>(lo))
                                           : v.get<std::int64_t>() >= lo && v.get<std::int64_t>() <= hi;
  if (!fits)
    throw JsonFieldError(path + ": " + v.dump() + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  return v.is_number_unsigned() ? static_cast<std::int64_t>(v.get<std::uint64_t>()) : v.get<std::int64_t>();
}

std::int64_t JsonObjectReader::getInteger(const char* key, std::int64_t lo, std::int64_t hi) {
  return integerIn(at(key), fieldPath(key), lo, hi);
}

std::vector<std::int64_t> JsonObjectReader::getIntegers(const char* key, std::size_t count, std::int64_t lo,
                                                        std::int64_t hi) {
  const nlohmann::json& v = at(key);
  if (!v.is_array() || v.size() != count)
    throw JsonFieldError(fieldPath(key) + ": expected " + std::to_string(count) + " integers, got " + v.dump());
  std::vector<std::int64_t> out;
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(integerIn(v[i], fieldPath(key) + "[" + std::to_string(i) + "]", lo, hi));
  return out;
}

JsonObjectReader JsonObjectReader::object(const char* key) { return JsonObjectReader(at(key), fieldPath(key)); }

void JsonObjectReader::finish() const {
  for (const auto& [key, value] : j_->items())
    if (!read_.count(key)) throw JsonFieldError(fieldPath(key.c_str()) + ": unknown key");
}

void readFrameExtents(JsonObjectReader& r, int& width, int& height, int& planes) {
  if (r.has("image")) {
    const auto image = r.get<std::vector<int>>("image");
    if (image.size() != 2 || image[0] < 1 || image[1] < 1 || image[0] > 4096 || image[1] > 4096)
      throw JsonFieldError("image: expected [width, height] within 1..4096");
    width = image[0];
    height = image[1];
  }
  planes = r.getInt("planes", planes, 1, 4096);
}

}  // namespace voxref::conf
