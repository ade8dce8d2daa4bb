// fit_sequence end to end: a target in its own frame and units (scaled by 50 and moved), a
// perturbed skeleton; the written result must match the target, re-evaluate from the written
// sequence.json, and be rebuilt by real Blender from rebuild_blender.py. Bad input: one line,
// exit code 2, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "core/metrics.h"
#include "core/obj_io.h"
#include "core/surface_distance.h"
#include "ops/sequence.h"
#include "tests/run_command.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

std::string Quote(const std::string& s) { return "'" + s + "'"; }

const char* kTruth = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [30, 40, 90]}},
  {"op": "LoopCut", "params": {"axis": "Z", "cuts": 4, "near": [30, 40, 0]}},
  {"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 1}, "height": 40, "width": 0.6}},
  {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 60}},
  {"op": "GlobalAffineTranslate", "params": {"offset": [500, -200, 1000]}}]})";

const char* kInit = R"({"operations": [
  {"op": "GlobalAffineScale", "params": {"scale": [25, 48, 75]}},
  {"op": "LoopCut", "params": {"axis": "Z", "cuts": 4, "near": [30, 40, 0]}},
  {"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 1}, "height": 30, "width": 0.75}},
  {"op": "SimpleDeformTwist", "params": {"axis": "Z", "angle_deg": 45}},
  {"op": "GlobalAffineTranslate", "params": {"offset": [480, -180, 1010]}}]})";

TEST(FitSequence, FitsInTheInputFrameAndBlenderRebuildsIt) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_fit_sequence_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Sequence truth = ParseSequence(Json::parse(kTruth));
  const Mesh target = EvaluateSequence(&truth).back();
  WriteObj(target, (dir / "target.obj").string());
  std::ofstream(dir / "init.json") << kInit;
  const fs::path out = dir / "out";
  ASSERT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + Quote((dir / "target.obj").string()) + " --init " +
                Quote((dir / "init.json").string()) + " --out " + Quote(out.string()) + " --seed 3 > " +
                Quote((dir / "log.txt").string())),
            0);
  for (const char* name : {"sequence.json", "result.obj", "rebuild_blender.py", "metrics.json"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  const Mesh result = ReadObj((out / "result.obj").string());
  EXPECT_LT(SymmetricSurfaceDistanceRelative(target, result), 1e-6);

  std::ifstream metrics_file(out / "metrics.json");
  const Json metrics = Json::parse(metrics_file);
  EXPECT_LT(metrics["shape"]["chamfer"]["sum"].get<double>(), 1e-6);
  EXPECT_LT(metrics["fit"]["final_loss"].get<double>(), 1e-3 * metrics["fit"]["initial_loss"].get<double>());
  // The unit box: the target's longest side is its height, 2 x 90 + 40 (before the twist).
  EXPECT_NEAR(metrics["frame"]["scale"].get<double>(), 1.0 / 220, 1e-12);

  Sequence fitted = LoadSequence((out / "sequence.json").string());
  const Mesh again = EvaluateSequence(&fitted).back();
  EXPECT_LT(SymmetricSurfaceDistanceRelative(result, again), 1e-6);

  const fs::path blender_obj = dir / "blender.obj";
  ASSERT_EQ(RunCommand("blender -b --factory-startup --python-exit-code 1 -P " + Quote((out / "rebuild_blender.py").string()) +
                " -- " + Quote(blender_obj.string()) + " > " + Quote((dir / "blender.log").string()) + " 2>&1"),
            0);
  const Mesh rebuilt = ReadObj(blender_obj.string());
  const double distance = SymmetricSurfaceDistanceRelative(result, rebuilt);
  std::printf("[fit_sequence] Blender rebuild distance %.2e (relative), %d vs %d vertices\n", distance,
              rebuilt.NumVertices(), result.NumVertices());
  EXPECT_LT(distance, 1e-6);
  EXPECT_EQ(rebuilt.NumVertices(), result.NumVertices());
  fs::remove_all(dir);
}

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The default budget is in work, so a seed gives the same bytes on one thread, on two, and on
// two while another process keeps both cores busy.
TEST(FitSequence, SameOutputForAnyThreadCountAndLoad) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_fit_sequence_threads";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Sequence truth = ParseSequence(Json::parse(R"({"operations": [
      {"op": "GlobalAffineScale", "params": {"scale": [2, 2, 0.5]}},
      {"op": "Extrude", "params": {"faces": {"normal": [0, 0, 1], "expect": 1}, "height": 0.8, "width": 0.5}},
      {"op": "GlobalAffineTranslate", "params": {"offset": [3, 0, 1]}}]})"));
  WriteObj(EvaluateSequence(&truth).back(), (dir / "target.obj").string());
  auto run = [&](const std::string& name, int threads) {
    const fs::path out = dir / name;
    EXPECT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + Quote((dir / "target.obj").string()) +
                         " --out " + Quote(out.string()) + " --threads " + std::to_string(threads) + " --quiet > /dev/null"),
              0);
    return ReadBytes(out / "sequence.json") + ReadBytes(out / "result.obj");
  };
  const std::string one_thread = run("one", 1);
  const std::string two_threads = run("two", 2);
  // Two busy loops beside the run, ended by their process group.
  const fs::path pid_file = dir / "load.pid";
  ASSERT_EQ(RunCommand("setsid sh -c 'sh -c \"while :; do :; done\" & sh -c \"while :; do :; done\" & wait' "
                       "> /dev/null 2>&1 & echo $! > " + Quote(pid_file.string())),
            0);
  const std::string loaded = run("loaded", 2);
  const std::string pid = ReadBytes(pid_file);
  RunCommand("kill -- -" + pid.substr(0, pid.find_first_of("\n")) + " 2> /dev/null");
  ASSERT_GT(one_thread.size(), 100u);
  EXPECT_TRUE(one_thread == two_threads) << "--threads 1 and --threads 2 differ";
  EXPECT_TRUE(one_thread == loaded) << "a loaded machine changed the result";
  const Json metrics = Json::parse(std::ifstream(dir / "loaded" / "metrics.json"));
  EXPECT_NE(metrics["fit"]["ended_by"], "time budget");
  fs::remove_all(dir);
}

