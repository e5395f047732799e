#pragma once
/// \file prefetch.h
/// Asking for memory ahead of its use, as the contact solver's passes do: their constraints,
/// records, batches and bodies lie far apart in memory, and a pass that reads them in turn waits on
/// each (docs/benchmarks.md). Not for use outside controller/dynamics.

#include <cstddef>

namespace impetus::controller::detail {

/// Bytes in a cache line: 64 on x86-64 and most AArch64 processors. Where a line is longer (128 on
/// some AArch64), a line is asked for more than once, which costs little and changes nothing.
inline constexpr std::size_t kCacheLine = 64;

/// Asks for every cache line of the `bytes` bytes from `start`: to be read, or, with ForWrite, to
/// be written (the line then comes to the core to own). A hint only: it changes no result.
template <bool ForWrite = false>
inline void prefetchLines(const void* start, std::size_t bytes)
{
    const char* const first = static_cast<const char*>(start);
    for (std::size_t offset = 0; offset < bytes; offset += kCacheLine)
        __builtin_prefetch(first + offset, ForWrite ? 1 : 0);
}

/// prefetchLines() for the whole of one object.
template <bool ForWrite = false, class T>
inline void prefetchObject(const T& object)
{
    prefetchLines<ForWrite>(&object, sizeof(T));
}

} // namespace impetus::controller::detail
