// How the settings table's rows are made (renderer/settings/settings_table.cpp): field(&Settings::m, "flag") gives a
// row for one member whose parsing, text, JSON, CSV, comparison and check follow from the member's type
// (uint32_t, float, bool, std::string or a settings enum); the calls after it say the rest:
//   field(&Settings::learnEvery, "learn-every").range(1, 64).json("learn_every", keepDefault).csv("learn_every")
//       .effects(kEffectSortCosts).help("N", "length caches learn ..., {range} (default {default})").sample("4")
// Rows of several members (size, grid, clamp, heatmap range) are written out in settings_table_rows.cpp.
// Only for those two files.
#pragma once

#include <cmath>
#include <cstdio>
#include <sstream>

#include "renderer/settings/settings_table.h"

namespace raylab::setting_rows {

using nlohmann::json;

// What a sidecar without the key held: an error (older sidecars all have it), the default, or a value.
enum class Absent { Required, KeepDefault, Value };
inline constexpr Absent required = Absent::Required;
inline constexpr Absent keepDefault = Absent::KeepDefault;

std::string floatText(float v);              // the shortest text that reads back the same float
std::string joined(const std::vector<std::string>& names, const std::string& sep, const std::string& last);
double jsonNumber(const std::string& key, const json& v);  // throws SettingsError for a non-number
const json& jsonAt(const json& j, const std::string& key);  // throws SettingsError "missing 'key'"

template <class E>
std::vector<std::string> enumNames() {
  std::vector<std::string> names;
  for (E e : allValues<E>()) names.push_back(toString(e));
  return names;
}

// The type-specific part of a row for one member of type T.
template <class T>
struct Codec;

template <>
struct Codec<uint32_t> {
  static uint32_t parse(const SettingRow& r, const std::string& t) { return uintFromText(r.range(), t); }
  static std::string text(uint32_t v) { return std::to_string(v); }
  static json write(uint32_t v) { return v; }
  static uint32_t read(const SettingRow& r, const std::string& key, const json& v) {
    double d = jsonNumber(key, v);
    checkUint(r.range(), d, formatNumber(d));
    return static_cast<uint32_t>(d);
  }
  static void check(const SettingRow& r, uint32_t v) { checkUint(r.range(), v, std::to_string(v)); }
};

template <>
struct Codec<float> {
  static float parse(const SettingRow& r, const std::string& t) { return floatFromText(r.range(), t); }
  static std::string text(float v) { return floatText(v); }
  static json write(float v) { return v; }
  static float read(const SettingRow& r, const std::string& key, const json& v) {
    double d = jsonNumber(key, v);
    checkFloat(r.range(), d, formatNumber(d));
    return static_cast<float>(d);
  }
  static void check(const SettingRow& r, float v) { checkFloat(r.range(), v, formatNumber(v)); }
};

template <>
struct Codec<bool> {  // a switch: the command line gives no value, `set` and the overlay give on or off
  static bool parse(const SettingRow&, const std::string& t) { return t == "on"; }
  static std::string text(bool v) { return v ? "on" : "off"; }
  static json write(bool v) { return v; }
  static bool read(const SettingRow&, const std::string&, const json& v) { return v.get<bool>(); }
  static void check(const SettingRow&, bool) {}
};

template <>
struct Codec<std::string> {
  static std::string parse(const SettingRow&, const std::string& t) { return t; }
  static std::string text(const std::string& v) { return v; }
  static json write(const std::string& v) { return v; }
  static std::string read(const SettingRow&, const std::string&, const json& v) { return v.get<std::string>(); }
  static void check(const SettingRow&, const std::string&) {}
};

template <class E>
struct EnumCodec {
  static E parse(const SettingRow& r, const std::string& t) {
    for (E e : allValues<E>())
      if (toString(e) == t) return e;
    throw SettingsError(r.dashed + " must be one of " + joined(enumNames<E>(), "|", "|") + ", got '" + t + "'");
  }
  static std::string text(E v) { return toString(v); }
  static json write(E v) { return toString(v); }
  static E read(const SettingRow& r, const std::string& key, const json& v) {
    const std::string name = v.get<std::string>();
    for (E e : allValues<E>())
      if (toString(e) == name) return e;
    if (!r.jsonError.empty()) throw SettingsError("settings: " + r.jsonError);
    throw SettingsError("settings: '" + key + "' must be " + joined(enumNames<E>(), ", ", " or ") + ", got " + v.dump());
  }
  static void check(const SettingRow&, E) {}
};
template <class T>
  requires std::is_enum_v<T>
struct Codec<T> : EnumCodec<T> {};

// A row under construction; converts to the SettingRow it describes.
template <class T>
class Field {
 public:
  Field(T Settings::*member, const char* flag, const char* memberName) : member_(member) {
    row_.flag = flag;
    row_.dashed = std::string("--") + flag;
    row_.members = {memberName};
  }
  Field& range(double lo, double hi) { return row_.lo = lo, row_.hi = hi, *this; }
  Field& json(const char* key, Absent absent = required, const char* absentValue = "") {
    row_.jsonKeys = {key};
    absent_ = absent, absentValue_ = absentValue;
    return *this;
  }
  // A sidecar without the key held `value` (the flag's text).
  Field& jsonAbsent(const char* key, const char* value) { return json(key, Absent::Value, value); }
  // A sidecar without the key: `rule` decides (it may read the others).
  Field& whenAbsent(std::function<void(const nlohmann::json&, Settings&)> rule) { return whenAbsent_ = rule, *this; }
  Field& jsonError(const char* message) { return row_.jsonError = message, *this; }
  Field& csv(const char* column, bool quoted = false) { return row_.csvColumns = {column}, quoted_ = quoted, *this; }
  Field& effects(unsigned e) { return row_.effects = e, *this; }
  Field& help(const char* hint, const char* text) { return row_.hint = hint, row_.help = text, *this; }
  Field& sample(const char* text) { return row_.sample = text, *this; }
  Field& axis(SettingAxis a) { return row_.axis = a, *this; }
  Field& infinity() { return infinity_ = true, *this; }  // floats: "inf" on the command line, null in JSON

