// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_PYTHON_NUMERIC_SETTING_DOCS_H
#define EXPMAP_PYTHON_NUMERIC_SETTING_DOCS_H

// The docstring lines of the heat method's numeric settings, made from the
// library's ranges and help (expmap/Setting_ranges.h).

#include <expmap/Setting_ranges.h>

#include <sstream>
#include <string>

namespace expmap_python {

/// "keyword: help (range; default: value)." wrapped to 76 columns, the
/// lines after the first indented by four spaces.
inline std::string numeric_setting_doc(const expmap::Setting_range& setting,
                                       const std::string& default_text,
                                       const std::string& more = "") {
  std::istringstream words(std::string(setting.name) + ": " + setting.help + more + " (" +
                           setting.range + "; default: " + default_text + ").");
  std::string doc, word;
  std::size_t column = 0;
  while (words >> word) {
    if (column > 0 && column + 1 + word.size() > 76) {
      doc += "\n    ";
      column = 4;
    } else if (column > 0) {
      doc += ' ';
      ++column;
    }
    doc += word;
    column += word.size();
  }
  return doc + "\n";
}

}  // namespace expmap_python

#endif  // EXPMAP_PYTHON_NUMERIC_SETTING_DOCS_H
