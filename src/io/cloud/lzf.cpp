#include "io/cloud/lzf.hpp"

#include <cstdint>

namespace rigdesign::io {
namespace {

// The stream is a sequence of chunks, each opened by a control byte:
//   ctrl < 32: a literal run of ctrl + 1 bytes follows;
//   otherwise a back-reference: length code L = ctrl >> 5 (1..6, or 7 followed by a byte
//   that adds to it), then a byte that completes the distance: it copies L + 2 bytes from
//   ((ctrl & 31) << 8) + byte + 1 bytes back in the output (the copy may overlap itself).
constexpr unsigned kLiteralLimit = 1u << 5;
constexpr unsigned kLongLengthCode = 7;
constexpr std::size_t kShortestMatch = 2;
// The best a chunk can do is 3 bytes (control, length, distance) for the longest match,
// 7 + 255 + 2 = 264 bytes: 88 output bytes per input byte. A declared size beyond that is
// corrupt, and refusing it spares allocating whatever a damaged header claims.
constexpr std::size_t kMostBytesOutPerByteIn = 88;

std::string at_offset(std::size_t offset) {
  return " at compressed byte " + std::to_string(offset);
}

}  // namespace

LzfResult lzf_decompress(std::string_view compressed, std::size_t decompressed_size) {
  LzfResult result;
  if (decompressed_size / kMostBytesOutPerByteIn > compressed.size()) {
    result.problem = std::to_string(compressed.size()) + " compressed bytes cannot expand to " +
                     std::to_string(decompressed_size);
    return result;
  }
  result.bytes.resize(decompressed_size);
  std::size_t in = 0;
  std::size_t out = 0;
  const auto next_byte = [&]() { return static_cast<std::uint8_t>(compressed[in++]); };
  while (in < compressed.size()) {
    const std::size_t chunk_start = in;
    const unsigned control = next_byte();
    if (control < kLiteralLimit) {
      const std::size_t length = control + 1;
      if (compressed.size() - in < length) {
        result.problem = "literal run of " + std::to_string(length) +
                         " bytes passes the stream's end" + at_offset(chunk_start);
        return result;
      }
      if (decompressed_size - out < length) {
        result.problem = "literal run overflows the declared size" + at_offset(chunk_start);
        return result;
      }
      result.bytes.replace(out, length, compressed.substr(in, length));
      in += length;
      out += length;
      continue;
    }
    std::size_t length = control >> 5;
    const bool needs_length_byte = length == kLongLengthCode;
    if (compressed.size() - in < (needs_length_byte ? 2u : 1u)) {
      result.problem = "back-reference cut off by the stream's end" + at_offset(chunk_start);
      return result;
    }
    if (needs_length_byte) length += next_byte();
    length += kShortestMatch;
    const std::size_t distance =
        ((std::size_t{control} & (kLiteralLimit - 1)) << 8) + next_byte() + 1;
    if (distance > out) {
      result.problem = "back-reference reaches " + std::to_string(distance) +
                       " bytes back with only " + std::to_string(out) + " decompressed" +
                       at_offset(chunk_start);
      return result;
    }
    if (decompressed_size - out < length) {
      result.problem = "back-reference overflows the declared size" + at_offset(chunk_start);
      return result;
    }
    // Byte by byte on purpose: a reference may copy bytes it has just written (a run).
    for (std::size_t i = 0; i < length; ++i, ++out) {
      result.bytes[out] = result.bytes[out - distance];
    }
  }
  if (out != decompressed_size) {
    result.problem = "stream ends after " + std::to_string(out) + " of the declared " +
                     std::to_string(decompressed_size) + " bytes";
  }
  return result;
}

}  // namespace rigdesign::io
