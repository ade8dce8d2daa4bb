#include "apps/report_html.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/printable.h"

namespace opgraph {
namespace {

constexpr int kCardPixels = 260;
// Beyond this many front-facing polygons the smallest are left out (a Subdivision level 3
// result would make a page of many megabytes); their neighbours' outlines cover the gaps.
constexpr size_t kMaxDrawnFaces = 12000;
constexpr size_t kMaxGhostPoints = 2500;

// An orthographic view from the front right, a little above, as Blender's default 3-D view.
struct View {
  Eigen::Matrix3d view_from_input;
  Vec3d right, up, toward_viewer;
  Vec3d light;
  double scale = 1, x0 = 0, y0 = 0;

  View(const Eigen::Matrix3d& frame, const std::vector<const Positions<double>*>& extent) : view_from_input(frame) {
    const double azimuth = 35 * M_PI / 180, elevation = 25 * M_PI / 180;
    toward_viewer = Vec3d(std::sin(azimuth) * std::cos(elevation), -std::cos(azimuth) * std::cos(elevation),
                          std::sin(elevation));
    right = Vec3d::UnitZ().cross(toward_viewer).normalized();
    up = toward_viewer.cross(right);
    light = (toward_viewer + Vec3d(0.2, 0.1, 0.8)).normalized();
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const Positions<double>* points : extent) {
      for (const Vec3d& p : *points) {
        const Vec3d s = Screen(p);
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], s[k]), hi[k] = std::max(hi[k], s[k]);
      }
    }
    const double span = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-12});
    scale = 0.9 * kCardPixels / span;
    x0 = (lo[0] + hi[0]) / 2, y0 = (lo[1] + hi[1]) / 2;
  }
  // (x right, y up, depth toward the viewer), before fitting to the card.
  Vec3d Screen(const Vec3d& p) const {
    const Vec3d q = view_from_input * p;
    return Vec3d(q.dot(right), q.dot(up), q.dot(toward_viewer));
  }
  double PixelX(const Vec3d& screen) const { return kCardPixels / 2.0 + scale * (screen.x() - x0); }
  double PixelY(const Vec3d& screen) const { return kCardPixels / 2.0 - scale * (screen.y() - y0); }
};

std::string Number(double x) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", x);
  return text;
}

std::string GhostPoints(const View& view, const Positions<double>& points) {
  std::string svg = "<g fill=\"#b8b8b8\">";
  for (size_t i = 0; i < std::min(points.size(), kMaxGhostPoints); ++i) {
    const Vec3d s = view.Screen(points[i]);
    svg += "<circle cx=\"" + Number(view.PixelX(s)) + "\" cy=\"" + Number(view.PixelY(s)) + "\" r=\"0.9\"/>";
  }
  return svg + "</g>";
}

std::string ShadedMesh(const View& view, const Mesh& mesh) {
  struct Drawn {
    double depth, area;
    int face;
    double shade;
  };
  std::vector<Vec3d> screen(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) screen[v] = view.Screen(mesh.vertices[v]);
  std::vector<Drawn> drawn;
  for (int f = 0; f < mesh.NumFaces(); ++f) {
    const Polygon& polygon = mesh.faces[f];
    Vec3d normal = Vec3d::Zero(), centre = Vec3d::Zero();
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Vec3d& a = screen[polygon[i]];
      const Vec3d& b = screen[polygon[(i + 1) % polygon.size()]];
      normal += a.cross(b);
      centre += a;
    }
    if (normal.z() <= 0) continue;  // facing away (screen coordinates are right-handed)
    const double shade = 0.35 + 0.65 * std::max(0.0, normal.normalized().dot(Vec3d(0.2, 0.45, 0.87).normalized()));
    drawn.push_back({centre.z() / polygon.size(), normal.z(), f, shade});
  }
  if (drawn.size() > kMaxDrawnFaces) {
    std::nth_element(drawn.begin(), drawn.begin() + kMaxDrawnFaces, drawn.end(),
                     [](const Drawn& a, const Drawn& b) { return a.area > b.area; });
    drawn.resize(kMaxDrawnFaces);
  }
  std::sort(drawn.begin(), drawn.end(), [](const Drawn& a, const Drawn& b) { return a.depth < b.depth; });
  std::ostringstream svg;
  svg << "<g stroke-width=\"0.5\" stroke-linejoin=\"round\">";
  for (const Drawn& d : drawn) {
    char colour[32];
    std::snprintf(colour, sizeof(colour), "#%02x%02x%02x", static_cast<int>(80 * d.shade + 30),
                  static_cast<int>(130 * d.shade + 30), static_cast<int>(190 * d.shade + 40));
    svg << "<polygon fill=\"" << colour << "\" stroke=\"" << colour << "\" points=\"";
    for (int v : mesh.faces[d.face]) svg << Number(view.PixelX(screen[v])) << "," << Number(view.PixelY(screen[v])) << " ";
    svg << "\"/>";
  }
  svg << "</g>";
  return svg.str();
}

