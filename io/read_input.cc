#include "io/read_input.h"

#include "core/obj_io.h"
#include "io/read_in_child_process.h"
#include "io/read_point_cloud.h"
#include "io/ply_header.h"

#include <assimp/DefaultLogger.hpp>
#include <memory>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>

namespace opgraph {
namespace {

namespace fs = std::filesystem;

std::string Lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

[[noreturn]] void Fail(const std::string& path, const std::string& message) {
  throw std::runtime_error(path + ": " + message);
}

// Welds vertices at exactly equal positions (parts of an OBJ or glTF scene that share corners
// arrive as separate meshes) and drops faces that collapse below 3 distinct vertices.
Mesh WeldExactDuplicates(const Mesh& mesh) {
  std::map<std::tuple<double, double, double>, int> index_of_position;
  std::vector<int> remap(mesh.vertices.size());
  Mesh welded;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3d& p = mesh.vertices[v];
    const auto [it, inserted] = index_of_position.emplace(std::make_tuple(p.x(), p.y(), p.z()), welded.NumVertices());
    if (inserted) welded.vertices.push_back(p);
    remap[v] = it->second;
  }
  for (const Polygon& face : mesh.faces) {
    Polygon loop;
    for (int v : face) {
      if (loop.empty() || loop.back() != remap[v]) loop.push_back(remap[v]);
    }
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    if (loop.size() >= 3) welded.faces.push_back(loop);
  }
  return welded;
}

// Collects the errors Assimp logs: some loaders repair corrupt data (an OFF face index out of
// range is clamped) and only log it, and a repaired corrupt file must not pass as valid.
class AssimpErrorCollector : public Assimp::LogStream {
 public:
  void write(const char* message) override {
    if (first_error_.empty()) first_error_ = message;
  }
  std::string first_error() const {
    std::string text = first_error_;
    text.erase(std::remove(text.begin(), text.end(), '\n'), text.end());
    // Drop the logger's "Error, T0: " prefix.
    if (text.rfind("Error, ", 0) == 0 && text.find(": ") != std::string::npos) text = text.substr(text.find(": ") + 2);
    return text;
  }

 private:
  std::string first_error_;
};

// The file's meshes through Assimp (run in the child process of ReadWithAssimp); `errors`
// holds what Assimp logged.
InputGeometry ImportWithAssimp(const std::string& path, const AssimpErrorCollector& errors) {
  Assimp::Importer importer;
  // Points and lines are kept (a PLY without faces is a point cloud, which Assimp's own
  // validation step would reject; CheckGeometry validates instead); node transforms are baked so
  // parts land where the file places them.
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  if (scene == nullptr) Fail(path, std::string("cannot read mesh: ") + importer.GetErrorString());
  if (!errors.first_error().empty()) Fail(path, "corrupt mesh: " + errors.first_error());
  // Parts are concatenated; only vertices used by a face are kept (stray points and line ends
  // carry no surface).
  Mesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* part = scene->mMeshes[m];
    std::vector<int> index_in_mesh(part->mNumVertices, -1);
    for (unsigned f = 0; f < part->mNumFaces; ++f) {
      const aiFace& face = part->mFaces[f];
      if (face.mNumIndices < 3) continue;
      Polygon loop;
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        const unsigned v = face.mIndices[k];
        if (v >= part->mNumVertices) Fail(path, "face refers to a missing vertex");
        if (index_in_mesh[v] < 0) {
          index_in_mesh[v] = mesh.NumVertices();
          mesh.vertices.emplace_back(part->mVertices[v].x, part->mVertices[v].y, part->mVertices[v].z);
        }
        loop.push_back(index_in_mesh[v]);
      }
      mesh.faces.push_back(std::move(loop));
    }
  }
  if (mesh.faces.empty()) Fail(path, "no faces (for a point cloud use PLY, PCD or XYZ)");
  InputGeometry input;
  input.mesh = WeldExactDuplicates(mesh);
  return input;
}

InputGeometry ReadWithAssimp(const std::string& path) {
  // Assimp's logger is global: a host program's own logger is borrowed (our stream attached, then
  // detached), else one is made for the call and removed after it.
  static std::mutex logger_mutex;
  const std::lock_guard<std::mutex> lock(logger_mutex);
  const bool own_logger = Assimp::DefaultLogger::isNullLogger();
  if (own_logger) Assimp::DefaultLogger::create(nullptr, Assimp::Logger::NORMAL, 0);
  auto errors = std::make_unique<AssimpErrorCollector>();
  Assimp::DefaultLogger::get()->attachStream(errors.get(), Assimp::Logger::Err);
  struct RestoreLogger {
    AssimpErrorCollector* stream;
    bool own;
    ~RestoreLogger() {
      Assimp::DefaultLogger::get()->detachStream(stream, Assimp::Logger::Err);  // ownership returns to us
      if (own) Assimp::DefaultLogger::kill();
    }
  } restore_logger{errors.get(), own_logger};
  // Assimp crashes on some malformed files: it reads in a child process (the logger above, set
  // up here, is the child's copy there).
  return ReadInChildProcess(path, [&path, &errors] { return ImportWithAssimp(path, *errors); });
}

constexpr double kMaxCoordinate = 1e12;

void CheckGeometry(const std::string& path, InputGeometry* input) {
  const Positions<double>& vertices = input->mesh.vertices;
  if (vertices.empty()) Fail(path, "no vertices");
  for (size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices[v].allFinite()) Fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate");
    // Beyond this, double precision keeps under 1e-4 of a unit of detail and float32 Blender
    // none: a stray huge coordinate would shrink the rest of the model to a point.
    if (vertices[v].cwiseAbs().maxCoeff() > kMaxCoordinate) {
      Fail(path, "vertex " + std::to_string(v) + " has a coordinate beyond 1e12 in magnitude");
    }
  }
  Vec3d lo = vertices[0], hi = vertices[0];
  for (const Vec3d& p : vertices) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!((hi - lo).maxCoeff() > 0)) Fail(path, "all vertices are at one point (zero extent)");
  const std::string problem = input->mesh.Validate();
  if (!problem.empty()) Fail(path, problem);
  // Unusable file normals are replaced by estimates rather than trusted.
  for (Vec3d& n : input->normals) {
    if (!n.allFinite() || n.norm() < 1e-12) {
      input->normals.clear();
      break;
    }
    n.normalize();
  }
}

}  // namespace

InputGeometry ReadInput(const std::string& path) {
  // PCL warns on stderr about absent optional fields (normals); errors are ours to report. The
  // host program's level is restored on return.
  const QuietPcl quiet_pcl;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) Fail(path, "cannot open file (missing or not a file)");
  if (fs::file_size(path, error) == 0) Fail(path, "file is empty");
  const std::string extension = Lowercase(fs::path(path).extension().string());
  InputGeometry input;
  if (extension == ".pcd") {
    input = ReadPcdPoints(path);
  } else if (extension == ".xyz" || extension == ".pts" || extension == ".txt") {
    input = ReadXyzPoints(path);
  } else if (extension == ".obj") {
    // Our own reader: it keeps one vertex list across groups and rejects non-finite numbers,
    // which Assimp's OBJ loader silently drops.
    input.mesh = ReadObj(path);
  } else if (extension == ".ply" && !CheckPlyFile(path).HasFaces()) {
    input = ReadPlyPoints(path);
  } else {
    Assimp::Importer probe;
    if (!probe.IsExtensionSupported(extension)) Fail(path, "unsupported file type '" + extension + "'");
    input = ReadWithAssimp(path);
  }
  CheckGeometry(path, &input);
  return input;
}

}  // namespace opgraph
