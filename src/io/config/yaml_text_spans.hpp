#pragma once
// Where YAML values lie in a file's text, for edits that replace characters instead of
// re-serialising (rig_text_editor): byte offsets from the parser's marks, the lines a block
// spans, the end of a flow collection. Lines end in LF or CR LF.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rigdesign::io::yaml_text {

/// Byte offset of a 0-based line and column (yaml-cpp counts bytes: it passes UTF-8 through).
std::size_t offset_of(const std::string& text, int line, int column);

/// The first byte of the line holding `offset`.
std::size_t line_begin(const std::string& text, std::size_t offset);
/// One past the last byte of the line holding `offset`, before its CR LF or LF.
std::size_t line_end(const std::string& text, std::size_t offset);
/// The line break the line holding `offset` ends with ("\r\n" or "\n"; "\n" at the end of text).
std::string_view line_break_at(const std::string& text, std::size_t offset);

/// Whether `line` holds nothing but blanks and perhaps a comment.
bool blank_or_comment(std::string_view line);

/// The end of the last content line of a block that starts on the line of `offset`: the
/// following lines belong to it while they are blank, only a comment, or indented by at least
/// `min_indent` spaces. Returns line_end of the last line with content that belongs.
std::size_t block_content_end(const std::string& text, std::size_t offset, std::size_t min_indent);

/// One past the bracket closing the flow collection (`{` or `[`) that opens at `open`, quotes
/// skipped; std::string::npos when it does not close.
std::size_t flow_end(const std::string& text, std::size_t open);

/// 0-based line and column, as yaml-cpp's marks count them.
using TextMark = std::pair<int, int>;

/// A value that aliases share: its anchor (`&name`) and every alias (`*name`) that refers to it.
/// Its text is written once, at the anchor, so editing it changes every place that uses it.
struct SharedValue {
  std::string anchor;
  TextMark anchor_mark;  ///< where the anchored node starts (its `&`): yaml-cpp's mark for it
  std::vector<TextMark> alias_marks;
};

/// The values of the first document of `text` that at least one alias refers to, keyed by the
/// anchored node's mark (the mark yaml-cpp gives that node and every alias resolved to it).
/// An anchor no alias uses is not listed. Throws YAML::Exception on a syntax error.
std::map<TextMark, SharedValue> shared_values(const std::string& text);

}  // namespace rigdesign::io::yaml_text
