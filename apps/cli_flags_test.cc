// The tools' command-line parser on flags of its own (a tool's flags are the same kinds).
#include "apps/cli_flags.h"

#include <gflags/gflags.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

DEFINE_int64(test_budget, 500, "a number of units");
DEFINE_string(test_name, "box", "a name");
DEFINE_bool(test_freeform, true, "a stage, on by default");

namespace opgraph {
namespace {

namespace fs = std::filesystem;

// Parses `args` with the flags restored afterwards; the error, or "" when fine.
class CommandLineTest : public ::testing::Test {
 protected:
  std::string Parse(const std::vector<std::string>& args, int max_arguments = 0) {
    parsed_ = ParseCommandLine(args, max_arguments);
    return parsed_.error;
  }

  // A flagfile holding `text`, removed after the test.
  std::string Flagfile(const std::string& text) {
    const fs::path path = fs::temp_directory_path() / ("opgraph_flagfile_" + std::to_string(getpid()) + ".txt");
    std::ofstream(path) << text;
    flagfiles_.push_back(path);
    return path.string();
  }

  void TearDown() override {
    for (const fs::path& path : flagfiles_) fs::remove(path);
  }

  ParsedCommandLine parsed_;
  std::vector<fs::path> flagfiles_;
  gflags::FlagSaver saver_;
};

TEST_F(CommandLineTest, ValueAfterEqualsOrSpaceAndDashesOrUnderscores) {
  EXPECT_EQ(Parse({"--test-budget=7"}), "");
  EXPECT_EQ(FLAGS_test_budget, 7);
  EXPECT_EQ(Parse({"--test_budget", "8", "-test-name", "slab"}), "");
  EXPECT_EQ(FLAGS_test_budget, 8);
  EXPECT_EQ(FLAGS_test_name, "slab");
  EXPECT_EQ(Parse({"--test-name", "-x"}), "");  // a value may start with a dash (as --seed -1)
  EXPECT_EQ(FLAGS_test_name, "-x");
}

TEST_F(CommandLineTest, BoolsTurnedOnAndOff) {
  for (const char* off : {"--no-test-freeform", "--notest_freeform", "--no_test_freeform", "--test-freeform=false"}) {
    FLAGS_test_freeform = true;
    EXPECT_EQ(Parse({off}), "") << off;
    EXPECT_FALSE(FLAGS_test_freeform) << off;
  }
  EXPECT_EQ(Parse({"--test-freeform"}), "");
  EXPECT_TRUE(FLAGS_test_freeform);
  EXPECT_EQ(Parse({"--test-freeform=maybe"}), "--test-freeform: expected true or false, not 'maybe'");
}

TEST_F(CommandLineTest, EachProblemNamesItsArgument) {
  EXPECT_EQ(Parse({"--test-name"}), "flag '--test-name' is missing its value");
  EXPECT_EQ(Parse({"--bogus=1"}), "unknown flag '--bogus'");
  EXPECT_EQ(Parse({"--no-test-name"}), "unknown flag '--no-test-name'");  // not a bool
  EXPECT_EQ(Parse({"--no-test-freeform=1"}), "unknown flag '--no-test-freeform'");
  EXPECT_EQ(Parse({"--test-budget", "12x"}), "--test-budget: expected an integer, not '12x'");
  EXPECT_EQ(Parse({"stray"}), "unexpected argument 'stray'");
  EXPECT_EQ(Parse({"a.json", "b.json"}, 1), "unexpected argument 'b.json'");
  EXPECT_EQ(Parse({std::string(200, 'x')}).size(), std::string("unexpected argument ''...").size() + 80);
}

TEST_F(CommandLineTest, ArgumentsBesideFlagsAndAfterDoubleDash) {
  EXPECT_EQ(Parse({"a.json", "--test-budget=3", "--", "--b.json"}, 2), "");
  EXPECT_EQ(parsed_.arguments, (std::vector<std::string>{"a.json", "--b.json"}));
  EXPECT_EQ(FLAGS_test_budget, 3);
}

// --help and --version win wherever they stand, before any flag is set or refused.
TEST_F(CommandLineTest, HelpAndVersionBeforeAnything) {
  EXPECT_EQ(Parse({"--test-budget=5", "--bogus", "--help"}), "");
  EXPECT_TRUE(parsed_.help);
  EXPECT_EQ(FLAGS_test_budget, 500);
  EXPECT_EQ(Parse({"stray", "--version"}), "");
  EXPECT_TRUE(parsed_.version);
  EXPECT_EQ(Parse({"-h"}), "");
  EXPECT_TRUE(parsed_.help);
  EXPECT_EQ(Parse({"--", "--help"}, 1), "");  // an argument after --
  EXPECT_FALSE(parsed_.help);
}

TEST_F(CommandLineTest, Flagfiles) {
  const std::string good = Flagfile("# a comment\n\n  --test-budget=11\r\n--no-test-freeform\n--test_name=a b\n");
  EXPECT_EQ(Parse({"--flagfile", good, "--test-budget=12"}), "");
  EXPECT_EQ(FLAGS_test_budget, 12);  // later wins, as in gflags
  EXPECT_FALSE(FLAGS_test_freeform);
  EXPECT_EQ(FLAGS_test_name, "a b");

  const std::string no_value = Flagfile("--test-name\n");
  EXPECT_EQ(Parse({"--flagfile=" + no_value}), "--flagfile " + no_value + ": flag '--test-name' is missing its value");
  const std::string stray = Flagfile("box.obj\n");
  EXPECT_EQ(Parse({"--flagfile=" + stray}), "--flagfile " + stray + ": expected a --name=value line, not 'box.obj'");
  EXPECT_EQ(Parse({"--flagfile=/no/such/file"}), "--flagfile: cannot open '/no/such/file'");
  const std::string loop = Flagfile("");
  std::ofstream(loop) << "--flagfile=" << loop << "\n";
  EXPECT_NE(Parse({"--flagfile=" + loop}).find("flagfiles nested deeper than"), std::string::npos);
}

TEST(CommandLineHelp, TheToolsFlagsWithTypeDefaultAndMeaning) {
  const std::string help = CommandLineHelp({"tool", "usage: tool [flags]", __FILE__, 0});
  EXPECT_EQ(help.rfind("usage: tool [flags]\n", 0), 0u) << help;
  EXPECT_NE(help.find("  --test-budget (int64, default 500)\n      a number of units\n"), std::string::npos) << help;
  EXPECT_NE(help.find("  --test-name (string, default \"box\")\n"), std::string::npos) << help;
  EXPECT_NE(help.find("  --test-freeform (bool, default true)\n"), std::string::npos) << help;
  for (const char* common : {"--flagfile FILE", "--help, -h", "--version"}) {
    EXPECT_NE(help.find(common), std::string::npos) << common;
  }
  // Not the flags of gflags itself or of the libraries linked in.
  EXPECT_EQ(help.find("--tryfromenv"), std::string::npos) << help;
  EXPECT_EQ(help.find("--minloglevel"), std::string::npos) << help;
}

}  // namespace
}  // namespace opgraph
