#include "solver/target.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "core/metrics.h"
#include "core/obj_io.h"

namespace opgraph {

std::string TargetOptions::Check() const {
  if (num_samples < 100 || num_samples > 10000000) return "num_samples must be in [100, 1e7]";
  if (max_cloud_points < 100) return "max_cloud_points must be >= 100";
  if (normal_neighbours < 3 || normal_neighbours > 100) return "normal_neighbours must be in [3, 100]";
  return "";
}

namespace {

// Unit normals of a cloud from the smallest principal direction of each point's neighbourhood.
Positions<double> EstimateNormals(const Positions<double>& points, const PointTree& tree, int neighbours) {
  Positions<double> normals(points.size(), Vec3d::Zero());
  const int k = std::min<int>(neighbours, static_cast<int>(points.size()));
  std::vector<size_t> indices;
  std::vector<double> squared;
  for (size_t i = 0; i < points.size(); ++i) {
    tree.KNearest(points[i], k, &indices, &squared);
    Vec3d mean = Vec3d::Zero();
    for (size_t j : indices) mean += points[j];
    mean /= static_cast<double>(indices.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (size_t j : indices) covariance += (points[j] - mean) * (points[j] - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    normals[i] = solver.eigenvectors().col(0).normalized();
  }
  return normals;
}

std::string Extension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(c));
  return ext;
}

void ReadXyz(const std::string& path, Mesh* cloud, Positions<double>* normals) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open file");
  std::string line;
  int line_number = 0, columns = -1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    std::istringstream ss(line);
    std::vector<double> values;
    double v;
    while (ss >> v) values.push_back(v);
    if (!ss.eof() || (values.size() != 3 && values.size() != 6) || (columns >= 0 && int(values.size()) != columns)) {
      throw std::runtime_error(path + ":" + std::to_string(line_number) + ": expected 'x y z' or 'x y z nx ny nz'");
    }
    for (double x : values) {
      if (!std::isfinite(x)) throw std::runtime_error(path + ":" + std::to_string(line_number) + ": non-finite value");
    }
    columns = static_cast<int>(values.size());
    cloud->vertices.emplace_back(values[0], values[1], values[2]);
    if (columns == 6) {
      const Vec3d n(values[3], values[4], values[5]);
      normals->push_back(n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::Zero());
    }
  }
}

// ASCII PLY: the vertex element (x, y, z, optional nx, ny, nz) and an optional face element
// (a list property); other elements are skipped.
void ReadPly(const std::string& path, Mesh* mesh, Positions<double>* normals) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open file");
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) throw std::runtime_error(path + ": not a PLY file");
  struct Element {
    std::string name;
    long count;
    std::vector<std::string> properties;
  };
  std::vector<Element> elements;
  bool ascii = false;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string word;
    ss >> word;
    if (word == "format") {
      std::string format;
      ss >> format;
      ascii = format == "ascii";
    } else if (word == "element") {
      Element e;
      if (!(ss >> e.name >> e.count) || e.count < 0) throw std::runtime_error(path + ": malformed element line");
      elements.push_back(e);
    } else if (word == "property" && !elements.empty()) {
      std::string type, name;
      ss >> type;
      if (type == "list") ss >> type >> type;
      ss >> name;
      elements.back().properties.push_back(name);
    } else if (word == "end_header") {
      break;
    }
  }
  if (!ascii) throw std::runtime_error(path + ": only ASCII PLY is supported");
  for (const Element& e : elements) {
    auto column = [&](const std::string& name) {
      for (size_t i = 0; i < e.properties.size(); ++i) if (e.properties[i] == name) return static_cast<int>(i);
      return -1;
    };
    for (long r = 0; r < e.count; ++r) {
      if (!std::getline(in, line)) throw std::runtime_error(path + ": truncated " + e.name + " data");
      std::istringstream ss(line);
      if (e.name == "vertex") {
        std::vector<double> values;
        double v;
        while (ss >> v) values.push_back(v);
        const int x = column("x"), y = column("y"), z = column("z");
        const int nx = column("nx"), ny = column("ny"), nz = column("nz");
        if (x < 0 || y < 0 || z < 0 || values.size() < e.properties.size()) {
          throw std::runtime_error(path + ": malformed vertex " + std::to_string(r));
        }
        const Vec3d p(values[x], values[y], values[z]);
        if (!p.allFinite()) throw std::runtime_error(path + ": non-finite vertex " + std::to_string(r));
        mesh->vertices.push_back(p);
        if (nx >= 0 && ny >= 0 && nz >= 0) {
          const Vec3d n(values[nx], values[ny], values[nz]);
          normals->push_back(n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::Zero());
        }
      } else if (e.name == "face") {
        int k;
        Polygon face;
        if (!(ss >> k) || k < 3) throw std::runtime_error(path + ": malformed face " + std::to_string(r));
        face.resize(k);
        for (int& i : face) {
          if (!(ss >> i)) throw std::runtime_error(path + ": malformed face " + std::to_string(r));
        }
        mesh->faces.push_back(face);
      }
    }
  }
  if (!mesh->faces.empty()) normals->clear();
  const std::string problem = mesh->Validate();
  if (!problem.empty()) throw std::runtime_error(path + ": " + problem);
}

}  // namespace