std::string Svg(const std::string& body) {
  const std::string size = std::to_string(kCardPixels);
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + size + "\" height=\"" + size + "\" viewBox=\"0 0 " +
         size + " " + size + "\">" + body + "</svg>";
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string MetricRow(const Json& metrics, const std::string& label, const Json::json_pointer& path) {
  std::string value = "-";
  if (metrics.contains(path)) value = metrics[path].is_string() ? metrics[path].get<std::string>() : metrics[path].dump();
  return "<tr><th>" + label + "</th><td>" + Escape(value) + "</td></tr>";
}

const char* kStyle = R"CSS(
body { font-family: sans-serif; margin: 24px; color: #222; }
.cards { display: flex; flex-wrap: wrap; gap: 16px; }
.card { border: 1px solid #ccc; border-radius: 6px; padding: 8px; width: 260px; }
.card h3 { margin: 0 0 6px 0; font-size: 15px; }
.card pre { font-size: 11px; white-space: pre-wrap; word-break: break-all; max-height: 140px; overflow: auto; }
table { border-collapse: collapse; margin-bottom: 16px; } th, td { text-align: left; padding: 2px 10px; }
)CSS";

}  // namespace

std::string ReportHtml(const ReportInput& input) {
  // One view for every card, holding every step, the result and the target.
  std::vector<const Positions<double>*> extent = {&input.result.vertices, &input.target_points};
  for (const Mesh& step : input.steps) extent.push_back(&step.vertices);
  const View view(input.view_from_input, extent);
  const std::string ghost = GhostPoints(view, input.target_points);
  std::ostringstream html;
  html << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>opgraph: "
       << Escape(Printable(input.title, 80)) << "</title><style>" << kStyle << "</style></head><body>\n";
  html << "<h1>opgraph: " << Escape(Printable(input.title, 80)) << "</h1>\n<table>"
       << MetricRow(input.metrics, "ops", Json::json_pointer("/ops"))
       << MetricRow(input.metrics, "Chamfer (unit box)", Json::json_pointer("/shape/chamfer/sum"))
       << MetricRow(input.metrics, "F1 at 0.01", Json::json_pointer("/shape/f1_0.01"))
       << MetricRow(input.metrics, "normal consistency", Json::json_pointer("/shape/normal_consistency"))
       << MetricRow(input.metrics, "seconds", Json::json_pointer("/fit/seconds"))
       << MetricRow(input.metrics, "ended by", Json::json_pointer("/fit/ended_by")) << "</table>\n";
  html << "<div class=\"cards\"><div class=\"card\" id=\"result\"><h3>result</h3>"
       << Svg(ShadedMesh(view, input.result)) << "</div><div class=\"card\" id=\"target\"><h3>target</h3>"
       << Svg(ghost) << "</div></div>\n<h2>Steps</h2>\n<div class=\"cards\">\n";
  for (size_t i = 0; i < input.steps.size(); ++i) {
    const std::string params =
        i < input.operations.size() && input.operations[i].contains("params") ? input.operations[i]["params"].dump(1) : "{}";
    html << "<div class=\"card step\"><h3>" << Escape(input.step_names[i]) << "</h3>"
         << Svg(ghost + ShadedMesh(view, input.steps[i])) << "<pre>" << Escape(params) << "</pre></div>\n";
  }
  html << "</div></body></html>\n";
  return html.str();
}

}  // namespace opgraph
