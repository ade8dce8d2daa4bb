// Operation engine tests: Jet derivatives against central finite differences, the gate's
// identity at 0, Blender parity (real Blender replays rebuild_blender.py), Blender-built
// gt-dev references, and bad-input handling of apply_sequence.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <sys/wait.h>

#include "core/geometry.h"
#include "core/obj_io.h"
#include "core/surface_distance.h"
#include "ops/blender_script.h"
#include "ops/sequence.h"
#include "tests/blender_runner.h"
#include "tests/gt_convert.h"
#include "tests/run_command.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> ParityCases() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(std::string(OPGRAPH_SOURCE_DIR) + "/tests/data/parity")) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string ParityPath(const std::string& name) {
  return std::string(OPGRAPH_SOURCE_DIR) + "/tests/data/parity/" + name + ".json";
}

// Inputs of every op of a sequence (the start mesh, then each step's result).
std::vector<Mesh> OpInputs(Sequence* sequence) {
  std::vector<Mesh> inputs = {sequence->StartMesh()};
  std::vector<Mesh> steps = EvaluateSequence(sequence);
  inputs.insert(inputs.end(), steps.begin(), steps.end() - (steps.empty() ? 0 : 1));
  return inputs;
}

class ParityCase : public ::testing::TestWithParam<std::string> {};

// Jet derivatives of the output positions with respect to every continuous parameter and the
// gate agree with central differences, at random parameters near the sequence's and on
// randomly perturbed inputs.
TEST_P(ParityCase, JetDerivativesMatchFiniteDifferences) {
  Sequence sequence = LoadSequence(ParityPath(GetParam()));
  const std::vector<Mesh> inputs = OpInputs(&sequence);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (size_t i = 0; i < sequence.ops.size(); ++i) {
    Op& op = *sequence.ops[i];
    op.Prepare(inputs[i]);
    const int n = static_cast<int>(op.params().size()) + 1;  // parameters, then the gate
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<double> x(n);
      for (int k = 0; k + 1 < n; ++k) {
        const ParamSpec& s = op.specs()[k];
        x[k] = std::clamp(op.params()[k] * (1 + 0.1 * unit(rng)) + 0.05 * unit(rng), s.lower, s.upper);
      }
      x[n - 1] = 0.6 + 0.3 * unit(rng);
      Positions<double> input = inputs[i].vertices;
      for (Vec3d& v : input) v += 1e-3 * Vec3d(unit(rng), unit(rng), unit(rng));

      auto eval = [&](const std::vector<double>& xs) {
        Positions<double> out;
        op.Evaluate(xs.data(), xs[n - 1], input, &out);
        return out;
      };
      const Positions<JetT> input_jet = CastPositions<JetT>(input);
      for (int start = 0; start < n; start += kJetDim) {
        std::vector<JetT> xj(n);
        for (int k = 0; k < n; ++k) {
          xj[k] = JetT(x[k]);
          if (k >= start && k < start + kJetDim) xj[k].v[k - start] = 1;
        }
        Positions<JetT> out_jet;
        op.Evaluate(xj.data(), xj[n - 1], input_jet, &out_jet);
        for (int k = start; k < std::min(n, start + kJetDim); ++k) {
          const double h = 1e-6 * std::max(1.0, std::abs(x[k]));
          std::vector<double> xp = x, xm = x;
          xp[k] += h;
          xm[k] -= h;
          const Positions<double> op_plus = eval(xp), op_minus = eval(xm);
          double diff = 0, norm = 0;
          for (size_t v = 0; v < out_jet.size(); ++v) {
            for (int c = 0; c < 3; ++c) {
              const double fd = (op_plus[v][c] - op_minus[v][c]) / (2 * h);
              const double jet = out_jet[v][c].v[k - start];
              diff += (fd - jet) * (fd - jet);
              norm += jet * jet;
            }
          }
          const std::string name = k + 1 < n ? op.specs()[k].name : "gate";
          EXPECT_LT(std::sqrt(diff), 1e-5 * std::max(std::sqrt(norm), 1e-3))
              << "op " << i << " " << op.Name() << " parameter " << name << " trial " << trial;
        }
      }
    }
  }
}

