#include "core/obj_io.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace opgraph {

Mesh ReadObj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open file");
  Mesh mesh;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    std::istringstream ss(line);
    std::string tag;
    if (!(ss >> tag)) continue;
    if (tag == "v") {
      double x, y, z;
      if (!(ss >> x >> y >> z)) {
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": malformed vertex");
      }
      if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": non-finite vertex");
      }
      mesh.vertices.emplace_back(x, y, z);
    } else if (tag == "f") {
      Polygon face;
      std::string token;
      while (ss >> token) {
        int index = 0;
        try {
          index = std::stoi(token.substr(0, token.find('/')));
        } catch (const std::exception&) {
          throw std::runtime_error(path + ":" + std::to_string(line_number) + ": malformed face");
        }
        face.push_back(index > 0 ? index - 1 : mesh.NumVertices() + index);
      }
      mesh.faces.push_back(face);
    }
  }
  if (mesh.vertices.empty() || mesh.faces.empty()) {
    throw std::runtime_error(path + ": no mesh (no vertices or no faces)");
  }
  const std::string problem = mesh.Validate();
  if (!problem.empty()) throw std::runtime_error(path + ": " + problem);
  return mesh;
}

void WriteFileAtomic(const std::string& path, const std::string& contents) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot write file");
    out << contents;
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error(path + ": write failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename temporary file: " + ec.message());
  }
}

void WriteObj(const Mesh& mesh, const std::string& path, const std::string& comment) {
  std::ostringstream out;
  out.precision(17);
  if (!comment.empty()) out << "# " << comment << "\n";
  for (const Vec3d& v : mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const Polygon& f : mesh.faces) {
    out << "f";
    for (int v : f) out << " " << v + 1;
    out << "\n";
  }
  WriteFileAtomic(path, out.str());
}

}  // namespace opgraph
