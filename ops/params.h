// Reading and writing operation parameters: validation with errors that name the field, and
// Python literals for the Blender export that can only ever be numbers or whitelisted words.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

using Json = nlohmann::json;

// A problem with one field of one operation's parameters; the sequence loader adds the
// operation's index and name.
class FieldError : public std::runtime_error {
 public:
  FieldError(const std::string& field, const std::string& message)
      : std::runtime_error(message), field_(field) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// A complete one-line error about a sequence ("operation 2 (Extrude): field 'height': ...").
class SequenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Typed, validated access to an operation's "params" object. Unknown keys are rejected when
// Finish() is called, so a typo never silently falls back to a default.
class ParamReader {
 public:
  explicit ParamReader(const Json& params);

  bool Has(const std::string& key) const;
  double Number(const std::string& key, double lower, double upper);
  double Number(const std::string& key, double lower, double upper, double fallback);
  int Integer(const std::string& key, int lower, int upper);
  int Integer(const std::string& key, int lower, int upper, int fallback);
  bool Bool(const std::string& key, bool fallback);
  Vec3d Vector3(const std::string& key, double lower, double upper);
  Vec3d Vector3(const std::string& key, double lower, double upper, const Vec3d& fallback);
  // One of `allowed` (case-sensitive).
  std::string Word(const std::string& key, const std::vector<std::string>& allowed);
  std::string Word(const std::string& key, const std::vector<std::string>& allowed,
                   const std::string& fallback);
  const Json& Object(const std::string& key);
  // Raw access for nested structures parsed elsewhere; marks the key as used.
  const Json& Raw(const std::string& key);
  void Finish() const;  // throws on keys that were never read

 private:
  const Json& Get(const std::string& key);
  const Json& params_;
  std::vector<std::string> used_;
};

// Checks a JSON number (finite, in range) at `field`.
double CheckedNumber(const Json& value, const std::string& field, double lower, double upper);
// Checks a JSON integer (written without a fraction: 1.7 is refused, not truncated) in range.
int CheckedInteger(const Json& value, const std::string& field, int lower, int upper);
Vec3d CheckedVector3(const Json& value, const std::string& field, double lower, double upper);

// Python literal of a finite double (round-trips exactly). Throws on NaN/inf.
std::string Py(double value);
std::string PyVec(const Vec3d& v);
std::string PyBool(bool value);
// A word already validated against a whitelist, quoted for Python.
std::string PyWord(const std::string& word);

constexpr double kPi = 3.14159265358979323846;
inline double DegToRad(double deg) { return deg * kPi / 180.0; }
inline double RadToDeg(double rad) { return rad * 180.0 / kPi; }

Json ToJson(const Vec3d& v);

// A non-empty JSON list of non-negative integers at `field`.
std::vector<int> CheckedIndices(const Json& value, const std::string& field);

// Throws FieldError(field) when `count` is 0 or differs from `expect` (< 0: any count).
// `noun` names the elements ("faces", "vertices").
void CheckSelectionCount(size_t count, int expect, const std::string& field, const std::string& noun);

// params[key] when params is an object holding it, else null (for members parsed in an
// initialiser list before the ParamReader runs; the reader then reports a missing key).
inline const Json& MemberOrNull(const Json& params, const char* key) {
  static const Json kNull;
  return params.is_object() && params.contains(key) ? params[key] : kNull;
}

}  // namespace opgraph