// Largest distance of a polygon's vertices from the plane through its centroid with its
// Newell normal: how far its bilinear surface can depart from its fan triangulation.
double MaxNonPlanarity(const Mesh& mesh) {
  double worst = 0;
  for (const Polygon& f : mesh.faces) {
    const Vec3d n = FaceAreaNormal(mesh.vertices, f).normalized();
    const Vec3d c = FaceCentroid(mesh.vertices, f);
    for (int v : f) worst = std::max(worst, std::abs(n.dot(mesh.vertices[v] - c)));
  }
  return worst;
}

// Gate 0 reproduces the op's input surface exactly (in the op's output topology). The one
// surface-definition caveat: Subdivision at gate 0 is the bilinear (midpoint) refinement, which
// lies on each quad's bilinear patch; for non-planar quads that departs from the fan
// triangulation the distance is measured on by at most the quad's non-planarity.
TEST_P(ParityCase, GateZeroIsIdentity) {
  Sequence sequence = LoadSequence(ParityPath(GetParam()));
  const std::vector<Mesh> inputs = OpInputs(&sequence);
  for (size_t i = 0; i < sequence.ops.size(); ++i) {
    Op& op = *sequence.ops[i];
    op.Prepare(inputs[i]);
    Mesh out;
    op.Evaluate(op.params().data(), 0.0, inputs[i].vertices, &out.vertices);
    out.faces = op.OutputFaces(0.0);
    const double tolerance =
        1e-12 + (op.Name() == "Subdivision" ? MaxNonPlanarity(inputs[i]) / BoundingBoxDiagonal(inputs[i]) : 0);
    EXPECT_LT(SymmetricSurfaceDistanceRelative(inputs[i], out), tolerance) << "op " << i << " " << op.Name();
  }
}



