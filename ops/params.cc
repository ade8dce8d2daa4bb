#include "ops/params.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "core/printable.h"

namespace opgraph {

namespace {
std::string RangeText(double lower, double upper) {
  std::ostringstream s;
  s << "[" << lower << ", " << upper << "]";
  return s.str();
}
}  // namespace

ParamReader::ParamReader(const Json& params) : params_(params) {
  if (!params_.is_object()) throw FieldError("params", "must be an object");
}

bool ParamReader::Has(const std::string& key) const {
  return params_.contains(key) && !params_.at(key).is_null();
}

const Json& ParamReader::Get(const std::string& key) {
  if (!params_.contains(key)) throw FieldError(key, "missing");
  used_.push_back(key);
  return params_.at(key);
}

double CheckedNumber(const Json& value, const std::string& field, double lower, double upper) {
  if (!value.is_number()) throw FieldError(field, "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw FieldError(field, "must be finite");
  if (x < lower || x > upper) {
    std::ostringstream s;
    s << "value " << x << " out of range " << RangeText(lower, upper);
    throw FieldError(field, s.str());
  }
  return x;
}

Vec3d CheckedVector3(const Json& value, const std::string& field, double lower, double upper) {
  if (!value.is_array() || value.size() != 3) throw FieldError(field, "must be an array of 3 numbers");
  Vec3d v;
  for (int i = 0; i < 3; ++i) {
    v[i] = CheckedNumber(value[i], field + "[" + std::to_string(i) + "]", lower, upper);
  }
  return v;
}

double ParamReader::Number(const std::string& key, double lower, double upper) {
  return CheckedNumber(Get(key), key, lower, upper);
}

double ParamReader::Number(const std::string& key, double lower, double upper, double fallback) {
  if (!params_.contains(key)) return fallback;
  return Number(key, lower, upper);
}

int ParamReader::Integer(const std::string& key, int lower, int upper) { return CheckedInteger(Get(key), key, lower, upper); }

int CheckedInteger(const Json& value, const std::string& field, int lower, int upper) {
  if (!value.is_number_integer()) throw FieldError(field, "must be an integer");
  // Unsigned values above the signed range are out of range too (not wrapped).
  const bool huge = value.is_number_unsigned() && value.get<unsigned long long>() > static_cast<unsigned long long>(upper);
  const long long x = huge ? static_cast<long long>(upper) + 1 : value.get<long long>();
  if (x < lower || x > upper) {
    throw FieldError(field, "value " + (huge ? value.dump() : std::to_string(x)) + " out of range " + "[" +
                                std::to_string(lower) + ", " + std::to_string(upper) + "]");
  }
  return static_cast<int>(x);
}

int ParamReader::Integer(const std::string& key, int lower, int upper, int fallback) {
  if (!params_.contains(key)) return fallback;
  return Integer(key, lower, upper);
}

bool ParamReader::Bool(const std::string& key, bool fallback) {
  if (!params_.contains(key)) return fallback;
  const Json& v = Get(key);
  if (!v.is_boolean()) throw FieldError(key, "must be true or false");
  return v.get<bool>();
}

Vec3d ParamReader::Vector3(const std::string& key, double lower, double upper) {
  return CheckedVector3(Get(key), key, lower, upper);
}

Vec3d ParamReader::Vector3(const std::string& key, double lower, double upper,
                           const Vec3d& fallback) {
  if (!params_.contains(key)) return fallback;
  return Vector3(key, lower, upper);
}

std::string ParamReader::Word(const std::string& key, const std::vector<std::string>& allowed) {
  const Json& v = Get(key);
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  if (!v.is_string()) throw FieldError(key, "must be one of " + list);
  const std::string word = v.get<std::string>();
  if (std::find(allowed.begin(), allowed.end(), word) == allowed.end()) {
    throw FieldError(key, "'" + word.substr(0, 40) + "' is not one of " + list);
  }
  return word;
}

std::string ParamReader::Word(const std::string& key, const std::vector<std::string>& allowed,
                              const std::string& fallback) {
  if (!params_.contains(key)) return fallback;
  return Word(key, allowed);
}

const Json& ParamReader::Object(const std::string& key) {
  const Json& v = Get(key);
  if (!v.is_object()) throw FieldError(key, "must be an object");
  return v;
}

const Json& ParamReader::Raw(const std::string& key) { return Get(key); }

void ParamReader::Finish() const {
  for (auto it = params_.begin(); it != params_.end(); ++it) {
    if (std::find(used_.begin(), used_.end(), it.key()) == used_.end()) {
      throw FieldError(Printable(it.key()), "unknown parameter");
    }
  }
}

std::string Py(double value) {
  if (!std::isfinite(value)) throw std::runtime_error("non-finite value in Blender export");
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.17g", value);
  std::string s(buf);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string PyVec(const Vec3d& v) { return "(" + Py(v.x()) + ", " + Py(v.y()) + ", " + Py(v.z()) + ")"; }

std::string PyBool(bool value) { return value ? "True" : "False"; }

std::string PyWord(const std::string& word) {
  for (char c : word) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) throw std::runtime_error("refusing to export a non-identifier word to Python");
  }
  return "'" + word + "'";
}

std::vector<int> CheckedIndices(const Json& value, const std::string& field) {
  if (!value.is_array() || value.empty()) throw FieldError(field, "must be a non-empty list of indices");
  std::vector<int> indices;
  for (const Json& i : value) {
    if (!i.is_number_integer()) throw FieldError(field, "entries must be integers");
    indices.push_back(CheckedInteger(i, field, 0, 1000000000));
  }
  // A repeated index would select its element twice (a face extruded twice over).
  std::vector<int> sorted = indices;
  std::sort(sorted.begin(), sorted.end());
  if (const auto repeat = std::adjacent_find(sorted.begin(), sorted.end()); repeat != sorted.end()) {
    throw FieldError(field, "index " + std::to_string(*repeat) + " is listed twice");
  }
  return indices;
}

void CheckSelectionCount(size_t count, int expect, const std::string& field, const std::string& noun) {
  if (count == 0) throw FieldError(field, "selects no " + noun + " at this step");
  if (expect >= 0 && static_cast<int>(count) != expect) {
    throw FieldError(field, "selects " + std::to_string(count) + " " + noun + ", expected " + std::to_string(expect));
  }
}

Json ToJson(const Vec3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

}  // namespace opgraph
