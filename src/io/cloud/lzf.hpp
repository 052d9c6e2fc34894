#pragma once
// LZF decompression, the codec of PCD's binary_compressed bodies (Marc Lehmann's liblzf
// format, which PCL embeds). Private to io.
#include <cstddef>
#include <string>
#include <string_view>

namespace rigdesign::io {

/// Decompressed bytes, or the reason the stream is corrupt.
struct LzfResult {
  std::string bytes;
  std::string problem;  ///< empty when decompression succeeded; names the input byte offset

  bool ok() const { return problem.empty(); }
};

/// Decompresses `compressed`, which must expand to exactly `decompressed_size` bytes. Every
/// read and write is checked against its buffer's end, so a corrupt or hostile stream gives
/// a problem, never an out-of-bounds access.
LzfResult lzf_decompress(std::string_view compressed, std::size_t decompressed_size);

}  // namespace rigdesign::io
