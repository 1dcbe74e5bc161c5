// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_INTERNAL_HUGE_PAGES_H
#define EXPMAP_INTERNAL_HUGE_PAGES_H

/// \file Huge_pages.h
/// Asking the operating system to back large arrays with huge pages (Linux
/// transparent huge pages, where enabled).
///
/// Two costs of 4 KiB pages matter here. Arrays read in scattered pieces (a
/// factor's supernodes) miss the processor's address translation cache on
/// nearly every piece. And every page is zeroed by the kernel when it is
/// first touched: building the flat copy of a mesh of millions of vertices
/// touches about a gigabyte of new memory, a quarter of a million such page
/// faults, which cost seconds on virtual machines. Linux's default
/// transparent-huge-page mode ("madvise") gives 2 MiB pages only to memory
/// that asks for them before it is first touched.

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define EXPMAP_HUGE_PAGE_ADVICE 1
#else
#define EXPMAP_HUGE_PAGE_ADVICE 0
#endif

namespace expmap {
namespace internal {

/// Size of a huge page on x86-64 and AArch64 Linux (with 4 KiB base pages).
constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

/// Advises huge pages for the whole 2 MiB-aligned pages inside `bytes`
/// bytes from `data` (none if it holds none). Advice only: where it does not
/// exist or fails, the memory stays ordinary.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if EXPMAP_HUGE_PAGE_ADVICE
  const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (first + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  const std::uintptr_t end = (first + bytes) / huge_page_bytes * huge_page_bytes;
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

/// Empties `v` and gives it new storage for `n` elements, advised as above
/// before anything touches it. Meant for arrays of a whole mesh built once:
/// fill them with `resize`, `assign` or `push_back` up to `n`.
template <class T, class Allocator>
void reserve_on_huge_pages(std::vector<T, Allocator>& v, std::size_t n) {
  std::vector<T, Allocator> fresh;
  fresh.reserve(n);
  if (n > 0) advise_huge_pages(fresh.data(), n * sizeof(T));
  v.swap(fresh);
}

/// `n` copies of `value`, in storage advised as above.
template <class T>
std::vector<T> filled_on_huge_pages(std::size_t n, const T& value) {
  std::vector<T> v;
  reserve_on_huge_pages(v, n);
  v.assign(n, value);
  return v;
}

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_HUGE_PAGES_H
