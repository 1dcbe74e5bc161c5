// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_WORKSPACE_POOL_H
#define EXPMAP_INTERNAL_WORKSPACE_POOL_H

#include <memory>
#include <mutex>
#include <vector>

namespace expmap {
namespace internal {

/// Keeps per-query scratch memory (O(mesh) sized, allocated once) for
/// reuse, so that `const` queries allocate nothing proportional to the mesh
/// and concurrent queries each get their own workspace.
template <class Workspace>
class Workspace_pool {
 public:
  /// Returns a workspace to the pool when it goes out of scope.
  class Lease {
   public:
    Lease(Workspace_pool& pool, std::unique_ptr<Workspace> ws) : m_pool(pool), m_ws(std::move(ws)) {}
    ~Lease() { m_pool.release(std::move(m_ws)); }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Workspace* operator->() { return m_ws.get(); }
    Workspace& operator*() { return *m_ws; }

   private:
    Workspace_pool& m_pool;
    std::unique_ptr<Workspace> m_ws;
  };

  Workspace_pool() = default;
  // A copied or moved owner starts with an empty pool of its own.
  Workspace_pool(const Workspace_pool&) {}
  Workspace_pool& operator=(const Workspace_pool&) { return *this; }

  /// A free workspace, or a new one made by `make()` if none is free.
  template <class Make>
  Lease acquire(Make make) {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (!m_free.empty()) {
        std::unique_ptr<Workspace> ws = std::move(m_free.back());
        m_free.pop_back();
        return Lease(*this, std::move(ws));
      }
    }
    return Lease(*this, make());
  }

 private:
  void release(std::unique_ptr<Workspace> ws) {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_free.push_back(std::move(ws));
  }
  std::mutex m_mutex;
  std::vector<std::unique_ptr<Workspace>> m_free;
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_WORKSPACE_POOL_H
