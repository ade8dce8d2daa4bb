// The last few values a topology pass computed from a face list, shared between ops and
// threads: a search evaluates the same cage topology over and over (every correspondence update
// re-evaluates its sequence, and sibling proposals share their prefix), while the pass depends
// on the faces alone. Keyed by the face list, the vertex count and a small integer (e.g. a
// subdivision level); compared directly, no hash: a hit reads the face list once (a hash would
// read it again), and a miss mostly stops at the first differing face, then costs a build anyway.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace opgraph {

template <typename Value>
class FaceListCache {
 public:
  explicit FaceListCache(size_t capacity) : capacity_(capacity) {}

  // The value for (mesh.faces, mesh.NumVertices(), key); `make()` (returning a
  // std::shared_ptr<const Value>) builds it on a miss, outside the lock. What make() throws
  // passes through and is not cached.
  template <typename Make>
  std::shared_ptr<const Value> Get(const Mesh& mesh, int key, Make&& make) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (const Entry& entry : entries_) {
        if (entry.key == key && entry.num_vertices == mesh.NumVertices() && entry.faces == mesh.faces) {
          return entry.value;
        }
      }
    }
    std::shared_ptr<const Value> value = std::forward<Make>(make)();
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.push_front({key, mesh.NumVertices(), mesh.faces, value});
    if (entries_.size() > capacity_) entries_.pop_back();
    return value;
  }

 private:
  struct Entry {
    int key;
    int num_vertices;
    std::vector<Polygon> faces;
    std::shared_ptr<const Value> value;
  };
  const size_t capacity_;
  std::mutex mutex_;
  std::deque<Entry> entries_;  // most recent first
};

}  // namespace opgraph
