// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef EXPMAP_INTERNAL_SOLVER_HUGE_PAGE_ALLOCATOR_H
#define EXPMAP_INTERNAL_SOLVER_HUGE_PAGE_ALLOCATOR_H

/// \file Huge_page_allocator.h
/// An allocator that asks the operating system to back large arrays with
/// huge pages (Linux transparent huge pages, where enabled).

#include <expmap/internal/Huge_pages.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>

namespace expmap {
namespace internal {

/// A `std::allocator` for arrays that are read in scattered pieces, such as
/// the supernodal factors the localized solves traverse: a query visits a
/// few thousand supernodes of a few kilobytes each, spread over tens of
/// megabytes. With 4 KiB pages nearly every supernode is a miss in the
/// processor's address translation cache (a page-table walk before the first
/// byte arrives); with 2 MiB pages the whole factor of a mesh of 50k vertices
/// fits in that cache. Linux's default transparent-huge-page mode
/// ("madvise") gives huge pages only to memory that asks for them, before
/// it is first touched: allocations of at least `threshold` bytes are
/// aligned to 2 MiB and advised `MADV_HUGEPAGE`. Elsewhere (other systems,
/// or huge pages disabled) the memory is ordinary.
template <class T>
class Huge_page_allocator {
 public:
  using value_type = T;
  static constexpr std::size_t huge_page = huge_page_bytes;
  /// Allocations from this size on are aligned and advised. Rounding up to
  /// whole huge pages wastes less than one per array, and only a few large
  /// arrays per mesh (the factors, one solve block per thread) use this
  /// allocator.
  static constexpr std::size_t threshold = huge_page;

  Huge_page_allocator() noexcept = default;
  template <class U>
  Huge_page_allocator(const Huge_page_allocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
#if EXPMAP_HUGE_PAGE_ADVICE
    if (advised(n)) {
      // aligned_alloc wants a multiple of the alignment.
      const std::size_t rounded = (n * sizeof(T) + huge_page - 1) / huge_page * huge_page;
      void* p = std::aligned_alloc(huge_page, rounded);
      if (!p) throw std::bad_alloc();
      advise_huge_pages(p, rounded);
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (advised(n))
      std::free(p);
    else
      std::allocator<T>().deallocate(p, n);
  }

  /// Whether an allocation of n elements is aligned and advised (only where
  /// the advice exists).
  static constexpr bool advised(std::size_t n) {
    return EXPMAP_HUGE_PAGE_ADVICE && n * sizeof(T) >= threshold;
  }

  template <class U>
  bool operator==(const Huge_page_allocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const Huge_page_allocator<U>&) const noexcept { return false; }
};

}  // namespace internal
}  // namespace expmap

#endif  // EXPMAP_INTERNAL_SOLVER_HUGE_PAGE_ALLOCATOR_H
