// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_TOOLS_VIEWER_VIEW_COMMAND_H
#define EXPMAP_TOOLS_VIEWER_VIEW_COMMAND_H

/// \file View_command.h
/// `expmap view MESH [--port P] [--host H]`: the interactive viewer's web
/// server. It lives in a translation unit of its own (view_command.cpp):
/// the HTTP library and a second instantiation of the methods then compile
/// beside the rest of the program, and changing one does not recompile the
/// other.

#include <string>
#include <vector>

namespace expmap_view {

/// The help of `expmap view`.
std::string view_help();

/// Runs `expmap view` with the arguments after "view" until the process is
/// stopped. Returns the exit status for failures it reports itself
/// (printed as one "expmap: error:" line).
/// \throws expmap_cli::Usage_error for bad arguments; the library's
///         exceptions for a mesh it cannot use.
int run_view_command(const std::vector<std::string>& args);

}  // namespace expmap_view

#endif  // EXPMAP_TOOLS_VIEWER_VIEW_COMMAND_H
