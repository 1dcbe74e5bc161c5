// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H
#define EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H

/// \file Method_cache.h
/// The viewer's precomputed methods: each built once, on the first request
/// that needs it, and shared by the requests after it. The queries running
/// on each at once are capped, so that slow queries of one method (the
/// exact one) cannot take every server thread from another; a few more
/// wait their turn in order, so that a script sending several requests at
/// once is served rather than turned away.

#include "Viewer_methods.h"

#include <expmap/Errors.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace expmap_view {

/// The server cannot take the request now (a precomputation runs, or the
/// method's queries and its queue are full): HTTP 503 with a Retry-After
/// of `retry_after` seconds.
class Busy : public std::runtime_error {
 public:
  Busy(const std::string& message, int retry_after)
      : std::runtime_error(message), retry_after(retry_after) {}
  int retry_after;
};

/// A precomputation that failed: its message, and whether the mesh was to
/// blame (`Invalid_input`, HTTP 400) or the computation (HTTP 422).
class Precomputation_failed : public std::runtime_error {
 public:
  Precomputation_failed(const std::string& message, bool invalid_input)
      : std::runtime_error(message), invalid_input(invalid_input) {}
  bool invalid_input;
};

/// How much the cache lets run, wait and stay.
struct Cache_limits {
  /// Queries that run on one method at once.
  unsigned queries_per_method = 2;
  /// Requests that wait, in order, for one of those; more get `Busy`.
  unsigned waiting_per_method = 4;
  /// How long one of them waits at most before it gets `Busy`.
  double max_wait_seconds = 30;
  /// Variants of one method (heat's time factors) kept at once; the least
  /// recently used idle one makes room for a new one.
  unsigned variants_kept = 3;
  /// Fewer are kept where their `held_bytes()` and a new one's (as large as
  /// the largest kept one once precomputed) would exceed this. Heat's
  /// factors grow with the mesh: below `Heat_options::subdomain_min_vertices`
  /// a heat method holds its whole mesh's factors from the start; above,
  /// its subdomains' cache bound (1 GiB) until a patch
  /// too large for them factors the whole mesh (1.1 GB more on 711k
  /// vertices, 4.4 GB on 2.85M), which first drops every other idle variant
  /// (until one such factorization was measured, then as many as its bytes
  /// require).
  std::size_t variant_bytes_kept = std::size_t(3) << 30;
};

/// What `Method_cache::status()` reports of one precomputed method.
struct Precomputation_status {
  std::string method;
  double time_factor = 0;  ///< heat's m; 0 for the others
  enum class State { running, ready, failed } state = State::running;
  double seconds = 0;  ///< so far while running, in all once done
  std::string error;   ///< when failed
  /// While running: the step it is in and the estimated fraction done.
  std::string step;
  double fraction = 0;
  unsigned queries_running = 0, waiting = 0;  ///< once ready
};

class Method_cache {
  struct Entry;

 public:
  /// A method ready to answer, held for one query: the query cap counts it
  /// until the lease is destroyed.
  class Lease {
   public:
    Lease(std::shared_ptr<Entry> entry, std::mutex& mutex) : m_entry(std::move(entry)), m_mutex(&mutex) {}
    Lease(Lease&& other) noexcept : m_entry(std::move(other.m_entry)), m_mutex(other.m_mutex) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (!m_entry) return;
      std::lock_guard<std::mutex> lock(*m_mutex);
      // A query may have factored the whole mesh where the estimate
      // (`may_factor_whole_mesh()`) did not expect it.
      m_entry->held_bytes = m_entry->method->held_bytes();
      --m_entry->queries_running;
      m_entry->turn.notify_all();
    }
    const Viewer_method& method() const { return *m_entry->method; }

