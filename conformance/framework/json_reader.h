// Strict reading of JSON objects: every key must be known, every value of the expected type and
// range; errors name the full path of the field ("texture.format") and what was expected.
#pragma once

#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

namespace voxref::conf {

class JsonFieldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class JsonObjectReader {
 public:
  // Throws JsonFieldError if `j` is not an object.
  JsonObjectReader(const nlohmann::json& j, std::string path);

  bool has(const char* key) const { return j_->contains(key); }
  // The value at `key`, converted to T (bool, int, double, std::string, std::vector<...>).
  template <class T>
  T get(const char* key) {
    const nlohmann::json& v = at(key);
    try {
      // Integers are checked before nlohmann converts them: its get<int>() of 1e300 is undefined
      // behaviour, of 2.5 or 2^40 a silent truncation.
      if constexpr (std::is_same_v<T, int>) {
        if (!isInt(v)) throw JsonFieldError("");
      } else if constexpr (std::is_same_v<T, std::vector<int>>) {
        if (!v.is_array()) throw JsonFieldError("");
        for (const nlohmann::json& e : v)
          if (!isInt(e)) throw JsonFieldError("");
      } else if constexpr (std::is_same_v<T, double>) {
        if (!v.is_number()) throw JsonFieldError("");
      } else if constexpr (std::is_same_v<T, bool>) {
        if (!v.is_boolean()) throw JsonFieldError("");
      } else if constexpr (std::is_same_v<T, std::string>) {
        if (!v.is_string()) throw JsonFieldError("");
      }
      return v.get<T>();
    } catch (const std::exception&) {
      throw JsonFieldError(fieldPath(key) + ": expected " + typeName<T>() + ", got " + v.dump());
    }
  }
  template <class T>
  T get(const char* key, T fallback) {
    return has(key) ? get<T>(key) : fallback;
  }
  int getInt(const char* key, int fallback, int lo, int hi);  // with a range check
  // A required integer in [lo, hi] (int64; a JSON integer, not 2.0 or 1e300).
  std::int64_t getInteger(const char* key, std::int64_t lo, std::int64_t hi);
  // A required array of exactly `count` integers, each in [lo, hi]; errors name the element
  // ("dims[2]: 2000 is outside 1..1025").
  std::vector<std::int64_t> getIntegers(const char* key, std::size_t count, std::int64_t lo, std::int64_t hi);
  // A nested object reader; the key counts as known.
  JsonObjectReader object(const char* key);
  // Throws JsonFieldError naming the first key that was never read.
  void finish() const;
  std::string fieldPath(const char* key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  const nlohmann::json& at(const char* key);
  static std::int64_t integerIn(const nlohmann::json& v, const std::string& path, std::int64_t lo, std::int64_t hi);
  // An integer within int's range (a JSON integer: not 2.0).
  static bool isInt(const nlohmann::json& v) {
    if (v.is_number_unsigned())
      return v.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    return v.is_number_integer() && v.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
           v.get<std::int64_t>() <= std::numeric_limits<int>::max();
  }
  template <class T>
  static std::string typeName() {
    if constexpr (std::is_same_v<T, int>) return "an integer";
    if constexpr (std::is_same_v<T, std::vector<int>>) return "an array of integers";
    if constexpr (std::is_same_v<T, std::vector<double>>) return "an array of numbers";
    if constexpr (std::is_same_v<T, double>) return "a number";
    if constexpr (std::is_same_v<T, bool>) return "true or false";
    if constexpr (std::is_same_v<T, std::string>) return "a string";
    return "a value of another type";
  }

  const nlohmann::json* j_;
  std::string path_;
  std::set<std::string> read_;
};

// The extents of a plane frame as both plane-based scene kinds take them (sparse grids and
// time-varying volumes): "image" [width, height] and "planes", each within 1..4096, both optional
// (the arguments keep their values when a key is absent). JsonFieldError naming the field.
void readFrameExtents(JsonObjectReader& r, int& width, int& height, int& planes);

}  // namespace voxref::conf