  operator SettingRow() const {
    SettingRow r = row_;
    T Settings::*m = member_;
    const bool inf = infinity_;
    const std::string key = r.jsonKeys.empty() ? std::string() : r.jsonKeys.front();
    const Absent absent = absent_;
    const std::string absentValue = absentValue_;
    const auto whenAbsent = whenAbsent_;
    r.same = [m](const Settings& a, const Settings& b) { return a.*m == b.*m; };
    r.copy = [m](Settings& to, const Settings& from) { to.*m = from.*m; };
    r.text = [m, inf](const Settings& s) { return isInf(inf, s.*m) ? std::string("inf") : Codec<T>::text(s.*m); };
    r.parseFn = [m, inf](const SettingRow& self, Settings& s, const std::string& t) {
      if (inf && t == "inf") return setInf(s.*m);
      s.*m = Codec<T>::parse(self, t);
    };
    r.checkFn = [m, inf](const SettingRow& self, const Settings& s) {
      if (!isInf(inf, s.*m)) Codec<T>::check(self, s.*m);
    };
    r.write = [m, key, inf](const Settings& s, nlohmann::json& out) {
      out[key] = isInf(inf, s.*m) ? nlohmann::json(nullptr) : Codec<T>::write(s.*m);
    };
    r.readFn = [m, key, inf, absent, absentValue, whenAbsent](const SettingRow& self, const nlohmann::json& j,
                                                               Settings& s) {
      if (!j.contains(key)) {
        if (whenAbsent) return whenAbsent(j, s);
        if (absent == Absent::Required) throw SettingsError("settings: missing '" + key + "'");
        if (absent == Absent::Value) self.parse(s, absentValue);
        return;
      }
      const nlohmann::json& v = j.at(key);
      if (inf && v.is_null()) return setInf(s.*m);
      s.*m = Codec<T>::read(self, key, v);
    };
    const std::string column = r.csvColumns.empty() ? std::string() : r.csvColumns.front();
    const bool quoted = quoted_;
    r.csv = [m, column, quoted](const Settings& s, std::map<std::string, std::string>& out) {
      if (column.empty()) return;
      std::ostringstream text;  // as the CSV writes numbers: 6 significant digits
      if constexpr (std::is_arithmetic_v<T>) text << s.*m;
      else text << Codec<T>::text(s.*m);
      out[column] = quoted ? "\"" + text.str() + "\"" : text.str();
    };
    return r;
  }

 private:
  static bool isInf(bool inf, const T& v) {
    if constexpr (std::is_floating_point_v<T>) return inf && std::isinf(v) && v > 0;
    else return false;
  }
  static void setInf(T& v) {
    if constexpr (std::is_floating_point_v<T>) v = INFINITY;
  }

  SettingRow row_;
  T Settings::*member_;
  Absent absent_ = required;
  std::string absentValue_;
  std::function<void(const nlohmann::json&, Settings&)> whenAbsent_;
  bool quoted_ = false, infinity_ = false;
};

#define RAYLAB_FIELD(member, flag) ::raylab::setting_rows::Field(&Settings::member, flag, #member)

// The rows of several members (settings_table_rows.cpp), in the help's order among the others.
SettingRow sizeRow();
SettingRow gridRow();
SettingRow clampRow();
SettingRow heatmapRangeRow();

}  // namespace raylab::setting_rows
