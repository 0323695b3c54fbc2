#include "conformance/framework/shard.h"

#include <charconv>
#include <stdexcept>

namespace voxref::conf {

Shard parseShard(const std::string& text) {
  const auto slash = text.find('/');
  auto parse = [&](std::string_view s, int& v) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && end == s.data() + s.size() && !s.empty();
  };
  Shard s;
  if (slash == std::string::npos || !parse(std::string_view(text).substr(0, slash), s.index) ||
      !parse(std::string_view(text).substr(slash + 1), s.count))
    throw std::invalid_argument("--shard '" + text + "': expected I/N with whole numbers, for example 2/4");
  if (s.count < 1 || s.index < 1 || s.index > s.count)
    throw std::invalid_argument("--shard '" + text + "': I must be between 1 and N, and N at least 1");
  return s;
}

std::vector<Case> shardOf(const std::vector<Case>& selection, const Shard& shard) {
  std::vector<Case> out;
  for (std::size_t p = 0; p < selection.size(); ++p)
    if (static_cast<int>(p % static_cast<std::size_t>(shard.count)) == shard.index - 1) out.push_back(selection[p]);
  return out;
}

std::vector<Case> fractionOf(const std::vector<Case>& selection, int n) {
  if (n < 1) throw std::invalid_argument("--fraction must be at least 1");
  std::vector<Case> out;
  for (std::size_t p = 0; p < selection.size(); p += static_cast<std::size_t>(n)) out.push_back(selection[p]);
  return out;
}

std::optional<Shard> shardFromCiVariables(const char* nodeIndex, const char* nodeTotal) {
  if (!nodeIndex && !nodeTotal) return std::nullopt;
  if (!nodeIndex || !nodeTotal)
    throw std::invalid_argument(std::string(nodeIndex ? "CI_NODE_INDEX is set but CI_NODE_TOTAL is not"
                                                      : "CI_NODE_TOTAL is set but CI_NODE_INDEX is not") +
                                " (GitLab sets both for a job with parallel: N)");
  try {
    return parseShard(std::string(nodeIndex) + "/" + nodeTotal);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("CI_NODE_INDEX='" + std::string(nodeIndex) + "' and CI_NODE_TOTAL='" + nodeTotal +
                                "': expected whole numbers with 1 <= CI_NODE_INDEX <= CI_NODE_TOTAL");
  }
}

}  // namespace voxref::conf
