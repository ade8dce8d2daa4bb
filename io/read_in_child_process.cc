#include "io/read_in_child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <stdexcept>

namespace opgraph {
namespace {

// The child's answer: 'G' and the geometry, or 'E' and an error message.
constexpr char kGeometry = 'G';
constexpr char kError = 'E';

template <class T>
void Append(std::string* bytes, const T& value) {
  bytes->append(reinterpret_cast<const char*>(&value), sizeof(T));
}

void AppendPositions(std::string* bytes, const Positions<double>& positions) {
  Append(bytes, static_cast<uint64_t>(positions.size()));
  for (const Vec3d& p : positions) Append(bytes, p.x()), Append(bytes, p.y()), Append(bytes, p.z());
}

std::string Serialize(const InputGeometry& geometry) {
  std::string bytes(1, kGeometry);
  AppendPositions(&bytes, geometry.mesh.vertices);
  AppendPositions(&bytes, geometry.normals);
  Append(&bytes, static_cast<uint64_t>(geometry.mesh.faces.size()));
  for (const Polygon& face : geometry.mesh.faces) {
    Append(&bytes, static_cast<uint64_t>(face.size()));
    for (int v : face) Append(&bytes, static_cast<int32_t>(v));
  }
  return bytes;
}

// Reads what Serialize wrote; a short or inconsistent message is the child's failure.
class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  T Next() {
    T value;
    if (bytes_.size() - offset_ < sizeof(T)) throw std::length_error("truncated");
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }
  // A count of items of `item_size` bytes each that the rest of the message can hold.
  size_t Count(size_t item_size) {
    const uint64_t count = Next<uint64_t>();
    if (count > (bytes_.size() - offset_) / item_size) throw std::length_error("truncated");
    return static_cast<size_t>(count);
  }
  Positions<double> NextPositions() {
    Positions<double> positions(Count(3 * sizeof(double)));
    for (Vec3d& p : positions) p.x() = Next<double>(), p.y() = Next<double>(), p.z() = Next<double>();
    return positions;
  }
  bool AtEnd() const { return offset_ == bytes_.size(); }

 private:
  const std::string& bytes_;
  size_t offset_ = 1;  // after the kind
};

InputGeometry Deserialize(const std::string& bytes) {
  Reader reader(bytes);
  InputGeometry geometry;
  geometry.mesh.vertices = reader.NextPositions();
  geometry.normals = reader.NextPositions();
  geometry.mesh.faces.resize(reader.Count(sizeof(uint64_t)));
  for (Polygon& face : geometry.mesh.faces) {
    face.resize(reader.Count(sizeof(int32_t)));
    for (int& v : face) v = reader.Next<int32_t>();
  }
  if (!reader.AtEnd()) throw std::length_error("trailing bytes");
  return geometry;
}

void WriteAll(int fd, const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nothing to tell
    written += static_cast<size_t>(n);
  }
}

// Reads until the writer closes its end; false if `deadline` passes first.
bool ReadAllBefore(int fd, std::chrono::steady_clock::time_point deadline, std::string* bytes) {
  char buffer[1 << 16];
  while (true) {
    using std::chrono::milliseconds;
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd poll_fd{fd, POLLIN, 0};
    const int ready = poll(&poll_fd, 1, static_cast<int>(std::min<int64_t>(left.count(), 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked at the top
    if (ready < 0) return true;
    const ssize_t n = read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    bytes->append(buffer, static_cast<size_t>(n));
  }
}

[[noreturn]] void RunChild(int fd, const std::function<InputGeometry()>& read) {
  // A crash here ends this process quietly, with its signal for the parent to report: not in
  // the handlers of the host's copy (a crash reporter, a sanitizer's report, a fuzzer's).
  for (const int signal_number : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(signal_number, SIG_DFL);
  std::string answer;
  try {
    answer = Serialize(read());
  } catch (const std::exception& error) {
    answer = std::string(1, kError) + error.what();
  } catch (...) {
    answer = std::string(1, kError) + "unknown error";
  }
  WriteAll(fd, answer);
  // _exit: no atexit handlers or static destructors of the parent's copy run here (nor a leak
  // check of what the reader leaked).
  _exit(0);
}

}  // namespace

double ReaderTimeLimitSeconds(const std::string& path) {
  std::error_code error;
  const uintmax_t bytes = std::filesystem::file_size(path, error);
  return 10.0 + (error ? 0.0 : 5.0 * static_cast<double>(bytes) / (1 << 20));
}

InputGeometry ReadInChildProcess(const std::string& path, const std::function<InputGeometry()>& read,
                                 double time_limit_seconds) {
  if (time_limit_seconds <= 0) time_limit_seconds = ReaderTimeLimitSeconds(path);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(std::min(time_limit_seconds, 1e7)));
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(path + ": cannot read it: pipe: " + std::strerror(errno));
  const pid_t child = fork();
  if (child < 0) {
    close(fds[0]), close(fds[1]);
    throw std::runtime_error(path + ": cannot read it: fork: " + std::strerror(errno));
  }
  if (child == 0) {
    close(fds[0]);
    RunChild(fds[1], read);
  }
  close(fds[1]);
  std::string answer;
  const bool finished = ReadAllBefore(fds[0], deadline, &answer);
  close(fds[0]);
  if (!finished) kill(child, SIGKILL);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished) {
    char limit[32];
    std::snprintf(limit, sizeof(limit), "%.0f", time_limit_seconds);
    throw std::runtime_error(path + ": cannot read it: the reader did not finish within " + limit +
                             " s (a malformed file can make it loop)");
  }
  if (WIFSIGNALED(status) || answer.empty()) {
    const std::string how = WIFSIGNALED(status) ? strsignal(WTERMSIG(status)) : "no answer";
    throw std::runtime_error(path + ": cannot read it: the reader crashed on it (" + how + ")");
  }
  if (answer[0] == kError) throw std::runtime_error(answer.substr(1));
  try {
    if (answer[0] == kGeometry) return Deserialize(answer);
  } catch (const std::length_error&) {
  }
  throw std::runtime_error(path + ": cannot read it: the reader's answer is incomplete");
}

}  // namespace opgraph
