// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_VERSION_H
#define EXPMAP_VERSION_H

/// \file version.h
/// The version of expmap. This header is its one source: CMakeLists.txt
/// reads the three numbers from here for `project(VERSION)` (and so for the
/// installed package's version file), the command-line program prints the
/// string for `--version` and the Python module exports it as `__version__`.
/// A header rather than a configured file or a compile definition, so that
/// an installed copy of the headers knows its version on its own.

/// \ingroup PkgExpmapRef
#define EXPMAP_VERSION_MAJOR 0
/// \ingroup PkgExpmapRef
#define EXPMAP_VERSION_MINOR 1
/// \ingroup PkgExpmapRef
#define EXPMAP_VERSION_PATCH 0

// The string is spelled out rather than built from the numbers with the
// preprocessor so that it can be grepped; CMakeLists.txt checks that both
// agree.
/// \ingroup PkgExpmapRef
/// "MAJOR.MINOR.PATCH".
#define EXPMAP_VERSION_STRING "0.1.0"

#endif  // EXPMAP_VERSION_H
