// report.html: a visual step report of a run, one self-contained page (inline SVG renderings,
// no scripts or files fetched at view time).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "ops/params.h"

namespace opgraph {

struct ReportInput {
  std::string title;                    // the input's name
  std::vector<Mesh> steps;              // the mesh after each op (as Blender shows it)
  std::vector<std::string> step_names;  // "NN_<op>"
  Json operations;                      // sequence.json's "operations" (parameters per card)
  Mesh result;
  Positions<double> target_points;      // samples of the target, drawn ghosted behind each step
  Json metrics;                         // metrics.json
  // The view's world (+Z up) from the meshes' frame, e.g. Blender's importer axes for the input.
  Eigen::Matrix3d view_from_input = Eigen::Matrix3d::Identity();
};

// The page. Each step card shows the op, its parameters and a flat-shaded rendering of the mesh
// after it over the target's samples; the top shows the metrics and the result beside the target.
std::string ReportHtml(const ReportInput& input);

}  // namespace opgraph
