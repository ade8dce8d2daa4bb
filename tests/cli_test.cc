// The tools' command lines, run as a user runs them (apps/cli_flags.h): --help lists the tool's
// flags with their defaults and exits 0 without work, --version prints the project's version,
// values follow '=' or a space, and a bad command line (unknown flag, missing value, stray
// argument) gives one line naming it, exit code 2, and nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/parallel_for.h"
#include "search/zero_shot.h"
#include "tests/blender_runner.h"
#include "tests/run_command.h"

namespace opgraph {
namespace {

namespace fs = std::filesystem;

struct ToolOutput {
  int exit_code = -1;
  std::string out, err;
};

// Runs `command` with its stdout and stderr kept.
ToolOutput RunTool(const std::string& command) {
  const std::string stem = (fs::temp_directory_path() / ("opgraph_cli_" + std::to_string(getpid()))).string();
  ToolOutput output;
  output.exit_code = RunCommand(command + " > " + ShellQuote(stem + ".out") + " 2> " + ShellQuote(stem + ".err"));
  output.out = ReadText(stem + ".out");
  output.err = ReadText(stem + ".err");
  fs::remove(stem + ".out");
  fs::remove(stem + ".err");
  return output;
}

// The default --help gives `flag`, from its line "  --flag (type, default VALUE)".
std::string DefaultIn(const std::string& help, const std::string& flag) {
  const size_t line = help.find("\n  " + flag + " (");
  if (line == std::string::npos) return "(not listed)";
  const size_t start = help.find(", default ", line) + std::string(", default ").size();
  return help.substr(start, help.find(")\n", start) - start);
}

const char* const kTools[] = {OPGRAPH_FIT_SEQUENCE,   OPGRAPH_APPLY_SEQUENCE, OPGRAPH_COMPARE_MESHES,
                              OPGRAPH_FIT_BENCHMARK, OPGRAPH_RUN_RESULTS,    OPGRAPH_MAKE_SYNTH};

TEST(CommandLine, EveryToolPrintsItsVersionAndHelpAndRefusesAnUnknownFlag) {
  for (const char* tool : kTools) {
    const std::string name = fs::path(tool).filename().string();
    const ToolOutput version = RunTool(ShellQuote(tool) + " --version");
    EXPECT_EQ(version.exit_code, 0) << name;
    EXPECT_EQ(version.out, name + " (opgraph) " + OPGRAPH_VERSION + "\n");
    const ToolOutput help = RunTool(ShellQuote(tool) + " --help");
    EXPECT_EQ(help.exit_code, 0) << name;
    EXPECT_EQ(help.out.rfind("usage: " + name, 0), 0u) << help.out;
    EXPECT_NE(help.out.find("--flagfile FILE"), std::string::npos) << help.out;
    EXPECT_EQ(help.err, "");
    const ToolOutput unknown = RunTool(ShellQuote(tool) + " --no-such-flag=1");
    EXPECT_EQ(unknown.exit_code, 2) << name;
    EXPECT_EQ(unknown.err, name + ": unknown flag '--no-such-flag' (see --help)\n");
  }
}

// Every flag fit_sequence has had keeps its name; the defaults shown are the options' own.
TEST(FitSequenceCommandLine, HelpListsEveryFlagWithItsDefaultAndDoesNoWork) {
  const fs::path dir = FreshDir("opgraph_cli_help");
  const ToolOutput help = RunTool(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote(OPGRAPH_SOURCE_DIR) +
                              "/examples/barrel.obj --out " + ShellQuote((dir / "out").string()) + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "out"));
  for (const char* flag : {"--input", "--out", "--init", "--work-budget", "--time-budget", "--max-ops", "--max-faces", "--seed",
                           "--threads", "--beam-width", "--op-price", "--optimizer", "--loss", "--fit-gates", "--samples", "--freeform",
                           "--blender-axes", "--quiet"}) {
    EXPECT_NE(DefaultIn(help.out, flag), "(not listed)") << flag;
  }
  EXPECT_EQ(DefaultIn(help.out, "--work-budget"), std::to_string(ZeroShotOptions().work_budget));
  EXPECT_EQ(DefaultIn(help.out, "--max-ops"), std::to_string(ZeroShotOptions().max_ops));
  EXPECT_EQ(DefaultIn(help.out, "--max-faces"), std::to_string(kDefaultMaxFaces));
  EXPECT_EQ(DefaultIn(help.out, "--seed"), std::to_string(FitterOptions().seed));
  EXPECT_EQ(DefaultIn(help.out, "--threads"), std::to_string(HardwareThreads()));
  EXPECT_EQ(DefaultIn(help.out, "--time-budget"), "0");
  EXPECT_EQ(DefaultIn(help.out, "--beam-width"), std::to_string(ZeroShotOptions().beam_width));
  EXPECT_EQ(DefaultIn(help.out, "--optimizer"), "\"lm\"");
  EXPECT_EQ(DefaultIn(help.out, "--blender-axes"), "\"import\"");
  EXPECT_EQ(DefaultIn(help.out, "--freeform"), "true");
  EXPECT_EQ(help.out.find("--minloglevel"), std::string::npos) << "glog's flags are not fit_sequence's";
  fs::remove_all(dir);
}

TEST(ApplySequenceCommandLine, HelpListsItsFlagsWithTheirDefaults) {
  const ToolOutput help = RunTool(std::string(OPGRAPH_APPLY_SEQUENCE) + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_EQ(DefaultIn(help.out, "--max-ops"), "1000");
  EXPECT_EQ(DefaultIn(help.out, "--max-faces"), std::to_string(kDefaultMaxFaces));
  EXPECT_EQ(DefaultIn(help.out, "--out"), "\"\"");
}

// --input=FILE, --input FILE and a flagfile give the same run.
TEST(FitSequenceCommandLine, ValuesAfterEqualsOrSpaceOrInAFlagfile) {
  const fs::path dir = FreshDir("opgraph_cli_values");
  const std::string input = std::string(OPGRAPH_SOURCE_DIR) + "/examples/barrel.obj";
  ASSERT_EQ(QuickFit(input, dir / "space", 500), 0);
  ASSERT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input=" + ShellQuote(input) + " --out=" +
                       ShellQuote((dir / "equals").string()) + " --work_budget=500 --quiet > /dev/null"),
            0);
  std::ofstream(dir / "flags.txt") << "# a quick fit\n--input=" << input << "\n--out=" << (dir / "flagfile").string()
                                   << "\n--work-budget=500\n--quiet\n";
  ASSERT_EQ(RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --flagfile " + ShellQuote((dir / "flags.txt").string()) +
                       " > /dev/null"),
            0);
  const std::string sequence = ReadText((dir / "space" / "sequence.json").string());
  EXPECT_GT(sequence.size(), 100u);
  EXPECT_EQ(ReadText((dir / "equals" / "sequence.json").string()), sequence);
  EXPECT_EQ(ReadText((dir / "flagfile" / "sequence.json").string()), sequence);
  fs::remove_all(dir);
}

