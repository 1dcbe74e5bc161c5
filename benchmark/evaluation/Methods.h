// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_BENCHMARK_EVALUATION_METHODS_H
#define EXPMAP_BENCHMARK_EVALUATION_METHODS_H

/// \file Methods.h
/// The exponential-map methods under study behind one interface: a key, a
/// label, the precomputation time and a query `compute(source, patch)`.

#include "Common.h"

#include <expmap/Heat_exponential_map.h>
#include <expmap/Patch.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace expmap_evaluation {

struct Method {
  std::string key;    // for CSVs: heat_m10, dem, ...
  std::string label;  // for tables and pictures
  double precompute_seconds = 0;
  std::function<Map(std::size_t, const expmap::Patch&)> compute;
};

class Method_set {
 public:
  explicit Method_set(const Mesh& mesh) : m_mesh(mesh) {}

  void add_heat(const std::string& key, const std::string& label, double time_factor,
                expmap::Laplacian_mode mode = expmap::Laplacian_mode::direct,
                const expmap::Heat_query_options& query = {}) {
    expmap::Heat_options options;
    options.time_factor = time_factor;
    options.laplacian = mode;
    add_heat(key, label, options, query);
  }

  void add_heat(const std::string& key, const std::string& label,
                const expmap::Heat_options& options, const expmap::Heat_query_options& query) {
    const auto start = std::chrono::steady_clock::now();
    auto heat = std::make_shared<expmap::Heat_exponential_map<Mesh>>(m_mesh, options);
    push(key, label, seconds_since(start),
         [heat, query](std::size_t s, const expmap::Patch& p) {
           return heat->compute_by_index(s, p, query);
         },
         heat);
  }

  template <template <class> class M>
  void add(const std::string& key, const std::string& label) {
    const auto start = std::chrono::steady_clock::now();
    auto method = std::make_shared<M<Mesh>>(m_mesh);
    push(key, label, seconds_since(start),
         [method](std::size_t s, const expmap::Patch& p) { return method->compute_by_index(s, p); },
         method);
  }

  std::vector<Method> methods;

 private:
  void push(const std::string& key, const std::string& label, double seconds,
            std::function<Map(std::size_t, const expmap::Patch&)> f, std::shared_ptr<void> owner) {
    Method m;
    m.key = key;
    m.label = label;
    m.precompute_seconds = seconds;
    m.compute = std::move(f);
    methods.push_back(std::move(m));
    m_owners.push_back(std::move(owner));
  }
  const Mesh& m_mesh;
  std::vector<std::shared_ptr<void>> m_owners;
};

}  // namespace expmap_evaluation

#endif  // EXPMAP_BENCHMARK_EVALUATION_METHODS_H