// CGAL orders its Boolean results partly by address, so the same search once differed between
// two processes whose heaps were laid out differently (on this CSG part: four layouts, four
// sequences). GLIBC_TUNABLES moves the heap; the outputs must not move with it.
TEST(FitSequence, SameOutputForAnyHeapLayout) {
  const fs::path dir = FreshDir("opgraph_fit_sequence_heap");
  // synth_007 of the synthetic corpus (make_synth's model.obj): a block with a prism added and
  // an eight-sided hole.
  const fs::path target = fs::path(OPGRAPH_SOURCE_DIR) / "tests" / "data" / "determinism" / "csg_part.obj";
  auto run = [&](const std::string& name, const std::string& tunables) {
    const fs::path out = dir / name;
    EXPECT_EQ(RunCommand("GLIBC_TUNABLES=" + tunables + " " + std::string(OPGRAPH_FIT_SEQUENCE) + " --input " +
                         Quote(target.string()) + " --out " + Quote(out.string()) +
                         " --work-budget 35000 --no-freeform --threads 1 --quiet > /dev/null"),
              0);
    return ReadBytes(out / "sequence.json") + ReadBytes(out / "result.obj");
  };
  const std::string plain = run("plain", "");
  const std::string moved = run("moved", "glibc.malloc.tcache_count=0");
  ASSERT_GT(plain.size(), 100u);
  EXPECT_TRUE(plain == moved) << "the heap's layout changed the result";
  fs::remove_all(dir);
}

