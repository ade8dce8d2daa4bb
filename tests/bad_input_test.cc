// The tools on inputs a careless or hostile user gives them (issue 15): each is refused with one
// line naming the file (and the op for sequences), exit code 2 and nothing written, before it
// costs 2 GB of memory (ExpectRefused measures the peak resident set of every refusal here).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "core/mesh.h"
#include "core/obj_io.h"
#include "tests/blender_runner.h"
#include "tests/run_command.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

void WriteText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string Subdivisions(int count, int levels) {
  std::string ops;
  for (int i = 0; i < count; ++i) {
    ops += std::string(i ? ", " : "") + R"({"op": "Subdivision", "params": {"levels": )" + std::to_string(levels) + "}}";
  }
  return R"({"operations": [)" + ops + "]}";
}

std::string Apply(const fs::path& sequence, const fs::path& out) {
  return std::string(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote(sequence.string()) + " --out " + ShellQuote(out.string());
}

// A cube (6 quads) subdivided 3 levels has 6 * 4 * 16 = 384 faces.
TEST(MaxFaces, AStepAboveTheLimitIsRefusedNamingTheOp) {
  const fs::path dir = FreshDir("opgraph_max_faces");
  WriteText(dir / "seq.json", R"({"operations": [
      {"op": "GlobalAffineScale", "params": {"scale": [1, 2, 1]}},
      {"op": "Subdivision", "params": {"levels": 2}},
      {"op": "Subdivision", "params": {"levels": 1}}]})");
  const std::string apply = Apply(dir / "seq.json", dir / "out");
  ExpectRefused(apply + " --max-faces 100", dir / "out",
                "seq.json: operation 2 (Subdivision): output too large: would make 384 faces, above --max-faces 100");
  EXPECT_EQ(RunCommand(apply + " --max-faces 384 > /dev/null"), 0);
  EXPECT_TRUE(fs::exists(dir / "out" / "result.obj"));

  // fit_sequence takes the limit to its --init sequence.
  WriteObj(MakeCube(2.0), (dir / "cube.obj").string());
  ExpectRefused(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote((dir / "cube.obj").string()) + " --init " +
                    ShellQuote((dir / "seq.json").string()) + " --max-faces 100 --out " +
                    ShellQuote((dir / "fit").string()),
                dir / "fit", "seq.json: operation 2 (Subdivision): output too large");
  for (const char* bad : {" --max-faces 0", " --max-faces 20000001"}) {
    ExpectRefused(apply + "_new" + bad, dir / "out_new", "apply_sequence: --max-faces: expected an integer in [1, 20000000]");
    ExpectRefused(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote((dir / "cube.obj").string()) +
                      " --out " + ShellQuote((dir / "fit").string()) + bad,
                  dir / "fit", "fit_sequence: --max-faces: expected an integer in [1, 20000000]");
  }
  fs::remove_all(dir);
}

// LoopCut's size depends on the ring it finds: it is checked once the ring is known, before the
// cut faces are built. A cube cut 64 times around X has 6 + 4 * 64 = 262 faces; the ring around
// Y then crosses the 65 strips of the top and of the bottom and the two side faces: 132 faces,
// each split into 65, so 262 + 132 * 64 = 8710.
TEST(MaxFaces, ALoopCutAboveTheLimitIsRefusedBeforeItBuildsItsFaces) {
  const fs::path dir = FreshDir("opgraph_max_faces_loop_cut");
  WriteText(dir / "seq.json", R"({"operations": [
      {"op": "LoopCut", "params": {"axis": "X", "cuts": 64}},
      {"op": "LoopCut", "params": {"axis": "Y", "cuts": 64}}]})");
  const std::string apply = Apply(dir / "seq.json", dir / "out");
  ExpectRefused(apply + " --max-faces 300", dir / "out",
                "seq.json: operation 1 (LoopCut): field 'cuts': would make 8710 faces, above the limit of 300");
  EXPECT_EQ(RunCommand(apply + " --max-faces 8710 > /dev/null"), 0);
  EXPECT_TRUE(fs::exists(dir / "out" / "result.obj"));
  fs::remove_all(dir);
}

