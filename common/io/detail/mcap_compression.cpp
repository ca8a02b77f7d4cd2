// Chunk compression for MCAP: LZ4 frames and Zstandard frames, through Debian's liblz4 and libzstd.
// Decompression never writes beyond the size the chunk declares and reports instead of throwing.
#include "io/detail/mcap_compression.hpp"

#include <lz4frame.h>
#include <zstd.h>
#include <zstd_errors.h>

#include <memory>
#include <stdexcept>

namespace cloudshape::io::detail::mcap {
namespace {

// A fast level: recordings are written while data arrives, and both decoders run at the
// same speed whatever level wrote the frame.
constexpr int kZstdLevel = 3;

std::string compress_lz4(std::string_view data) {
  LZ4F_preferences_t prefs{};
  prefs.frameInfo.contentSize = data.size();
  std::string out(LZ4F_compressFrameBound(data.size(), &prefs), '\0');
  const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), data.data(), data.size(), &prefs);
  if (LZ4F_isError(n)) throw std::runtime_error(std::string("lz4 compression failed: ") + LZ4F_getErrorName(n));
  out.resize(n);
  return out;
}

std::string compress_zstd(std::string_view data) {
  std::string out(ZSTD_compressBound(data.size()), '\0');
  const std::size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), kZstdLevel);
  if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

struct Lz4Context {
  LZ4F_dctx* ctx = nullptr;
  ~Lz4Context() { LZ4F_freeDecompressionContext(ctx); }
};

std::string decompress_lz4(std::string_view in, std::string& out) {
  Lz4Context dctx;
  const std::size_t created = LZ4F_createDecompressionContext(&dctx.ctx, LZ4F_VERSION);
  if (LZ4F_isError(created)) return std::string("lz4: ") + LZ4F_getErrorName(created);
  std::size_t consumed = 0;
  std::size_t produced = 0;
  std::size_t hint = 1;
  // One frame is the norm; concatenated frames decode one after another.
  while (consumed < in.size()) {
    std::size_t dst_size = out.size() - produced;
    std::size_t src_size = in.size() - consumed;
    hint = LZ4F_decompress(dctx.ctx, out.data() + produced, &dst_size, in.data() + consumed, &src_size, nullptr);
    if (LZ4F_isError(hint)) return std::string("lz4: ") + LZ4F_getErrorName(hint);
    produced += dst_size;
    consumed += src_size;
    if (dst_size == 0 && src_size == 0) {
      return "lz4: the data decodes to more than the declared " + std::to_string(out.size()) + " bytes";
    }
  }
  if (hint != 0) return "lz4: the frame ends early (truncated chunk data)";
  if (produced != out.size()) {
    return "lz4: the data decodes to " + std::to_string(produced) + " bytes, the chunk declares " +
           std::to_string(out.size());
  }
  return {};
}

std::string decompress_zstd(std::string_view in, std::string& out) {
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
  if (ZSTD_isError(n)) {
    if (ZSTD_getErrorCode(n) == ZSTD_error_dstSize_tooSmall) {
      return "zstd: the data decodes to more than the declared " + std::to_string(out.size()) + " bytes";
    }
    return std::string("zstd: ") + ZSTD_getErrorName(n);
  }
  if (n != out.size()) {
    return "zstd: the data decodes to " + std::to_string(n) + " bytes, the chunk declares " +
           std::to_string(out.size());
  }
  return {};
}

}  // namespace

std::string compress(McapCompression compression, std::string_view data) {
  switch (compression) {
    case McapCompression::lz4: return compress_lz4(data);
    case McapCompression::zstd: return compress_zstd(data);
    case McapCompression::none: break;
  }
  return std::string(data);
}

std::string decompress(std::string_view compression, std::string_view in, std::size_t size, std::string& out) {
  if (compression == "lz4" || compression == "zstd") out.resize(size);
  if (compression == "lz4") return decompress_lz4(in, out);
  if (compression == "zstd") return decompress_zstd(in, out);
  std::string shown;
  for (char c : compression.substr(0, 40)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  return "unknown compression '" + shown + "' (expected '', 'lz4' or 'zstd')";
}

}  // namespace cloudshape::io::detail::mcap