Target::Target(Mesh shape, Positions<double> cloud_normals, const TargetOptions& options) : shape_(std::move(shape)) {
  UnitBoxTransform(shape_, &centre_, &scale_);
  if (!is_cloud()) {
    const std::vector<MeshTriangle> triangles = FanTriangulate(shape_.faces);
    const SurfaceSamples samples = SampleSurface(shape_.vertices, triangles, options.num_samples, options.seed);
    if (samples.points.empty()) throw std::runtime_error("target: the mesh has no surface area");
    points_ = samples.points;
    normals_ = samples.normals;
    tree_.reset(new PointTree(points_));
    return;
  }
  points_ = shape_.vertices;
  normals_ = cloud_normals;
  if (static_cast<int>(points_.size()) > options.max_cloud_points) {
    // Seeded subsample (partial Fisher-Yates on the indices).
    std::vector<int> order(points_.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::mt19937_64 rng(options.seed);
    for (int i = 0; i < options.max_cloud_points; ++i) std::swap(order[i], order[i + rng() % (order.size() - i)]);
    Positions<double> points, normals;
    for (int i = 0; i < options.max_cloud_points; ++i) {
      points.push_back(points_[order[i]]);
      if (!normals_.empty()) normals.push_back(normals_[order[i]]);
    }
    points_.swap(points);
    normals_.swap(normals);
  }
  tree_.reset(new PointTree(points_));
  if (normals_.size() != points_.size()) normals_ = EstimateNormals(points_, *tree_, options.normal_neighbours);
}

std::unique_ptr<Target> LoadTarget(const std::string& path, const TargetOptions& options) {
  const std::string problem = options.Check();
  if (!problem.empty()) throw std::runtime_error("target options: " + problem);
  const std::string ext = Extension(path);
  Mesh shape;
  Positions<double> normals;
  if (ext == "obj") {
    shape = ReadObj(path);
  } else if (ext == "xyz" || ext == "txt") {
    ReadXyz(path, &shape, &normals);
  } else if (ext == "ply") {
    ReadPly(path, &shape, &normals);
  } else {
    throw std::runtime_error(path + ": unknown target format (expected .obj, .ply, .xyz or .txt)");
  }
  if (shape.vertices.size() < 4) throw std::runtime_error(path + ": fewer than 4 points");
  Eigen::AlignedBox3d box;
  for (const Vec3d& v : shape.vertices) box.extend(v);
  if (!(box.sizes().maxCoeff() > 0)) throw std::runtime_error(path + ": all points coincide");
  return std::make_unique<Target>(std::move(shape), std::move(normals), options);
}

}  // namespace opgraph