// The search keeps to --max-faces too: a layout or free-form refinement above it is not fitted
// (the bundled example needs a few hundred faces; with 200 its free-form Subdivision would pass
// the limit, and with 6 only the posed cube fits).
TEST(MaxFaces, TheSearchKeepsItsResultWithinTheLimit) {
  const fs::path dir = FreshDir("opgraph_max_faces_search");
  const std::string input = std::string(OPGRAPH_SOURCE_DIR) + "/examples/barrel.obj";
  for (const int max_faces : {6, 200}) {
    const fs::path out = dir / ("out" + std::to_string(max_faces));
    ASSERT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote(input) + " --out " +
                         ShellQuote(out.string()) + " --time-budget 8 --max-faces " + std::to_string(max_faces) +
                         " > /dev/null 2>&1"),
              0);
    const Mesh result = ReadObj((out / "result.obj").string());
    EXPECT_GE(result.NumFaces(), 6);
    EXPECT_LE(result.NumFaces(), max_faces);
  }
  fs::remove_all(dir);
}

// 20 Subdivision(1) ops, each in range, grow 4x a step: the default limit stops them at the
// step that would pass 2,000,000 faces, at once and in little memory.
TEST(MaxFaces, AnUnboundedSequenceFailsFast) {
  const fs::path dir = FreshDir("opgraph_max_faces_unbounded");
  WriteText(dir / "seq.json", Subdivisions(20, 1));
  const auto start = std::chrono::steady_clock::now();
  ExpectRefused(Apply(dir / "seq.json", dir / "out"), dir / "out",
                "operation 9 (Subdivision): output too large: would make 6291456 faces, above --max-faces 2000000");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
  fs::remove_all(dir);
}

// Headers that declare more data than the file holds are refused before anything is allocated
// for it; files that are not what their name says, and coordinates beyond range, are refused too.
TEST(RefusedInputs, OneLineExitTwoNothingWrittenUnderTwoGigabytes) {
  const fs::path dir = FreshDir("opgraph_refused_inputs");
  const std::string kPcdXyz = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const struct {
    std::string name, contents, expected;
  } cases[] = {
      {"billion.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n\x01\x02\x03",
       "billion.ply: not a valid PLY file: element 'vertex' declares 1000000000"},
      {"billion_ascii.ply",
       "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\nproperty float z\n"
       "end_header\n0 0 0\n",
       "element 'vertex' declares 1000000000"},
      {"billion_faces.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1000000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "element 'face' declares 1000000000"},
      {"billion.pcd", kPcdXyz + "WIDTH 1000000000\nHEIGHT 1\nPOINTS 1000000000\nDATA binary\n",
       "billion.pcd: not a valid PCD file: WIDTH '1000000000' is not an integer in [1, 100000000]"},
      {"billion_by_height.pcd", kPcdXyz + "WIDTH 100000\nHEIGHT 10000\nPOINTS 1000000000\nDATA binary\n",
       "billion_by_height.pcd: not a valid PCD file"},
      {"eighty_million.pcd", kPcdXyz + "WIDTH 80000000\nHEIGHT 1\nPOINTS 80000000\nDATA binary\n\x01\x02",
       "need 960000000 bytes of data; the file has 2"},
      {"eighty_million_ascii.pcd", kPcdXyz + "WIDTH 80000000\nHEIGHT 1\nPOINTS 80000000\nDATA ascii\n1 2 3\n",
       "eighty_million_ascii.pcd: not a valid PCD file: POINTS 80000000"},
      {"hello.pcd", "hello\n", "'hello' is not a PCD header keyword"},
      {"noise.pcd", "\x89\x01\xff\x10\x1b[31m\x02\x03", "not a PCD header keyword"},
      {"huge.obj", "v 0 0 0\nv 1 0 0\nv 1e300 1 0\nf 1 2 3\n", "vertex 2 has a coordinate beyond 1e12"},
  };
  for (const auto& c : cases) {
    WriteText(dir / c.name, c.contents);
    ExpectRefused(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote((dir / c.name).string()) + " --out " +
                      ShellQuote((dir / "out").string()),
                  dir / "out", c.expected);
  }
  fs::remove_all(dir);
}

// A file name with a line break and a terminal escape still gives one line, the bytes shown as '?'.
TEST(RefusedInputs, ControlCharactersInANameAreEscaped) {
  const fs::path dir = FreshDir("opgraph_refused_names");
  const fs::path sequence = dir / "bad\n\x1b[31mname.json";
  WriteText(sequence, R"({"operations": [{"op": "Explode"}]})");
  ExpectRefused(Apply(sequence, dir / "out"), dir / "out",
                "bad??[31mname.json: operation 0 (Explode): field 'op': unknown op 'Explode'");
  ExpectRefused(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote((dir / "no\nsuch.obj").string()) +
                    " --out " + ShellQuote((dir / "out").string()),
                dir / "out", "no?such.obj: cannot open file");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
