#pragma once

// Growing the step's largest arrays (contact constraints and their batches, tens of megabytes in a
// world of thousands of bodies) without touching fresh memory all at once (docs/benchmarks.md,
// "2026-11-28, evening: contacts beyond the colours, and arrays that grow ahead").

#include <algorithm>
#include <cstddef>
#include <vector>

namespace impetus::controller {

/// Arrays smaller than this grow as any vector does, bytes.
inline constexpr std::size_t kLargeArrayBytes = std::size_t{4} << 20;

/// How far ahead a large array reserves when it outgrows its capacity: this many times the size
/// it needs.
inline constexpr std::size_t kLargeArrayHeadroom = 4;

/// v.resize(n), with the same result; a large array that outgrows its capacity reserves
/// kLargeArrayHeadroom times n first. A vector that grows takes a new block and copies into it:
/// every page of the new block is a fault when first written (3.3 µs per 4 KiB page on the
/// development machine, ten times the cost of writing it), and doubling did that for the whole
/// array on each step that set a new peak: the spinner's step that first found 150,000 contacts
/// spent 150 ms of its 830 growing its constraints and batches (measured before the colouring
/// rounds made its batches 2.6 times smaller), 35 ms with this headroom. Reserved ahead, the
/// block's pages are only written as the array comes to use them, a step's new contacts at a
/// time; the address space reserved and not written costs no memory.
template <class T, class Allocator>
void resizeLarge(std::vector<T, Allocator>& v, std::size_t n)
{
    if (n > v.capacity() && n * sizeof(T) >= kLargeArrayBytes)
        v.reserve(std::max(kLargeArrayHeadroom * n, 2 * v.capacity()));
    v.resize(n);
}

} // namespace impetus::controller
