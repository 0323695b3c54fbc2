#include "reference/timevarying/transfer_function.h"

#include <stdexcept>

namespace voxref::ref {
namespace {

std::uint8_t mix(int a, int b, int v) { return static_cast<std::uint8_t>(a + (b - a) * (v - 1) / 254); }

TransferFunction plume(bool opaqueTop) {
  TransferFunction tf;
  tf.name = opaqueTop ? "opaque" : "plume";
  tf.table[0] = {0, 0, 0, 0};
  for (int v = 1; v < 256; ++v) {
    tf.table[v] = {mix(30, 250, v), mix(60, 230, v), mix(200, 40, v), mix(8, 240, v)};
    if (opaqueTop && v >= 200) tf.table[v][3] = 255;
  }
  return tf;
}

}  // namespace

std::vector<std::string> transferFunctionNames() { return {"plume", "opaque", "gray"}; }

TransferFunction transferFunction(std::string_view name) {
  if (name == "plume") return plume(false);
  if (name == "opaque") return plume(true);
  if (name == "gray") {
    TransferFunction tf;
    tf.name = "gray";
    for (int v = 0; v < 256; ++v) tf.table[v] = {std::uint8_t(v), std::uint8_t(v), std::uint8_t(v), std::uint8_t(v)};
    return tf;
  }
  std::string known;
  for (const auto& n : transferFunctionNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown transfer function '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace voxref::ref
