// An axis-aligned box with optional bounds (null = open), as the selectors name regions:
// [[xmin, ymin, zmin], [xmax, ymax, zmax]].
#pragma once

#include <optional>
#include <string>

#include "core/mesh.h"
#include "ops/params.h"

namespace opgraph {

struct Box {
  std::optional<double> lo[3], hi[3];

  // Throws FieldError(field) on a malformed box.
  static Box Parse(const Json& json, const std::string& field) {
    if (!json.is_array() || json.size() != 2 || !json[0].is_array() || json[0].size() != 3 ||
        !json[1].is_array() || json[1].size() != 3) {
      throw FieldError(field, "must be [[xmin, ymin, zmin], [xmax, ymax, zmax]] (null = unbounded)");
    }
    Box box;
    for (int k = 0; k < 3; ++k) {
      if (!json[0][k].is_null()) box.lo[k] = CheckedNumber(json[0][k], field, -1e9, 1e9);
      if (!json[1][k].is_null()) box.hi[k] = CheckedNumber(json[1][k], field, -1e9, 1e9);
    }
    return box;
  }

  bool Bounded() const {
    for (int k = 0; k < 3; ++k) {
      if (lo[k] || hi[k]) return true;
    }
    return false;
  }

  bool Contains(const Vec3d& p) const {
    for (int k = 0; k < 3; ++k) {
      if ((lo[k] && p[k] < *lo[k]) || (hi[k] && p[k] > *hi[k])) return false;
    }
    return true;
  }

  Json ToJson() const {
    Json l = Json::array(), h = Json::array();
    for (int k = 0; k < 3; ++k) {
      l.push_back(lo[k] ? Json(*lo[k]) : Json(nullptr));
      h.push_back(hi[k] ? Json(*hi[k]) : Json(nullptr));
    }
    return {l, h};
  }

  // "(lo_x, lo_y, lo_z), (hi_x, hi_y, hi_z)" with None for open bounds.
  std::string PythonArgs() const {
    auto bound = [](const std::optional<double>& b) { return b ? Py(*b) : std::string("None"); };
    return "(" + bound(lo[0]) + ", " + bound(lo[1]) + ", " + bound(lo[2]) + "), (" + bound(hi[0]) + ", " +
           bound(hi[1]) + ", " + bound(hi[2]) + ")";
  }
};

}  // namespace opgraph