   private:
    std::shared_ptr<Entry> m_entry;
    std::mutex* m_mutex;
  };

  /// \param mesh the mesh every method is built on; must outlive the cache.
  Method_cache(const Mesh& mesh, const Cache_limits& limits) : m_mesh(mesh), m_limits(limits) {}

  const Cache_limits& limits() const { return m_limits; }

  /// The method `info` (with heat's `time_factor`), leased for one query
  /// with `patch`. The first call for it precomputes it on the calling
  /// thread; so does the first call whose patch may need the whole mesh's
  /// factors of a method that has only built subdomains (heat on a large
  /// mesh), for that second step. When `queries_per_method` queries run on
  /// it, the call waits for one of them behind the calls that came before
  /// it.
  /// \throws Busy while another call precomputes it, when
  ///         `waiting_per_method` calls wait already, or after waiting
  ///         `max_wait_seconds`.
  /// \throws Precomputation_failed if its precomputation failed (then and
  ///         on every later call: it is not tried again), or if factoring
  ///         its whole mesh failed (for this call: a later one tries again).
  Lease acquire(const Method_info& info, double time_factor, const expmap::Patch& patch) {
    if (!info.takes_time_factor) time_factor = 0;
    std::shared_ptr<Entry> entry;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      entry = find(info.name, time_factor);
      if (entry) {
        entry->last_use = ++m_clock;
        if (entry->state == Precomputation_status::State::failed)
          throw Precomputation_failed(entry->error, entry->invalid_input);
        if (entry->state == Precomputation_status::State::running) throw precomputing(*entry);
        if (!entry->method->may_factor_whole_mesh(patch)) {
          return lease_in_turn(entry, lock);
        }
        // Until one such factorization was measured, it may take the
        // whole budget.
        make_room(info.name, m_whole_mesh_bytes ? m_whole_mesh_bytes : m_limits.variant_bytes_kept,
                  entry.get());
        entry->state = Precomputation_status::State::running;
        entry->started = std::chrono::steady_clock::now();
        entry->step.clear();
        entry->fraction = 0;
      } else {
        make_room(info.name, largest_precomputed(info.name));
        entry = std::make_shared<Entry>();
        entry->method_name = info.name;
        entry->time_factor = time_factor;
        entry->started = std::chrono::steady_clock::now();
        entry->last_use = ++m_clock;
        m_entries.push_back(entry);
      }
    }
    // The precomputation runs outside the lock: status() and other methods'
    // queries go on meanwhile; its progress is kept for status().
    const bool whole_mesh = entry->method != nullptr;
    std::unique_ptr<Viewer_method> method;
    std::string error;
    bool invalid_input = false;
    Entry* const progressing = entry.get();
    const expmap::Precomputation_callback progress = [this, progressing](const char* step, double fraction) {
      std::lock_guard<std::mutex> lock(m_mutex);
      progressing->step = step;
      progressing->fraction = fraction;
    };
    try {
      if (whole_mesh)
        entry->method->factor_whole_mesh(progress);
      else
        method = info.make(m_mesh, time_factor, progress);
    } catch (const expmap::Invalid_input& e) {
      error = e.what();
      invalid_input = true;
    } catch (const std::exception& e) {
      error = expmap::internal::user_message(e);
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    entry->seconds = seconds_since(entry->started);
    if (whole_mesh) {
      entry->state = Precomputation_status::State::ready;
      entry->held_bytes = entry->method->held_bytes();
      if (!error.empty())
        throw Precomputation_failed("factoring the whole mesh for " + describe(*entry) +
                                        " failed: " + error,
                                    invalid_input);
      m_whole_mesh_bytes = std::max(m_whole_mesh_bytes, entry->held_bytes);
      std::printf("expmap: factored the whole mesh for %s in %s\n", describe(*entry).c_str(),
                  seconds_text(entry->seconds).c_str());
      std::fflush(stdout);
      return lease_in_turn(entry, lock);
    }
    if (!method) {
      entry->state = Precomputation_status::State::failed;
      entry->error = "precomputing " + describe(*entry) + " failed: " + error;
      entry->invalid_input = invalid_input;
      throw Precomputation_failed(entry->error, invalid_input);
    }
    entry->held_bytes = entry->precomputed_bytes = method->held_bytes();
    entry->method = std::move(method);
    entry->state = Precomputation_status::State::ready;
    ++entry->queries_running;
    std::printf("expmap: precomputed %s in %s\n", describe(*entry).c_str(),
                seconds_text(entry->seconds).c_str());
    std::fflush(stdout);
    return Lease(entry, m_mutex);
  }

  /// Every precomputation started so far and kept, in the order started.
  std::vector<Precomputation_status> status() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<Precomputation_status> all;
    for (const auto& e : m_entries) {
      Precomputation_status s;
      s.method = e->method_name;
      s.time_factor = e->time_factor;
      s.state = e->state;
      s.seconds = e->state == Precomputation_status::State::running ? seconds_since(e->started)
                                                                      : e->seconds;
      s.error = e->error;
      s.step = e->step;
      s.fraction = e->fraction;
      s.queries_running = e->queries_running;
      s.waiting = static_cast<unsigned>(e->queue.size());
      all.push_back(s);
    }
    return all;
  }

 private:
  struct Entry {
    std::string method_name;
    double time_factor = 0;
    Precomputation_status::State state = Precomputation_status::State::running;
    std::chrono::steady_clock::time_point started;
    double seconds = 0;
    std::string step;
    double fraction = 0;
    std::unique_ptr<const Viewer_method> method;
    std::size_t held_bytes = 0;
    std::size_t precomputed_bytes = 0;  // held_bytes once precomputed, before any whole mesh
    std::string error;
    bool invalid_input = false;
    unsigned queries_running = 0;
    std::deque<std::uint64_t> queue;  // the tickets of the calls waiting, in order
    std::uint64_t next_ticket = 0;
    std::condition_variable turn;  // a query ended, or the queue moved
    unsigned long long last_use = 0;
  };

  // Returns once `e` has a free query slot and no earlier call waits for
  // one; waits for that in e's queue (`lock` held on m_mutex).
  void wait_for_turn(Entry& e, std::unique_lock<std::mutex>& lock) {
    if (e.queries_running < m_limits.queries_per_method && e.queue.empty()) return;
    if (e.queue.size() >= m_limits.waiting_per_method)
      throw Busy(std::to_string(e.queries_running) + " queries of " + describe(e) + " are running and " +
                     std::to_string(e.queue.size()) + " wait (as many as this server lets wait); retry",
                 1);
    const std::uint64_t ticket = e.next_ticket++;
    e.queue.push_back(ticket);
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(m_limits.max_wait_seconds));
    const bool turn = e.turn.wait_until(lock, deadline, [&] {
      return e.queries_running < m_limits.queries_per_method && e.queue.front() == ticket;
    });
    e.queue.erase(std::find(e.queue.begin(), e.queue.end(), ticket));
    e.turn.notify_all();  // the next in the queue may go, or move up
    if (!turn)
      throw Busy("waited " + seconds_text(m_limits.max_wait_seconds) + " for one of the " +
                     std::to_string(m_limits.queries_per_method) + " queries of " + describe(e) +
                     " to end; retry",
                 1);
  }

  // `e` leased for one query once its turn comes (`wait_for_turn`).
  Lease lease_in_turn(const std::shared_ptr<Entry>& e, std::unique_lock<std::mutex>& lock) {
    wait_for_turn(*e, lock);
    ++e->queries_running;
    return Lease(e, m_mutex);
  }

  // Busy for a request that finds `e` being precomputed: what it waits for,
  // and a retry after about the time left (from the fraction done so far).
  static Busy precomputing(const Entry& e) {
    const double seconds = seconds_since(e.started);
    const double left = e.fraction > 0.05 ? seconds * (1 - e.fraction) / e.fraction : 2.0;
    const int retry = static_cast<int>(std::clamp(left, 1.0, 30.0) + 0.5);
    std::string doing = e.step.empty() ? std::string() : ": " + e.step;
    if (e.fraction > 0) doing += ", about " + std::to_string(static_cast<int>(100 * e.fraction)) + "% done";
    return Busy(describe(e) + " is being precomputed" + doing + " (" + seconds_text(seconds) +
                    " so far); retry",
                retry);
  }

  static double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }
  static std::string seconds_text(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
  }
  static std::string describe(const Entry& e) {
    if (e.time_factor == 0) return e.method_name;
    char text[64];
    std::snprintf(text, sizeof text, "%s (m = %g)", e.method_name.c_str(), e.time_factor);
    return text;
  }

  std::shared_ptr<Entry> find(const std::string& name, double time_factor) const {
    for (const auto& e : m_entries)
      if (e->method_name == name && e->time_factor == time_factor) return e;
    return nullptr;
  }

  // What a new variant of `name` is expected to hold: the most a kept one
  // held once precomputed.
  std::size_t largest_precomputed(const std::string& name) const {
    std::size_t largest = 0;
    for (const auto& e : m_entries)
      if (e->method_name == name) largest = std::max(largest, e->precomputed_bytes);
    return largest;
  }

  // Before a precomputation of `name` expected to hold `expected` bytes:
  // drops the least recently used idle ready or failed variant while their
  // bytes and `expected` would exceed `variant_bytes_kept`. For a new
  // variant (`growing` null) also while `variants_kept` are held; a variant
  // `growing` (factoring its whole mesh) counts as `expected` alone. Leases
  // keep their entry alive, so only idle ones go.
  void make_room(const std::string& name, std::size_t expected, const Entry* growing = nullptr) {
    for (;;) {
      std::size_t held = 0, bytes = 0;
      std::shared_ptr<Entry> oldest;
      for (const auto& e : m_entries) {
        if (e->method_name != name || e.get() == growing) continue;
        ++held;
        bytes += e->held_bytes;
        const bool idle = e->state != Precomputation_status::State::running &&
                          e->queries_running == 0 && e->queue.empty();
        if (idle && (!oldest || e->last_use < oldest->last_use)) oldest = e;
      }
      if ((growing || held < m_limits.variants_kept) &&
          (held == 0 || bytes + expected <= m_limits.variant_bytes_kept))
        return;
      if (!oldest)
        throw Busy("every kept " + name + " method is in use; retry when a query is done", 1);
      m_entries.erase(std::find(m_entries.begin(), m_entries.end(), oldest));
    }
  }

  const Mesh& m_mesh;
  const Cache_limits m_limits;
  mutable std::mutex m_mutex;
  std::vector<std::shared_ptr<Entry>> m_entries;
  unsigned long long m_clock = 0;
  std::size_t m_whole_mesh_bytes = 0;  // the most a variant held once its whole mesh was factored
};

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H
