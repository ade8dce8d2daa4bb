// run_results as a user runs it: with more than one thread a model, a model's Blender replay
// runs beside the next model's fit; the rows must be the serial run's, each with its own
// model's replay.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ops/params.h"
#include "tests/blender_runner.h"
#include "tests/run_command.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

// A gt-dev folder of `data` with a model built by apply_sequence from `sequence` (its truth).
void AddModel(const fs::path& data, const std::string& name, const fs::path& sequence) {
  const fs::path dir = data / "gt-dev" / name, built = data / (name + "_built");
  ASSERT_EQ(RunCommand(ShellQuote(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote(sequence.string()) + " --out " +
                       ShellQuote(built.string()) + " > /dev/null"),
            0);
  fs::create_directories(dir);
  fs::copy_file(built / "result.obj", dir / "model.obj");
  fs::copy_file(sequence, dir / "sequence.json");
}

// The record's rows by model, without the wall times.
std::map<std::string, Json> Rows(const fs::path& records) {
  std::map<std::string, Json> rows;
  const Json record = Json::parse(std::ifstream(records / "gt-dev.json"));
  for (Json row : record.at("rows")) {
    row.erase("seconds");
    rows[row.at("name")] = row;
  }
  return rows;
}

TEST(RunResults, ReplaysBesideTheNextFitGiveTheSerialRunsRows) {
  const fs::path dir = FreshDir("opgraph_run_results"), data = dir / "data";
  const fs::path examples = fs::path(OPGRAPH_SOURCE_DIR) / "examples";
  AddModel(data, "vase", examples / "twisted_vase.json");
  AddModel(data, "vase_start", examples / "twisted_vase_init.json");
  auto run = [&](int threads) {
    const fs::path out = dir / ("threads" + std::to_string(threads));
    const std::string command = ShellQuote(OPGRAPH_RUN_RESULTS) + " --set gt-dev --data " + ShellQuote(data.string()) +
                                " --jobs 1 --threads " + std::to_string(threads) + " --work_budget 20000 --out " +
                                ShellQuote((out / "fits").string()) + " --records " +
                                ShellQuote((out / "records").string()) + " --doc " +
                                ShellQuote((out / "results.md").string()) + " > " + ShellQuote((out.string() + ".log"));
    fs::create_directories(out);
    EXPECT_EQ(RunCommand(command), 0) << ReadText(out.string() + ".log");
    return Rows(out / "records");
  };
  const std::map<std::string, Json> serial = run(1), overlapped = run(2);
  ASSERT_EQ(serial.size(), 2u);
  EXPECT_EQ(overlapped, serial);
  for (const auto& [name, row] : overlapped) {
    EXPECT_TRUE(row.at("ok").get<bool>()) << name;
    EXPECT_TRUE(row.at("replay_counts_equal").get<bool>()) << name;
    EXPECT_GE(row.at("replay_distance").get<double>(), 0) << name;
    EXPECT_LT(row.at("replay_distance").get<double>(), 1e-6) << name;
  }
}

}  // namespace
}  // namespace opgraph
