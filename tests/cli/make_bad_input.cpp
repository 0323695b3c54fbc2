// make_bad_input: derives a bad input file from a good one, for the bad-input catalogue
// (tests/cli/bad_input_tests.cmake, docs/bad_input.md). It knows nothing of voxref's code: the
// edits are written from the format documents (byte offsets, field widths, where a CRC-32 lies),
// and the CRC-32 and gzip are zlib's own.
//
//   make_bad_input GOOD OUT [OP ...]      GOOD "-" starts from no bytes
//
// The operations apply in order to the bytes of GOOD; the result is written to OUT.
//   truncate:N           keep the first N bytes (N < 0: drop the last -N bytes)
//   u8:OFF=V u16:OFF=V u32:OFF=V u64:OFF=V
//                        store V (decimal, or 0x hexadecimal) little endian at byte OFF
//                        (OFF < 0: counted from the end)
//   flip:OFF             invert every bit of the byte at OFF
//   crc32:BEGIN:END:AT   store the CRC-32 of bytes [BEGIN, END) at AT (END <= 0 and AT < 0:
//                        counted from the end), to make a field error reach past a checksum
//   append:TEXT          append TEXT
//   text:TEXT            replace everything by TEXT
//   gzip                 gzip-compress the bytes
//   gzip-zeros:N         replace everything by a gzip stream of N zero bytes (streamed: N may
//                        exceed the memory; a "gzip bomb")
//   json:POINTER=JSON    parse the bytes as JSON, set the value at the JSON pointer, write back
//   json-remove:POINTER  parse the bytes as JSON, remove the value at the JSON pointer
//   socket               make OUT a Unix-domain socket (bound, then left behind) instead of a file
//                        (make_bad_input - OUT socket); for outputs that are not regular files
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

[[noreturn]] void die(const std::string& what) {
  std::cerr << "make_bad_input: " << what << "\n";
  std::exit(1);
}

long long number(const std::string& s) {
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(s, &used, 0);
  } catch (const std::exception&) {
    die("not a number: '" + s + "'");
  }
  if (used != s.size()) die("not a number: '" + s + "'");
  return v;
}

std::size_t offsetIn(const std::string& bytes, long long off, std::size_t width) {
  const long long at = off < 0 ? static_cast<long long>(bytes.size()) + off : off;
  if (at < 0 || static_cast<std::size_t>(at) + width > bytes.size())
    die("offset " + std::to_string(off) + " (+" + std::to_string(width) + ") is outside the " +
        std::to_string(bytes.size()) + " bytes");
  return static_cast<std::size_t>(at);
}

void storeLe(std::string& bytes, long long off, std::size_t width, std::uint64_t v) {
  const std::size_t at = offsetIn(bytes, off, width);
  for (std::size_t i = 0; i < width; ++i) bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
}

