// Running the built tools from the tests as a user runs them: a shell command's exit code, a
// fresh folder for its outputs, a quick zero-shot fit, and the tools' contract for bad input.
#pragma once

#include <filesystem>
#include <string>

namespace opgraph {

// Runs `command` in a shell; its exit code (-1 when it did not exit normally). With
// `peak_rss_kb`, also the largest resident set of the shell and every process it waited for
// (the tool), in kB: wait4's rusage of the child.
int RunCommand(const std::string& command, long* peak_rss_kb = nullptr);

// The most memory a tool may take to refuse an input (issue: under 2 GB for any rejected input).
constexpr long kMaxRefusalRssKb = 2L * 1024 * 1024;

// A fresh folder `name` under the temporary directory.
std::filesystem::path FreshDir(const std::string& name);

// Zero-shot fit_sequence on `input` into `out` at a small budget; its exit code.
int QuickFit(const std::filesystem::path& input, const std::filesystem::path& out, int work_budget);

// Expects `command` (its output redirections added here) to refuse as the tools promise for
// bad input: exit code 2, one line on stderr holding `expected`, nothing written at `out`, and
// a peak resident set under kMaxRefusalRssKb.
void ExpectRefused(const std::string& command, const std::filesystem::path& out, const std::string& expected);

}  // namespace opgraph