// Real Blender replaying our rebuild_blender.py builds the mesh we computed.
TEST_P(ParityCase, BlenderRebuildMatches) {
  const fs::path dir = fs::temp_directory_path() / ("opgraph_parity_" + GetParam());
  fs::remove_all(dir);
  const std::string command = std::string(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote(ParityPath(GetParam())) +
                              " --out " + ShellQuote(dir.string()) + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Mesh ours = ReadObj((dir / "result.obj").string());
  const Mesh blender = RunBlender((dir / "rebuild_blender.py").string(), (dir / "blender.obj").string());
  const double distance = SymmetricSurfaceDistanceRelative(blender, ours);
  std::cout << "[parity] " << GetParam() << ": relative distance " << distance << ", vertices "
            << ours.NumVertices() << " vs " << blender.NumVertices() << ", faces " << ours.NumFaces() << " vs "
            << blender.NumFaces() << "\n";
  EXPECT_LT(distance, 1e-6);
  EXPECT_EQ(ours.NumVertices(), blender.NumVertices());
  EXPECT_EQ(ours.NumFaces(), blender.NumFaces());
  // The modifiers that no mesh edit follows stay live on the rebuilt object, in order.
  Sequence sequence = LoadSequence(ParityPath(GetParam()));
  EXPECT_EQ(ExportedModifiers((dir / "blender.obj").string()), LiveModifierNames(sequence));
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Sequences, ParityCase, ::testing::ValuesIn(ParityCases()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// Every implemented op is exercised by at least one parity sequence (and so by the derivative,
// gate and Blender tests above).
TEST(ParityCoverage, EveryOpHasAParitySequence) {
  std::set<std::string> covered;
  for (const std::string& name : ParityCases()) {
    Sequence sequence = LoadSequence(ParityPath(name));
    for (const auto& op : sequence.ops) covered.insert(op->Name());
  }
  for (const std::string& name : OpNames()) EXPECT_TRUE(covered.count(name)) << name << " has no parity sequence";
  EXPECT_GE(ParityCases().size(), 40u);
}

// The Blender-built references of ../shared/data/gt-dev evaluate to their model.obj.
TEST(GtDev, SequencesReproduceBlenderModels) {
  const fs::path root = fs::path(OPGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "gt-dev";
  ASSERT_TRUE(fs::exists(root)) << root;
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    std::string why_not;
    const Json converted = ConvertGtSequence(entry.path() / "sequence.json", &why_not);
    if (!why_not.empty()) {
      std::cout << "[gt-dev] " << name << ": not compared: " << why_not << "\n";
      continue;
    }
    Sequence sequence = ParseSequence(converted);
    const std::vector<Mesh> steps = EvaluateSequence(&sequence);
    const Mesh reference = ReadObj((entry.path() / "model.obj").string());
    const Mesh& ours = steps.back();
    const double distance = SymmetricSurfaceDistanceRelative(reference, ours);
    std::cout << "[gt-dev] " << name << ": relative distance " << distance << ", vertices "
              << ours.NumVertices() << " vs " << reference.NumVertices() << "\n";
    EXPECT_LT(distance, 1e-6) << name;
    EXPECT_EQ(ours.NumVertices(), reference.NumVertices()) << name;
    EXPECT_EQ(ours.NumFaces(), reference.NumFaces()) << name;
    ++checked;
  }
  std::cout << "[gt-dev] compared " << checked << " models\n";
}

// Boolean needs a closed, consistently oriented input (no sequence can build an open one, so the
// op is called directly on a cube without its top face).
TEST(Boolean, RejectsOpenInput) {
  Mesh open = MakeCube(2.0);
  open.faces.pop_back();
  std::unique_ptr<Op> op =
      CreateOp("Boolean", Json::parse(R"({"operation": "UNION", "primitive": "cube", "size": [1, 1, 1]})"));
  try {
    op->Prepare(open);
    FAIL() << "no error for an open input";
  } catch (const FieldError& e) {
    EXPECT_EQ(e.field(), "operation");
    EXPECT_NE(std::string(e.what()).find("not a closed"), std::string::npos) << e.what();
  }
}

// --max-ops bounds the step files apply_sequence writes.
TEST(ApplySequence, RefusesMoreOpsThanMaxOps) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_max_ops";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "seq.json") << R"({"operations": [
      {"op": "GlobalAffineScale", "params": {"scale": [1, 2, 1]}},
      {"op": "GlobalAffineScale", "params": {"scale": [1, 1, 2]}},
      {"op": "GlobalAffineScale", "params": {"scale": [2, 1, 1]}}]})";
  const std::string apply = std::string(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote((dir / "seq.json").string()) +
                            " --out " + ShellQuote((dir / "out").string());
  const int refused = std::system((apply + " --max-ops 2 2> " + ShellQuote((dir / "err.txt").string())).c_str());
  ASSERT_TRUE(WIFEXITED(refused));
  EXPECT_EQ(WEXITSTATUS(refused), 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
  std::string line;
  std::getline(std::ifstream(dir / "err.txt"), line);
  EXPECT_NE(line.find("3 operations, above --max-ops 2"), std::string::npos) << line;
  EXPECT_EQ(std::system((apply + " --max-ops 3 > /dev/null").c_str()), 0);
  fs::remove_all(dir);
}

// Bad input: one line naming the problem, exit code 2, nothing written.
struct BadInput {
  const char* name;
  const char* text;
  const char* expected;  // substring of the error line
};

void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.name; }

class BadSequence : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadSequence, FailsWithOneLineAndWritesNothing) {
  const BadInput& bad = GetParam();
  const fs::path dir = fs::temp_directory_path() / (std::string("opgraph_bad_") + bad.name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path seq = dir / "seq.json";
  if (std::string(bad.name) != "missing_file") std::ofstream(seq) << bad.text;
  const fs::path out = dir / "out";
  const fs::path err = dir / "stderr.txt";
  const std::string command = std::string(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote(seq.string()) + " --out " +
                              ShellQuote(out.string()) + " 2> " + ShellQuote(err.string());
  long peak_rss_kb = 0;
  EXPECT_EQ(RunCommand(command, &peak_rss_kb), 2);
  EXPECT_LT(peak_rss_kb, kMaxRefusalRssKb) << "refused only after taking " << peak_rss_kb << " kB";
  EXPECT_FALSE(fs::exists(out));
  std::ifstream in(err);
  std::string line, extra;
  std::getline(in, line);
  EXPECT_FALSE(std::getline(in, extra)) << "more than one line: " << extra;
  EXPECT_NE(line.find(bad.expected), std::string::npos) << line;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Errors, BadSequence,
    ::testing::Values(
        BadInput{"missing_file", "", "cannot open file"},
        BadInput{"twenty_subdivisions", R"({"operations": [{"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}, {"op": "Subdivision", "params": {"levels": 1}}]})",
                 "operation 9 (Subdivision): output too large: would make 6291456 faces, above --max-faces 2000000"},
        BadInput{"cuts_then_subdivision_6",
                 R"({"operations": [{"op": "LoopCut", "params": {"axis": "X", "cuts": 64, "near": [0, 0, 0]}},
                                    {"op": "LoopCut", "params": {"axis": "Y", "cuts": 64, "near": [0, 0, 0]}},
                                    {"op": "LoopCut", "params": {"axis": "Z", "cuts": 64, "near": [0, 0, 0]}},
                                    {"op": "Subdivision", "params": {"levels": 6}}]})",
                 "operation 3 (Subdivision): output too large: would make"},
        BadInput{"unknown_top_level", R"({"operations": [], "operatoins": []})", "sequence: field 'operatoins': unknown field"},
        BadInput{"huge_version", R"({"version": 4294967297, "operations": []})", "sequence: field 'version': unsupported"},
        BadInput{"other_format", R"({"format": "obj", "operations": []})", "sequence: field 'format'"},
        BadInput{"fractional_expect",
                 R"({"operations": [{"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 1.7}, "height": 1}}]})",
                 "operation 0 (Extrude): field 'faces.expect': must be an integer"},
        BadInput{"repeated_index",
                 R"({"operations": [{"op": "Extrude", "params": {"faces": {"indices": [0, 0, 0]}, "height": 1}}]})",
                 "operation 0 (Extrude): field 'faces.indices': index 0 is listed twice"},
        BadInput{"unknown_group_key",
                 R"({"operations": [{"op": "VertexDisplace", "params": {"groups": [{"verts": {"indices": [0]}, "offset": [0, 0, 1], "ofset": 1}]}}]})",
                 "operation 0 (VertexDisplace): field 'groups[0].ofset': unknown key"},
        BadInput{"escaped_op_name", "{\"operations\": [{\"op\": \"Ex\\u001b[31mtrude\\nX\"}]}",
                 "operation 0 (Ex?[31mtrude?X): field 'op': unknown op 'Ex?[31mtrude?X'"},
        BadInput{"empty_file", "", "invalid JSON"},
        BadInput{"invalid_json", "{\"operations\": [", "invalid JSON"},
        BadInput{"not_object", "[1, 2]", "top level must be a JSON object"},
        BadInput{"unknown_op", R"({"operations": [{"op": "Explode", "params": {}}]})",
                 "operation 0 (Explode): field 'op': unknown op"},
        BadInput{"missing_param", R"({"operations": [{"op": "GlobalAffineScale", "params": {}}]})",
                 "operation 0 (GlobalAffineScale): field 'scale': missing"},
        BadInput{"out_of_range",
                 R"({"operations": [{"op": "GlobalAffineTranslate", "params": {"offset": [0, 0, 0]}},
                                    {"op": "GlobalAffineScale", "params": {"scale": [1, 0, 1]}}]})",
                 "operation 1 (GlobalAffineScale): field 'scale[1]': must not be zero"},
        BadInput{"infinite", R"({"operations": [{"op": "GlobalAffineTranslate", "params": {"offset": [1e999, 0, 0]}}]})",
                 "seq.json: invalid JSON: number overflow"},
        BadInput{"wrong_type", R"({"operations": [{"op": "GlobalAffineRotate", "params": {"rotation_deg": "import os"}}]})",
                 "operation 0 (GlobalAffineRotate): field 'rotation_deg': must be an array of 3 numbers"},
        BadInput{"unknown_param", R"({"operations": [{"op": "GlobalAffineTranslate", "params": {"offset": [0, 0, 0], "code": "x"}}]})",
                 "operation 0 (GlobalAffineTranslate): field 'code': unknown parameter"},
        BadInput{"missing_target",
                 R"({"operations": [{"op": "GlobalAffineScale", "params": {"scale": [1, 1, 1]}},
                                    {"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 2}, "height": 1}}]})",
                 "operation 1 (Extrude): field 'faces': selects 1 faces, expected 2"},
        BadInput{"missing_vertex",
                 R"({"operations": [{"op": "VertexDisplace", "params": {"groups": [{"verts": {"indices": [8]}, "offset": [0, 0, 1]}]}}]})",
                 "operation 0 (VertexDisplace): field 'groups[0].verts': vertex 8 does not exist at this step"},
        BadInput{"knife_zero_normal", R"({"operations": [{"op": "KnifeCut", "params": {"plane_co": [0, 0, 0], "plane_no": [0, 0, 0]}}]})",
                 "operation 0 (KnifeCut): field 'plane_no': must not be zero"},
        // A cutter tilted 0.5 degrees off the top face, crossing it: ill-conditioned in float32.
        BadInput{"boolean_grazing", R"({"operations": [{"op": "Boolean", "params": {"operation": "DIFFERENCE", "primitive": "cube", "size": [1, 1, 1], "rotation_deg": [0.5, 0, 0], "location": [0, 0, 1.5]}}]})",
                 "operation 0 (Boolean): field 'operation': the primitive crosses the mesh at a grazing angle (0.35 degrees): the intersection is ill-conditioned"},
        // A cutter through a side of a twisted cube: Blender splits that non-planar quad along the
        // diagonal its loop start gives, which the engine cannot know.
        BadInput{"boolean_non_planar", R"({"operations": [{"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 40}},
                                                         {"op": "Boolean", "params": {"operation": "DIFFERENCE", "primitive": "cube", "size": [1, 1, 1], "location": [1, 0, 0]}}]})",
                 "operation 1 (Boolean): field 'operation': the primitive cuts a non-planar face (off its plane by 8.3e-02 of the diagonal)"},
        BadInput{"bad_word", R"({"operations": [{"op": "SimpleDeformTwist", "params": {"axis": "W'); import os; ('", "angle_deg": 10}}]})",
                 "operation 0 (SimpleDeformTwist): field 'axis': 'W'); import os; ('' is not one of X, Y, Z"},
        BadInput{"boolean_primitive",
                 R"({"operations": [{"op": "Boolean", "params": {"operation": "UNION", "primitive": "sphere", "size": [1, 1, 1]}}]})",
                 "operation 0 (Boolean): field 'primitive': 'sphere' is not one of cube, prism6, prism8, cylinder"},
        BadInput{"boolean_size",
                 R"({"operations": [{"op": "Boolean", "params": {"operation": "DIFFERENCE", "primitive": "cube", "size": [1, 0, 1]}}]})",
                 "operation 0 (Boolean): field 'size[1]': value 0 out of range"},
        BadInput{"bevel_segments_0", R"({"operations": [{"op": "Bevel", "params": {"width": 0.1, "segments": 0}}]})",
                 "operation 0 (Bevel): field 'segments': value 0 out of range"},
        BadInput{"bevel_segments_10", R"({"operations": [{"op": "Bevel", "params": {"width": 0.1, "segments": 10}}]})",
                 "operation 0 (Bevel): field 'segments': value 10 out of range"},
        BadInput{"bevel_negative_width", R"({"operations": [{"op": "Bevel", "params": {"width": -0.1, "segments": 2}}]})",
                 "operation 0 (Bevel): field 'width'"},
        BadInput{"bad_gate", R"({"operations": [{"op": "GlobalAffineTranslate", "params": {"offset": [0, 0, 0]}, "gate": 2}]})",
                 "operation 0 (GlobalAffineTranslate): field 'gate'"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace opgraph