std::string gzipped(const std::string& bytes) {
  z_stream s{};
  if (deflateInit2(&s, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) die("deflateInit2 failed");
  std::string out(deflateBound(&s, static_cast<uLong>(bytes.size())) + 64, '\0');
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  s.avail_in = static_cast<uInt>(bytes.size());
  s.next_out = reinterpret_cast<Bytef*>(out.data());
  s.avail_out = static_cast<uInt>(out.size());
  if (deflate(&s, Z_FINISH) != Z_STREAM_END) die("deflate failed");
  out.resize(s.total_out);
  deflateEnd(&s);
  return out;
}

std::string gzippedZeros(std::uint64_t n) {
  z_stream s{};
  if (deflateInit2(&s, Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) die("deflateInit2 failed");
  const std::vector<unsigned char> zeros(std::size_t{1} << 20, 0);
  std::vector<unsigned char> chunk(std::size_t{1} << 20);
  std::string out;
  int flush = Z_NO_FLUSH;
  do {
    const std::uint64_t take = n < zeros.size() ? n : zeros.size();
    n -= take;
    flush = n == 0 ? Z_FINISH : Z_NO_FLUSH;
    s.next_in = const_cast<Bytef*>(zeros.data());
    s.avail_in = static_cast<uInt>(take);
    do {
      s.next_out = chunk.data();
      s.avail_out = static_cast<uInt>(chunk.size());
      if (deflate(&s, flush) == Z_STREAM_ERROR) die("deflate failed");
      out.append(reinterpret_cast<const char*>(chunk.data()), chunk.size() - s.avail_out);
    } while (s.avail_out == 0);
  } while (flush != Z_FINISH);
  deflateEnd(&s);
  return out;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

void applyOp(std::string& bytes, const std::string& op) {
  const std::size_t colon = op.find(':');
  const std::string name = op.substr(0, colon), arg = colon == std::string::npos ? "" : op.substr(colon + 1);
  if (name == "truncate") {
    const long long n = number(arg);
    const long long keep = n < 0 ? static_cast<long long>(bytes.size()) + n : n;
    if (keep < 0 || static_cast<std::size_t>(keep) > bytes.size())
      die("cannot keep " + std::to_string(keep) + " of " + std::to_string(bytes.size()) + " bytes");
    bytes.resize(static_cast<std::size_t>(keep));
  } else if (name == "u8" || name == "u16" || name == "u32" || name == "u64") {
    const std::size_t eq = arg.find('=');
    if (eq == std::string::npos) die(op + ": expected OFF=V");
    const std::size_t width = name == "u8" ? 1 : name == "u16" ? 2 : name == "u32" ? 4 : 8;
    storeLe(bytes, number(arg.substr(0, eq)), width,
            static_cast<std::uint64_t>(std::stoull(arg.substr(eq + 1), nullptr, 0)));
  } else if (name == "flip") {
    const std::size_t at = offsetIn(bytes, number(arg), 1);
    bytes[at] = static_cast<char>(~static_cast<unsigned char>(bytes[at]));
  } else if (name == "crc32") {
    const std::vector<std::string> p = split(arg, ':');
    if (p.size() != 3) die(op + ": expected BEGIN:END:AT");
    const long long begin = number(p[0]), endArg = number(p[1]);
    const long long end = endArg <= 0 ? static_cast<long long>(bytes.size()) + endArg : endArg;
    if (begin < 0 || end < begin || static_cast<std::size_t>(end) > bytes.size()) die(op + ": range outside the bytes");
    const uLong c = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data() + begin),
                          static_cast<uInt>(end - begin));
    storeLe(bytes, number(p[2]), 4, c);
  } else if (name == "append") {
    bytes += arg;
  } else if (name == "text") {
    bytes = arg;
  } else if (name == "gzip") {
    bytes = gzipped(bytes);
  } else if (name == "gzip-zeros") {
    const long long n = number(arg);
    if (n < 0) die(op + ": a negative count");
    bytes = gzippedZeros(static_cast<std::uint64_t>(n));
  } else if (name == "json" || name == "json-remove") {
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(bytes);
    } catch (const std::exception& e) {
      die(std::string("the input is not JSON: ") + e.what());
    }
    try {
      if (name == "json") {
        const std::size_t eq = arg.find('=');
        if (eq == std::string::npos) die(op + ": expected POINTER=JSON");
        j[nlohmann::json::json_pointer(arg.substr(0, eq))] = nlohmann::json::parse(arg.substr(eq + 1));
      } else {
        const nlohmann::json::json_pointer ptr(arg);
        nlohmann::json& parent = j.at(ptr.parent_pointer());
        if (parent.is_array())
          parent.erase(static_cast<std::size_t>(std::stoul(ptr.back())));
        else if (parent.erase(ptr.back()) == 0)
          die(op + ": no such key");
      }
    } catch (const nlohmann::json::exception& e) {
      die(op + ": " + e.what());
    }
    bytes = j.dump(2) + "\n";
  } else {
    die("unknown operation '" + op + "'");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) die("usage: make_bad_input GOOD|- OUT [OP ...]");
  std::string bytes;
  if (std::string(argv[1]) != "-") {
    std::ifstream in(argv[1], std::ios::binary);
    if (!in) die(std::string("cannot read ") + argv[1]);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (argc == 4 && std::string(argv[3]) == "socket") {
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const std::string path = argv[2];
    if (path.size() >= sizeof addr.sun_path) die("socket path too long: " + path);
    path.copy(addr.sun_path, path.size());
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0 || ::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0)
      die("cannot make a socket at " + path);
    ::close(fd);
    return 0;
  }
  for (int i = 3; i < argc; ++i) applyOp(bytes, argv[i]);
  std::ofstream out(argv[2], std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) die(std::string("cannot write ") + argv[2]);
  return 0;
}
