#include "app/bench/bench_spread.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace raylab {
namespace {

// The median of the sorted values [from, to).
double sortedMedian(const std::vector<double>& v, size_t from, size_t to) {
  const size_t n = to - from, mid = from + n / 2;
  return n % 2 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
}

}  // namespace

Spread spreadOf(std::vector<double> v) {
  Spread s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.min = v.front();
  s.max = v.back();
  s.median = sortedMedian(v, 0, v.size());
  const size_t half = v.size() / 2;
  s.q1 = half ? sortedMedian(v, 0, half) : s.median;
  s.q3 = half ? sortedMedian(v, v.size() - half, v.size()) : s.median;
  return s;
}

bool overlaps(const Spread& a, const Spread& b) { return a.min <= b.max && b.min <= a.max; }

nlohmann::json toJson(const Spread& s, bool measured) {
  auto value = [&](double v) { return measured ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"median", s.median}, {"min", value(s.min)}, {"max", value(s.max)}, {"q1", value(s.q1)}, {"q3", value(s.q3)}};
}

std::string csvNumber(std::optional<double> value) {
  if (!value) return "";
  std::ostringstream text;
  text << *value;
  return text.str();
}

std::string csvText(std::string text) {
  std::replace(text.begin(), text.end(), '"', '\'');
  return "\"" + text + "\"";
}

std::string screenNumber(std::optional<double> value, int decimals) {
  if (!value) return "n/a";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, *value);
  return text;
}

}  // namespace raylab
