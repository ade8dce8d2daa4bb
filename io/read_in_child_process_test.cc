// A reader run in a child process: its geometry and its errors come back as if it ran here, and
// a reader that crashes takes down only the child.
#include "io/read_in_child_process.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace opgraph {
namespace {

TEST(ReadInChildProcess, GeometryComesBackExactly) {
  InputGeometry sent;
  sent.mesh.vertices = {Vec3d(0.1, -2e300, 3), Vec3d(1.0 / 3, 0, 0), Vec3d(0, 1, 0), Vec3d(5, 5, 5)};
  sent.mesh.faces = {{0, 1, 2}, {0, 2, 3, 1}};
  sent.normals = {Vec3d(0, 0, 1), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, -1)};
  const InputGeometry received = ReadInChildProcess("in.obj", [&sent] { return sent; });
  EXPECT_EQ(received.mesh.vertices, sent.mesh.vertices);
  EXPECT_EQ(received.mesh.faces, sent.mesh.faces);
  EXPECT_EQ(received.normals, sent.normals);
}

TEST(ReadInChildProcess, TheReadersErrorComesBackAsItsMessage) {
  try {
    ReadInChildProcess("in.ply", []() -> InputGeometry { throw std::invalid_argument("in.ply: bad header"); });
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "in.ply: bad header");
  }
}

TEST(ReadInChildProcess, ACrashInTheReaderIsAnErrorHere) {
  for (const int signal : {SIGSEGV, SIGABRT}) {
    try {
      ReadInChildProcess("in.off", [signal]() -> InputGeometry {
        std::raise(signal);
        return {};
      });
      FAIL() << "no error";
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find("in.off: cannot read it: the reader crashed on it ("), std::string::npos)
          << error.what();
    }
  }
}

TEST(ReadInChildProcess, AReaderThatNeverFinishesIsStoppedAtTheTimeLimit) {
  const auto start = std::chrono::steady_clock::now();
  try {
    ReadInChildProcess(
        "in.ply",
        []() -> InputGeometry {
          while (true) pause();  // as a parser looping on a malformed file
        },
        /*time_limit_seconds=*/1);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()),
              "in.ply: cannot read it: the reader did not finish within 1 s (a malformed file can make it loop)");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(seconds, 1.0);
  EXPECT_LT(seconds, 30.0);  // killed, not waited for
}

TEST(ReadInChildProcess, TheDefaultTimeLimitGrowsWithTheFile) {
  EXPECT_EQ(ReaderTimeLimitSeconds("/no/such/file.ply"), 10.0);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "opgraph_time_limit_test.ply";
  std::filesystem::remove(path);
  {
    std::ofstream file(path, std::ios::binary);
    file << std::string(2 << 20, 'x');  // 2 MiB
  }
  EXPECT_DOUBLE_EQ(ReaderTimeLimitSeconds(path.string()), 20.0);
  std::filesystem::remove(path);
}

// Files found by scripts/fuzz.sh on which Assimp 5.2 crashed or PCL's conversion read outside
// its data: refused with a one-line error.
TEST(ReadInput, MalformedFilesThatBrokeTheReadersAreRefused) {
  const std::filesystem::path dir = std::filesystem::path(OPGRAPH_SOURCE_DIR) / "tests" / "data" / "malformed";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    try {
      ReadInput(entry.path().string());
      ADD_FAILURE() << entry.path() << " was read";
    } catch (const std::runtime_error& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(entry.path().string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_GE(files, 3);
}

}  // namespace
}  // namespace opgraph
