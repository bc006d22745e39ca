#include "render/cairo_deflate.h"

#include <zlib.h>

namespace epure::render {
namespace {

thread_local std::uint64_t streams = 0;

}  // namespace

std::uint64_t cairo_deflate_streams() noexcept { return streams; }

}  // namespace epure::render

// zlib's deflateInit(strm, level) is this function under a macro; deflateInit2_ with zlib's own
// defaults for the rest (window 15 bits, memory level 8, default strategy) is what it does.
extern "C" int deflateInit_(z_streamp strm, int level, const char* version, int stream_size) {
  if (level == Z_DEFAULT_COMPRESSION) {
    level = epure::render::kCairoDeflateLevel;
    ++epure::render::streams;
  }
  return deflateInit2_(strm, level, Z_DEFLATED, MAX_WBITS, 8, Z_DEFAULT_STRATEGY, version, stream_size);
}