// --time-budget is a promise (issue 15): the finishing fits are cut and the optional steps
// skipped, so the whole process, outputs written, ends within 10% or 2 s of the cap, here on a
// model whose search alone takes longer under a large work budget. A limit check, not a speed
// benchmark: it holds on a loaded machine too (the fits' deadlines are wall time).
TEST(FitSequence, TimeBudgetBoundsTheWholeRun) {
  const fs::path dir = FreshDir("opgraph_time_budget");
  fs::path input = fs::path(OPGRAPH_SOURCE_DIR) / ".." / "shared" / "data" / "gt-dev" / "house" / "model.obj";
  if (!fs::exists(input)) input = fs::path(OPGRAPH_SOURCE_DIR) / "examples" / "barrel.obj";
  constexpr double kBudget = 5;
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + Quote(input.string()) + " --out " +
                       Quote((dir / "out").string()) + " --time-budget 5 --work-budget 1000000000 --quiet > /dev/null"),
            0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[time budget] " << input.filename() << ": " << seconds << " s for --time-budget " << kBudget << "\n";
  EXPECT_LE(seconds, kBudget + std::max(0.1 * kBudget, 2.0));
  const Json metrics = Json::parse(std::ifstream(dir / "out" / "metrics.json"));
  EXPECT_EQ(metrics["fit"]["ended_by"], "time budget");
  EXPECT_TRUE(metrics["fit"]["cut_by_time_budget"].is_array());
  fs::remove_all(dir);
}

// An --out that cannot take the outputs is refused before any work; a rerun replaces the folder
// whole (no stale step of the earlier run), and a failed run leaves it as it was.
TEST(OutputFolder, RefusedBeforeWorkOrReplacedWhole) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_output_folder";
  fs::remove_all(dir);
  fs::create_directories(dir / "users_folder");
  std::ofstream(dir / "users_folder" / "notes.txt") << "keep me";
  std::ofstream(dir / "users_folder" / "sequence.json") << kTruth;  // theirs, beside their notes
  std::ofstream(dir / "a_file") << "keep me";
  std::ofstream(dir / "truth.json") << kTruth;
  std::ofstream(dir / "broken.json") << R"({"operations": [{"op": "Extrude"}]})";
  const std::string apply = std::string(OPGRAPH_APPLY_SEQUENCE) + " ";
  const std::string fit = std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + Quote((dir / "truth.json").string()) + " ";
  for (const char* taken : {"a_file", "users_folder"}) {
    const std::string out = Quote((dir / taken).string());
    EXPECT_EQ(RunCommand(apply + Quote((dir / "truth.json").string()) + " --out " + out + " > /dev/null 2>&1"), 2) << taken;
    // fit_sequence refuses before reading its input (here not even a mesh).
    EXPECT_EQ(RunCommand(fit + "--out " + out + " > /dev/null 2>&1"), 2) << taken;
  }
  EXPECT_EQ(ReadBytes(dir / "a_file"), "keep me");
  EXPECT_EQ(ReadBytes(dir / "users_folder" / "notes.txt"), "keep me");
  EXPECT_EQ(ReadBytes(dir / "users_folder" / "sequence.json"), kTruth);

  const fs::path run = dir / "run";
  ASSERT_EQ(RunCommand(apply + Quote((dir / "truth.json").string()) + " --out " + Quote(run.string()) + " > /dev/null"), 0);
  std::ofstream(run / "steps" / "09_Stale.obj") << "from an earlier run";
  const std::string first = ReadBytes(run / "result.obj");
  // A bad sequence fails and leaves the folder as it was.
  EXPECT_EQ(RunCommand(apply + Quote((dir / "broken.json").string()) + " --out " + Quote(run.string()) + " 2> /dev/null"), 2);
  EXPECT_TRUE(fs::exists(run / "steps" / "09_Stale.obj"));
  // A rerun replaces it whole.
  ASSERT_EQ(RunCommand(apply + Quote((dir / "truth.json").string()) + " --out " + Quote(run.string()) + " > /dev/null"), 0);
  EXPECT_FALSE(fs::exists(run / "steps" / "09_Stale.obj"));
  EXPECT_EQ(ReadBytes(run / "result.obj"), first);
  std::set<std::string> entries;
  for (const auto& entry : fs::directory_iterator(dir)) entries.insert(entry.path().filename().string());
  EXPECT_EQ(entries, (std::set<std::string>{"a_file", "broken.json", "run", "truth.json", "users_folder"}))
      << "a staging or old folder was left beside the output";
  fs::remove_all(dir);
}

