#pragma once
// cairo compresses a PDF's content streams (and its fonts) with zlib's deflateInit at the
// default level (6): a fifth of the CPU time of a class set's PDFs went to zlib (perf, 100
// sheets, 2026-12-05). cairo_deflate.cpp defines deflateInit_ in the executable, which the
// dynamic linker binds cairo's calls to (as cairo_printf.h does for snprintf), and starts
// those streams at level 1 instead: the same bytes once inflated, so the same pages, written
// in about a third of the time, for files about 15 % larger. A caller asking for another level
// than the default gets it; libpng and libzip (epure's PNGs and zip files) call deflateInit2_,
// which this leaves alone. Only targets that link the object library epure::cairo_printf have it
// (epure and the unit tests).
#include <cstdint>

namespace epure::render {

// The level cairo's streams are compressed at.
inline constexpr int kCairoDeflateLevel = 1;

// How many deflate streams of this thread were started at kCairoDeflateLevel in place of the
// default (for the test that cairo's calls do reach it).
std::uint64_t cairo_deflate_streams() noexcept;

}  // namespace epure::render
