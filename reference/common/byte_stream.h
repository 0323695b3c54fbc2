// Little-endian byte streams for voxref's binary formats, written and read field by field.
//
// ByteReader is for untrusted bytes: every read checks the remaining length first and a failure
// throws StreamError carrying the byte offset and the field ("offset 24: page_bits: expected
// 6..20, got 31"), never reading past the end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace voxref::ref {

class StreamError : public std::runtime_error {
 public:
  StreamError(std::size_t offset, const std::string& detail)
      : std::runtime_error("offset " + std::to_string(offset) + ": " + detail), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

class ByteWriter {
 public:
  void bytes(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  void bytes(std::string_view s) { out_.append(s); }
  template <class T>
  void le(T v) {
    for (std::size_t i = 0; i < sizeof(T); ++i)
      out_.push_back(static_cast<char>((static_cast<std::uint64_t>(v) >> (8 * i)) & 0xff));
  }
  std::size_t size() const { return out_.size(); }
  std::string& str() { return out_; }

 private:
  std::string out_;
};

// Reads a little-endian unsigned value of `n` bytes at `p` (no bounds check: the caller has one).
inline std::uint64_t loadLe(const char* p, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[i])) << (8 * i);
  return v;
}

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes, std::size_t start = 0) : b_(bytes), at_(start) {}
  [[noreturn]] static void fail(std::size_t at, const std::string& what) { throw StreamError(at, what); }
  std::size_t offset() const { return at_; }
  std::size_t remaining() const { return b_.size() - at_; }
  template <class T>
  T le(const char* field) {
    need(sizeof(T), field);
    const T v = static_cast<T>(loadLe(b_.data() + at_, sizeof(T)));
    at_ += sizeof(T);
    return v;
  }
  // A value that must lie in [lo, hi]; the error names the field and the range.
  template <class T>
  T le(const char* field, std::uint64_t lo, std::uint64_t hi) {
    const std::size_t at = at_;
    const T v = le<T>(field);
    if (static_cast<std::uint64_t>(v) < lo || static_cast<std::uint64_t>(v) > hi)
      fail(at, std::string(field) + ": expected " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                   std::to_string(static_cast<std::uint64_t>(v)));
    return v;
  }
  std::string_view take(std::size_t n, const char* field) {
    need(n, field);
    const std::string_view v = b_.substr(at_, n);
    at_ += n;
    return v;
  }
  void need(std::size_t n, const char* field) const {
    if (b_.size() - at_ < n)
      fail(at_, std::string(field) + ": expected " + std::to_string(n) + " bytes, the stream ends after " +
                    std::to_string(b_.size() - at_));
  }

 private:
  std::string_view b_;
  std::size_t at_ = 0;
};

}  // namespace voxref::ref