TEST(FitSequenceCommandLine, BadCommandLineNamesTheArgument) {
  const fs::path dir = FreshDir("opgraph_cli_bad");
  std::ofstream(dir / "bad_flags.txt") << "--work-budget=500\n--bogus=1\n";
  const std::string fit = std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote(OPGRAPH_SOURCE_DIR) +
                          "/examples/barrel.obj --out " + ShellQuote((dir / "out").string());
  const struct {
    std::string args, expected;
  } cases[] = {
      {" --work-budget", "fit_sequence: flag '--work-budget' is missing its value"},
      {" --bogus 3", "fit_sequence: unknown flag '--bogus'"},
      {" stray.obj", "fit_sequence: unexpected argument 'stray.obj'"},
      {" --no-input", "fit_sequence: unknown flag '--no-input'"},
      {" --quiet=maybe", "fit_sequence: --quiet: expected true or false, not 'maybe'"},
      {" --seed=-1", "fit_sequence: --seed: expected an integer >= 0, not '-1'"},
      {" --beam-width 0", "fit_sequence: --beam-width: expected an integer in [1, 16]"},
      {" --op-price 0.95", "fit_sequence: --op-price: expected a fraction in [0, 0.9]"},
      {" --flagfile " + ShellQuote((dir / "bad_flags.txt").string()), "unknown flag '--bogus'"},
      {" --flagfile " + ShellQuote((dir / "missing.txt").string()), "fit_sequence: --flagfile: cannot open"},
  };
  for (const auto& c : cases) ExpectRefused(fit + c.args, dir / "out", c.expected);
  const std::string apply = std::string(OPGRAPH_APPLY_SEQUENCE) + " " + ShellQuote(OPGRAPH_SOURCE_DIR) +
                            "/examples/twisted_vase.json";
  ExpectRefused(apply + " --out " + ShellQuote((dir / "out").string()) + " extra.json", dir / "out",
                "apply_sequence: unexpected argument 'extra.json'");
  ExpectRefused(apply + " --out", dir / "out", "apply_sequence: flag '--out' is missing its value");
  ExpectRefused(apply + " --out " + ShellQuote((dir / "out").string()) + " --max-ops=0", dir / "out",
                "apply_sequence: --max-ops: expected an integer in [1, 9999999]");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace opgraph
