// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H
#define EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H

/// \file Method_cache.h
/// The viewer's precomputed methods: each built once, on the first request
/// that needs it, and shared by the requests after it; the number of
/// queries running on each at once is capped, so that slow queries of one
/// method (the exact one) cannot take every server thread from another.

#include "Viewer_methods.h"

#include <expmap/Errors.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace expmap_view {

/// The server cannot take the request now (a precomputation or the query
/// cap): HTTP 503, to be retried.
class Busy : public std::runtime_error {
 public:
  explicit Busy(const std::string& message) : std::runtime_error(message) {}
};

/// A precomputation that failed: its message, and whether the mesh was to
/// blame (`Invalid_input`, HTTP 400) or the computation (HTTP 422).
class Precomputation_failed : public std::runtime_error {
 public:
  Precomputation_failed(const std::string& message, bool invalid_input)
      : std::runtime_error(message), invalid_input(invalid_input) {}
  bool invalid_input;
};

/// What `Method_cache::status()` reports of one precomputation.
struct Precomputation_status {
  std::string method;
  double time_factor = 0;  ///< heat's m; 0 for the others
  enum class State { running, ready, failed } state = State::running;
  double seconds = 0;  ///< so far while running, in all once done
  std::string error;   ///< when failed
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
      --m_entry->queries_running;
    }
    const Viewer_method& method() const { return *m_entry->method; }

   private:
    std::shared_ptr<Entry> m_entry;
    std::mutex* m_mutex;
  };

  /// \param mesh the mesh every method is built on; must outlive the cache.
  /// \param queries_per_method queries that may run on one method at once.
  /// \param time_factors_kept heat methods of different m kept at once (each
  ///        holds its factors, the bulk of the server's memory); the least
  ///        recently used idle one makes room for a new one.
  Method_cache(const Mesh& mesh, unsigned queries_per_method, unsigned time_factors_kept)
      : m_mesh(mesh), m_queries_per_method(queries_per_method), m_time_factors_kept(time_factors_kept) {}

  /// The method `info` (with heat's `time_factor`), leased for one query.
  /// The first call for it precomputes it on the calling thread.
  /// \throws Busy while another call precomputes it, or when
  ///         `queries_per_method` queries already run on it.
  /// \throws Precomputation_failed if its precomputation failed (then and
  ///         on every later call: it is not tried again).
  Lease acquire(const Method_info& info, double time_factor) {
    if (!info.takes_time_factor) time_factor = 0;
    std::shared_ptr<Entry> entry;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      entry = find(info.name, time_factor);
      if (entry) {
        entry->last_use = ++m_clock;
        if (entry->state == Precomputation_status::State::failed)
          throw Precomputation_failed(entry->error, entry->invalid_input);
        if (entry->state == Precomputation_status::State::running)
          throw Busy(describe(*entry) + " is being precomputed (" +
                     seconds_text(seconds_since(entry->started)) + " so far); retry");
        if (entry->queries_running >= m_queries_per_method)
          throw Busy(std::to_string(m_queries_per_method) + " queries of " + describe(*entry) +
                     " are running; retry when one is done");
        ++entry->queries_running;
        return Lease(entry, m_mutex);
      }
      make_room(info.name);
      entry = std::make_shared<Entry>();
      entry->method_name = info.name;
      entry->time_factor = time_factor;
      entry->started = std::chrono::steady_clock::now();
      entry->last_use = ++m_clock;
      m_entries.push_back(entry);
    }
    // The precomputation runs outside the lock: status() and other methods'
    // queries go on meanwhile.
    std::unique_ptr<Viewer_method> method;
    std::string error;
    bool invalid_input = false;
    try {
      method = info.make(m_mesh, time_factor);
    } catch (const expmap::Invalid_input& e) {
      error = e.what();
      invalid_input = true;
    } catch (const std::exception& e) {
      error = expmap::internal::user_message(e);
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    entry->seconds = seconds_since(entry->started);
    if (!method) {
      entry->state = Precomputation_status::State::failed;
      entry->error = "precomputing " + describe(*entry) + " failed: " + error;
      entry->invalid_input = invalid_input;
      throw Precomputation_failed(entry->error, invalid_input);
    }
    entry->method = std::move(method);
    entry->state = Precomputation_status::State::ready;
    ++entry->queries_running;
    std::printf("expmap: precomputed %s in %s\n", describe(*entry).c_str(),
                seconds_text(entry->seconds).c_str());
    std::fflush(stdout);
    return Lease(entry, m_mutex);
  }

  /// Every precomputation started so far, in the order started.
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
    std::unique_ptr<const Viewer_method> method;
    std::string error;
    bool invalid_input = false;
    unsigned queries_running = 0;
    unsigned long long last_use = 0;
  };

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

  // Before a new precomputation of `name`: drops the least recently used
  // idle ready or failed variant while `time_factors_kept` are held. Leases
  // keep their entry alive, so only idle ones go.
  void make_room(const std::string& name) {
    for (;;) {
      std::size_t held = 0;
      std::shared_ptr<Entry> oldest;
      for (const auto& e : m_entries) {
        if (e->method_name != name) continue;
        ++held;
        const bool idle = e->state != Precomputation_status::State::running && e->queries_running == 0;
        if (idle && (!oldest || e->last_use < oldest->last_use)) oldest = e;
      }
      if (held < m_time_factors_kept) return;
      if (!oldest)
        throw Busy("every kept " + name + " method is in use; retry when a query is done");
      m_entries.erase(std::find(m_entries.begin(), m_entries.end(), oldest));
    }
  }

  const Mesh& m_mesh;
  const unsigned m_queries_per_method, m_time_factors_kept;
  mutable std::mutex m_mutex;
  std::vector<std::shared_ptr<Entry>> m_entries;
  unsigned long long m_clock = 0;
};

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_METHOD_CACHE_H