TEST(FitSequence, BadInputFailsWithOneLineAndWritesNothing) {
  const fs::path dir = fs::temp_directory_path() / "opgraph_fit_sequence_bad";
  fs::remove_all(dir);
  fs::create_directories(dir);
  WriteObj(MakeCube(2.0), (dir / "cube.obj").string());
  std::ofstream(dir / "init.json") << kInit;
  std::ofstream(dir / "broken.json") << R"({"operations": [{"op": "Extrude", "params": {"height": "x"}}]})";
  std::ofstream(dir / "empty.obj") << "";
  std::ofstream(dir / "garbage.stl") << "\x01\x02 not a mesh";
  const std::string cube = Quote((dir / "cube.obj").string()), init = Quote((dir / "init.json").string());
  const struct {
    std::string args, expected;
  } cases[] = {
      {"--input " + cube + " --init " + Quote((dir / "missing.json").string()), "cannot open"},
      {"--input " + cube + " --init " + Quote((dir / "broken.json").string()), "operation 0 (Extrude)"},
      {"--input " + Quote((dir / "empty.obj").string()) + " --init " + init, "empty"},
      {"--input " + cube + " --init " + init + " --optimizer sgd", "--optimizer"},
      {"--input " + cube + " --init " + init + " --seed x", "--seed"},
      {"--init " + init, "usage"},
      {"--input " + Quote((dir / "garbage.stl").string()), "cannot read mesh"},
      {"--input " + Quote((dir / "missing.ply").string()), "cannot open file"},
      {"--input " + cube + " --time-budget 86401", "--time-budget"},
      {"--input " + cube + " --work-budget 12x", "--work-budget"},
      {"--input " + cube + " --threads 0", "--threads"},
  };
  for (const auto& c : cases) {
    ExpectRefused(std::string(OPGRAPH_FIT_SEQUENCE) + " " + c.args + " --out " + Quote((dir / "out").string()), dir / "out",
                  c.expected);
  }
  fs::remove_all(dir);
}

// A file name that is not UTF-8 (bytes a filesystem allows) still gives every output: JSON
// needs UTF-8, so the name is written with the odd byte replaced.
TEST(FitSequence, FileNameThatIsNotUtf8) {
  const fs::path dir = FreshDir("opgraph_odd_name");
  const fs::path input = dir / "bar\xffrel.obj";
  fs::copy_file(fs::path(OPGRAPH_SOURCE_DIR) / "examples" / "barrel.obj", input);
  EXPECT_EQ(QuickFit(input, dir / "out", 500), 0);
  const Json sequence = Json::parse(std::ifstream(dir / "out" / "sequence.json"));
  EXPECT_EQ(sequence["name"], "bar_rel");
  EXPECT_TRUE(fs::exists(dir / "out" / "report.html"));
  fs::remove_all(dir);
}

// A flat sheet (one quad, zero thickness) is a fine input: the box keeps a sliver of thickness
// instead of collapsing to edges Blender could not rebuild.
TEST(FitSequence, AFlatSheetIsAFineInput) {
  const fs::path dir = FreshDir("opgraph_flat_sheet");
  std::ofstream(dir / "sheet.obj") << "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4\n";
  EXPECT_EQ(QuickFit(dir / "sheet.obj", dir / "out", 3000), 0);
  const Json metrics = Json::parse(std::ifstream(dir / "out" / "metrics.json"));
  EXPECT_LT(metrics["shape"]["chamfer"]["sum"].get<double>(), 0.005);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
