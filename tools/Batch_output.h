// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_BATCH_OUTPUT_H
#define EXPMAP_TOOLS_BATCH_OUTPUT_H

/// \file Batch_output.h
/// The output files of `expmap batch`, written as the maps arrive.

#include "Batch_table.h"
#include "Command_line.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace expmap_cli {

/// Where the maps of a batch go: CSV rows as each chunk of maps arrives (so
/// memory stays bounded), the columns of `.npz` outputs at the end (they
/// hold the whole table). Files are created on the first chunk, after the
/// precomputation succeeded, and removed again if the batch does not finish.
class Batch_output {
 public:
  // `file_index` as in Mesh_reading_report: the outputs speak of the file's
  // vertices, not the mesh's. With `point_sources` a map's source is the
  // position of its point in the list, as it is.
  Batch_output(const std::vector<Output>& outputs,
               const std::vector<std::size_t>& file_index, bool point_sources)
      : m_outputs(outputs), m_file_index(file_index), m_point_sources(point_sources) {}
  Batch_output(const Batch_output&) = delete;
  Batch_output& operator=(const Batch_output&) = delete;
  ~Batch_output() {
    if (m_finished) return;
    m_csv.clear();
    std::error_code ignored;
    for (const auto& output : m_outputs) std::filesystem::remove(output.path, ignored);
  }

  // `chunk` numbers vertices as the mesh does.
  void write(Batch_table chunk) {
    if (!m_point_sources)
      for (std::int64_t& s : chunk.sources) s = static_cast<std::int64_t>(m_file_index[s]);
    for (std::int64_t& v : chunk.vertex) v = static_cast<std::int64_t>(m_file_index[v]);
    if (!m_opened) open_csv();
    for (std::ofstream& out : m_csv) write_csv_rows(out, chunk);
    if (has(Output_format::npz)) m_table.append(chunk);
  }

  void finish() {
    if (!m_opened) open_csv();  // a batch of no sources still gets its header
    for (const auto& output : m_outputs) {
      if (output.format != Output_format::npz) continue;
      std::ofstream out(output.path, std::ios::binary);
      write_npz(out, m_table);
      close_checked(out, output.path);
    }
    std::size_t k = 0;
    for (const auto& output : m_outputs)
      if (output.format == Output_format::csv) close_checked(m_csv[k++], output.path);
    m_finished = true;
  }

 private:
  bool has(Output_format format) const {
    return std::any_of(m_outputs.begin(), m_outputs.end(),
                       [&](const Output& o) { return o.format == format; });
  }
  void open_csv() {
    for (const auto& output : m_outputs) {
      if (output.format != Output_format::csv) continue;
      m_csv.emplace_back(output.path);
      if (!m_csv.back()) throw Runtime_error("cannot create output file '" + output.path + "'");
      m_csv.back() << "source,vertex,r,theta,u,v,fold_free_radius\n";
    }
    m_opened = true;
  }
  static void close_checked(std::ofstream& out, const std::string& path) {
    out.close();
    if (!out) throw Runtime_error("could not write all of '" + path + "'");
  }

  std::vector<Output> m_outputs;
  const std::vector<std::size_t>& m_file_index;
  bool m_point_sources;
  std::vector<std::ofstream> m_csv;
  Batch_table m_table;
  bool m_opened = false, m_finished = false;
};

}  // namespace expmap_cli

#endif  // EXPMAP_TOOLS_BATCH_OUTPUT_H
