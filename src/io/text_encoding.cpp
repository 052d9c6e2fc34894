#include "io/text_encoding.hpp"

#include <cstdint>
#include <cstdio>

#include "rigdesign/io/emit/xml_text.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

void require_utf8(std::string_view text, const std::string& file) {
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = io::utf8_sequence_length(text, i);
    if (length == 0) {
      char value[8];
      std::snprintf(value, sizeof value, "0x%02X",
                    static_cast<unsigned>(static_cast<std::uint8_t>(text[i])));
      throw model::InputError(model::Diagnostic{
          {file, line, column},
          "(encoding)",
          std::string("byte ") + value + " is not UTF-8 (a Latin-1 or Windows-1252 file?)",
          "UTF-8 text: convert with `iconv -f latin1 -t utf-8`"});
    }
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += length;
  }
}

}  // namespace rigdesign::io
