#include "tests/run_command.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "tests/blender_runner.h"

namespace opgraph {

namespace fs = std::filesystem;

int RunCommand(const std::string& command, long* peak_rss_kb) {
  if (peak_rss_kb == nullptr) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  const pid_t child = fork();
  if (child < 0) return -1;
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(child, &status, 0, &usage) != child) return -1;
  *peak_rss_kb = usage.ru_maxrss;  // Linux: the child's and its waited-for descendants' peak
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path FreshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int QuickFit(const fs::path& input, const fs::path& out, int work_budget) {
  return RunCommand(std::string(OPGRAPH_FIT_SEQUENCE) + " --input " + ShellQuote(input.string()) + " --out " +
                    ShellQuote(out.string()) + " --work-budget " + std::to_string(work_budget) + " --quiet > /dev/null");
}

void ExpectRefused(const std::string& command, const fs::path& out, const std::string& expected) {
  // Per process: the suite runs tests of one binary side by side.
  const fs::path err = fs::temp_directory_path() / ("opgraph_refused_" + std::to_string(getpid()) + ".txt");
  long peak_rss_kb = 0;
  EXPECT_EQ(RunCommand(command + " > /dev/null 2> " + ShellQuote(err.string()), &peak_rss_kb), 2) << command;
  EXPECT_LT(peak_rss_kb, kMaxRefusalRssKb) << command;
  EXPECT_FALSE(fs::exists(out)) << command;
  std::ifstream in(err);
  std::string line, extra;
  std::getline(in, line);
  EXPECT_FALSE(std::getline(in, extra)) << command << ": more than one line: " << extra;
  EXPECT_NE(line.find(expected), std::string::npos) << command << ": " << line;
  fs::remove(err);
}

}  // namespace opgraph
