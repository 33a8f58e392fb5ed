#include "common/names.hpp"

#include <algorithm>

namespace dtwin {

std::string closestName(const std::string& name, const std::vector<std::string>& known) {
  auto dist = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j)
        cur[j] =
            std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      std::swap(prev, cur);
    }
    return prev[b.size()];
  };
  std::string best;
  std::size_t bestd = 4;
  for (auto& k : known) {
    const std::size_t d = dist(name, k);
    if (d < bestd) {
      bestd = d;
      best = k;
    }
  }
  return best;
}

std::string unknownNameRule(const std::string& what, const std::string& name,
                            const std::vector<std::string>& known) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  const std::string hint = closestName(name, known);
  return "unknown " + what + " '" + name + "' (known: " + list +
         (hint.empty() ? "" : "; did you mean '" + hint + "'?") + ")";
}

}  // namespace dtwin
