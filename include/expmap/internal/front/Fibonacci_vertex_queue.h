// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_FRONT_FIBONACCI_VERTEX_QUEUE_H
#define EXPMAP_INTERNAL_FRONT_FIBONACCI_VERTEX_QUEUE_H

#include <expmap/internal/Region_growing.h>

#include <boost/heap/fibonacci_heap.hpp>

#include <cassert>
#include <utility>
#include <vector>

namespace expmap {
namespace internal {

/// Min-priority queue of vertex indices with decrease-key, on
/// `boost::heap::fibonacci_heap` (the queue the paper found fastest for the
/// Dijkstra-style baselines).
///
/// The handle of each queued vertex lives in an array sized once for the
/// mesh; whether a handle is valid is told by a stamp, so `clear()` costs
/// the number of vertices still queued, never the size of the mesh. Equal
/// keys pop in increasing vertex order, so a run does not depend on the
/// order in which a mesh lists its faces.
class Fibonacci_vertex_queue {
 public:
  /// Allocates the handle array for vertices 0 .. n-1 (once per workspace).
  void resize(std::size_t n) {
    m_heap.clear();
    m_handle.resize(n);
    m_queued.resize(n);
    m_queued.next_query();
  }

  /// Empties the queue for the next query.
  void clear() {
    m_heap.clear();
    m_queued.next_query();
  }

  bool empty() const { return m_heap.empty(); }
  bool contains(int v) const { return m_queued.is_marked(v) && m_queued.value(v) == 1; }
  int top_vertex() const { return m_heap.top().vertex; }
  double top_key() const { return m_heap.top().key; }

  /// Queues `v` with `key`, or lowers its key if it is queued with a larger
  /// one (a larger key for a queued vertex is ignored).
  void push_or_decrease(int v, double key) {
    if (contains(v)) {
      auto& handle = m_handle[v];
      if (key < (*handle).key) m_heap.increase(handle, Item{key, v});  // higher priority
      return;
    }
    m_handle[v] = m_heap.push(Item{key, v});
    m_queued.mark(v, 1);
  }

  /// Removes and returns the vertex of smallest key, with its key.
  std::pair<int, double> pop() {
    assert(!m_heap.empty());
    const Item top = m_heap.top();
    m_heap.pop();
    m_queued.mark(top.vertex, 0);
    return {top.vertex, top.key};
  }

 private:
  struct Item {
    double key;
    int vertex;
  };
  // boost::heap is a max-heap: "greater" puts the smallest key on top.
  struct Lower_priority {
    bool operator()(const Item& a, const Item& b) const {
      return a.key > b.key || (a.key == b.key && a.vertex > b.vertex);
    }
  };
  using Heap = boost::heap::fibonacci_heap<Item, boost::heap::compare<Lower_priority>>;

  Heap m_heap;
  std::vector<typename Heap::handle_type> m_handle;
  Vertex_marks m_queued;  // marked this query; value 1 while in the heap
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_FRONT_FIBONACCI_VERTEX_QUEUE_H
